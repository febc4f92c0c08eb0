// ModalProperties on a two-storey shear frame reduced to a 1D chain of
// springs (k1 = 2k, k2 = k, masses 2m and m): the modes are closed form,
// lambda = (k/m) {1/2, 2}, phi = {1/2, 1} and {-1, 1} (top storey last).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "analysis/ModalProperties.h"
#include "support/Script.h"

using beamsolid::ModalProperties;
using beamsolid::testing::Script;

namespace {

constexpr double k = 50.0, m = 3.0;

void buildShearFrame(Script& s) {
  s("model", "basic", "-ndm", 1, "-ndf", 1);
  for (int i = 1; i <= 3; ++i) s("node", i, 0.0);
  s("fix", 1, 1);
  s("uniaxialMaterial", "Elastic", 1, 2.0 * k);
  s("uniaxialMaterial", "Elastic", 2, k);
  s("element", "zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1);
  s("element", "zeroLength", 2, 2, 3, "-mat", 2, "-dir", 1);
  s("mass", 2, 2.0 * m);
  s("mass", 3, m);
}

}  // namespace

TEST(ModalProperties, TwoStoreyShearFrameClosedForm) {
  Script s;
  buildShearFrame(s);
  const std::vector<double> lambda = s.list("eigen", "-fullGenLapack", 2);
  ASSERT_EQ(lambda.size(), 2u);
  EXPECT_NEAR(lambda[0], 0.5 * k / m, 1e-12 * k / m);
  EXPECT_NEAR(lambda[1], 2.0 * k / m, 1e-12 * k / m);

  ModalProperties p(s.interp.domain(), lambda, true);
  const auto d = p.toDict();
  // phi1 = {1/2, 1}: L = 2m/2 + m = 2m, gm = 2m/4 + m = 1.5m, Gamma = 4/3, Meff = 8m/3.
  // phi2 = {-1, 1} (unit-normalized): L = -m, gm = 3m, Gamma = -1/3, Meff = m/3.
  EXPECT_NEAR(std::abs(d.at("partiFactorMX")[0]), 4.0 / 3.0, 1e-10);
  EXPECT_NEAR(std::abs(d.at("partiFactorMX")[1]), 1.0 / 3.0, 1e-10);
  EXPECT_NEAR(d.at("partiMassMX")[0], 8.0 * m / 3.0, 1e-10 * m);
  EXPECT_NEAR(d.at("partiMassMX")[1], m / 3.0, 1e-10 * m);
  EXPECT_NEAR(d.at("partiMassRatiosMX")[0], 100.0 * 8.0 / 9.0, 1e-9);
  EXPECT_NEAR(d.at("partiMassRatiosCumuMX")[1], 100.0, 1e-9);
  EXPECT_DOUBLE_EQ(d.at("totalMass")[0], 3.0 * m);
  EXPECT_DOUBLE_EQ(d.at("totalFreeMass")[0], 3.0 * m);
  EXPECT_NEAR(d.at("eigenPeriod")[0], 2.0 * M_PI / std::sqrt(0.5 * k / m), 1e-12);

  std::ostringstream report;
  p.report(report);
  EXPECT_EQ(report.str().rfind("# MODAL ANALYSIS REPORT\n", 0), 0u);
  EXPECT_NE(report.str().find("* 7. MODAL PARTICIPATION MASSES:"), std::string::npos);
}

TEST(ModalProperties, WithoutEigenvaluesItSaysSo) {
  Script s;
  buildShearFrame(s);
  try {
    s("modalProperties", "-return");
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("eigen"), std::string::npos) << e.what();
  }
}
