// BFGS and Broyden (QuasiNewton) on a stiffening spring chain against the
// closed-form (Cardano) elongations; on a linear chain one cycle suffices.
#include <gtest/gtest.h>

#include <cmath>

#include "AnalysisTestSupport.h"
#include "analysis/QuasiNewton.h"

using namespace beamsolid;
using namespace beamsolid::analysistest;

namespace {

// f = k d + k3 d^3; the one real root of k3 d^3 + k d - F = 0 (k, k3 > 0).
struct Cubic {
  double k, k3;
  SpringLaw law() const {
    const double a = k, b = k3;
    return {[=](double d) { return a * d + b * d * d * d; }, [=](double d) { return a + 3.0 * b * d * d; }};
  }
  double elongation(double F) const {
    if (k3 == 0.0) return F / k;
    const double p = k / k3, q = -F / k3;
    const double r = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
    return std::cbrt(-q / 2.0 + r) + std::cbrt(-q / 2.0 - r);
  }
};

// node 1 fixed -A- 2 -B- 3 -C- 4, load P at 4: every spring carries P.
void expectChain(const std::string& algorithm, Args args, const Cubic (&s)[3], int steps) {
  Model m;
  for (int i = 1; i <= 4; ++i) m.addNode(i, i - 1.0);
  m.fixX(1);
  for (int i = 0; i < 3; ++i) m.addSpring(i + 1, i + 1, i + 2, s[i].law());
  const double P = 10.0;
  m.addLoad(4, P);
  m.analyzeWith(algorithm, std::move(args), "LoadControl", {1.0 / steps}, 1e-12, 100);
  for (int step = 0; step < steps; ++step) ASSERT_EQ(m.analyze(1), 0) << algorithm << " step " << step;
  double d = 0.0;
  for (int i = 0; i < 3; ++i) {
    d += s[i].elongation(P);
    EXPECT_NEAR(m.disp(i + 2), d, 1e-9) << algorithm;
  }
}

const Cubic stiffening[3] = {{1.0, 10.0}, {2.0, 0.0}, {3.0, 5.0}};
const Cubic linear[3] = {{1.0, 0.0}, {2.0, 0.0}, {3.0, 0.0}};

}  // namespace

TEST(QuasiNewton, BfgsAndBroydenReachTheClosedForm) {
  for (const char* type : {"BFGS", "Broyden"}) {
    expectChain(type, {}, stiffening, 10);
    expectChain(type, {std::string("-count"), 2LL}, stiffening, 10);
    expectChain(type, {std::string("-initial")}, stiffening, 20);
  }
}

TEST(QuasiNewton, LinearChainConvergesInTheFirstCycle) {
  for (const char* type : {"BFGS", "Broyden"}) {
    Model m;
    for (int i = 1; i <= 4; ++i) m.addNode(i, i - 1.0);
    m.fixX(1);
    for (int i = 0; i < 3; ++i) m.addSpring(i + 1, i + 1, i + 2, linear[i].law());
    m.addLoad(4, 1.0);
    m.analyzeWith(type, {}, "LoadControl", {1.0}, 1e-12, 100);
    ASSERT_EQ(m.analyze(1), 0);
    // testIter counts tangent cycles, as OpenSees: one.
    EXPECT_EQ(m.components.test->numIterations(), 1) << type;
    EXPECT_NEAR(m.disp(4), 1.0 + 0.5 + 1.0 / 3.0, 1e-12) << type;
  }
}
