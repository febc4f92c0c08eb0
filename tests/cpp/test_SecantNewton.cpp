// SecantNewton on a stiffening spring chain against the closed-form
// (Cardano) elongations, with each tangent choice and both update forms.
#include <gtest/gtest.h>

#include <cmath>

#include "AnalysisTestSupport.h"
#include "analysis/SecantNewton.h"

using namespace beamsolid;
using namespace beamsolid::analysistest;

namespace {

// f = k d + k3 d^3; the one real root of k3 d^3 + k d - F = 0.
double elongation(double k, double k3, double F) {
  if (k3 == 0.0) return F / k;
  const double p = k / k3, q = -F / k3;
  const double r = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
  return std::cbrt(-q / 2.0 + r) + std::cbrt(-q / 2.0 - r);
}

SpringLaw cubic(double k, double k3) {
  return {[=](double d) { return k * d + k3 * d * d * d; }, [=](double d) { return k + 3.0 * k3 * d * d; }};
}

}  // namespace

TEST(SecantNewton, ReachesTheClosedFormWithEveryOption) {
  const double k[3] = {1.0, 2.0, 3.0}, k3[3] = {10.0, 0.0, 5.0}, P = 10.0;
  const std::vector<Args> options = {
      {},
      {std::string("-maxDim"), 5LL},
      {std::string("-numTerms"), 3LL},
      {std::string("-increment"), std::string("initial")},
      {std::string("-cutOut"), 3.5, 0.3},
  };
  for (const Args& args : options) {
    Model m;
    for (int i = 1; i <= 4; ++i) m.addNode(i, i - 1.0);
    m.fixX(1);
    for (int i = 0; i < 3; ++i) m.addSpring(i + 1, i + 1, i + 2, cubic(k[i], k3[i]));
    m.addLoad(4, P);
    m.analyzeWith("SecantNewton", args, "LoadControl", {0.1}, 1e-12, 100);
    for (int step = 0; step < 10; ++step) ASSERT_EQ(m.analyze(1), 0) << "option set " << args.size();
    double d = 0.0;
    for (int i = 0; i < 3; ++i) {
      d += elongation(k[i], k3[i], P);
      EXPECT_NEAR(m.disp(i + 2), d, 1e-9);
    }
  }
}
