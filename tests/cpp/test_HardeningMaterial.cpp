// Hardening: yield stress and the elastoplastic slope E*H/(E+H) on the
// backbone, the kinematic shift of the elastic range and the isotropic growth
// after a reversal (closed forms of 1D combined hardening), a
// finite-difference tangent on a cyclic path, revert and input errors.
#include <gtest/gtest.h>

#include "core/OpenSeesError.h"
#include "support/ErrorOf.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using namespace beamsolid::uniaxialtest;

TEST(HardeningMaterial, BackboneAndReversalFollowClosedForms) {
  const double E = 200.0, sy = 2.0, Hi = 10.0, Hk = 5.0, ey = sy / E;
  Domain d;
  auto m = build(d, "Hardening", args("uniaxialMaterial", 1, E, sy, Hi, Hk));
  m->setTrialStrain(0.5 * ey);
  EXPECT_DOUBLE_EQ(m->stress(), 0.5 * sy);
  EXPECT_DOUBLE_EQ(m->tangent(), E);
  const double Ep = E * (Hi + Hk) / (E + Hi + Hk);
  const double e1 = 0.03;
  m->setTrialStrain(e1);
  m->commitState();
  const double s1 = sy + Ep * (e1 - ey);
  EXPECT_NEAR(m->stress(), s1, 1e-13 * sy);
  EXPECT_DOUBLE_EQ(m->tangent(), Ep);
  // Plastic multiplier so far and the elastic range on reversal: the centre
  // moved by Hk*gamma, the radius grew by Hi*gamma.
  const double gamma = (e1 - ey) * E / (E + Hi + Hk);
  const double centre = Hk * gamma, radius = sy + Hi * gamma;
  EXPECT_NEAR(m->stress(), centre + radius, 1e-13 * sy);
  // Reverse yielding starts at stress centre - radius and then slopes Ep again.
  const double reverseYieldStrain = e1 - 2.0 * radius / E;
  m->setTrialStrain(reverseYieldStrain + 1e-9);
  EXPECT_DOUBLE_EQ(m->tangent(), E);
  const double e2 = reverseYieldStrain - 0.01;
  m->setTrialStrain(e2);
  EXPECT_NEAR(m->stress(), centre - radius - Ep * 0.01, 1e-12 * sy);
  EXPECT_DOUBLE_EQ(m->tangent(), Ep);
}

TEST(HardeningMaterial, PerfectPlasticityWithoutHardening) {
  Domain d;
  auto m = build(d, "Hardening", args("uniaxialMaterial", 1, 100.0, 1.0, 0.0, 0.0, 0.3));  // eta ignored
  m->setTrialStrain(0.05);
  EXPECT_DOUBLE_EQ(m->stress(), 1.0);
  EXPECT_DOUBLE_EQ(m->tangent(), 0.0);
}

TEST(HardeningMaterial, TangentMatchesFiniteDifferenceOnCyclicPath) {
  Domain d;
  auto m = build(d, "Hardening", args("uniaxialMaterial", 1, 200.0, 2.0, 10.0, 5.0));
  expectTangentMatchesFiniteDifference(*m, {0.03, -0.02, 0.05, -0.06, 0.0}, 0.0037, 1e-7, 200.0);
}

TEST(HardeningMaterial, RevertToLastCommitRestoresExactly) {
  Domain d;
  auto m = build(d, "Hardening", args("uniaxialMaterial", 1, 200.0, 2.0, 10.0, 5.0));
  expectRevertRestoresExactly(*m, {0.005, 0.02, 0.035, 0.01, -0.02, -0.04, 0.0}, 0.03);
}

TEST(HardeningMaterial, InputErrorsNameTheArgument) {
  Domain d;
  auto err = [&](CommandArgs a) {
    return testsupport::errorOf([&] { build(d, "Hardening", std::move(a)); });
  };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 200.0, 2.0, 10.0)).find("H_kin"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, -200.0, 2.0, 10.0, 1.0)).find("E must be positive"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 200.0, 2.0, 1.0, 1.0, 0.0, 5.0)).find("uniaxialMaterial Hardening 1"),
            std::string::npos);
}

// Sensitivity (direct differentiation) on a cyclic strain path that yields both ways: at every
// step d stress / d theta (strain held, history's sensitivity carried) against central
// differences of the whole path run with theta +- h, for E, sigmaY, H_iso and H_kin.
TEST(HardeningMaterial, StressSensitivityMatchesFiniteDifferencesOfThePath) {
  std::vector<double> path;
  for (int i = 1; i <= 40; ++i) path.push_back(0.03 * std::sin(0.2 * i) + 0.001 * i);
  auto make = [](const std::vector<double>& v) {
    Domain d;
    return build(d, "Hardening", args("uniaxialMaterial", 1, v[0], v[1], v[2], v[3]));
  };
  expectSensitivitiesMatchFiniteDifferences(make, {200.0, 2.0, 10.0, 5.0}, {"E", "sigmaY", "H_iso", "H_kin"}, path,
                                            1e-7);
  // A strain sensitivity alone moves the stress by the tangent on a plastic step.
  Domain d;
  auto m = build(d, "Hardening", args("uniaxialMaterial", 1, 200.0, 2.0, 10.0, 5.0));
  m->setTrialStrain(0.05);
  m->commitSensitivity(1.0, 0, 0, 1);
  m->commitState();
  m->setTrialStrain(0.05);  // unchanged: the committed stress and its sensitivity
  EXPECT_NEAR(m->stressSensitivity(0, 0), 200.0 * 15.0 / 215.0, 1e-12);
}
