// Hysteretic: the trilinear and bilinear envelopes (last slope continued, a
// plateau after a falling branch), unloading with E1*mu^-beta, reloading to
// the other side's extreme through the pinch point, the damaged target
// strain emax*(1 + damage1*(mu - 1)) after a cycle, all by hand from the
// documented rules; finite-difference tangents on a cyclic path, revert and
// input errors.
#include <gtest/gtest.h>

#include <cmath>

#include "core/OpenSeesError.h"
#include "support/ErrorOf.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using namespace beamsolid::uniaxialtest;

namespace {

// Envelope (0.01, 10), (0.03, 15), (0.08, 18) and (-0.012, -12), (-0.035, -16), (-0.09, -17).
std::unique_ptr<UniaxialMaterial> hysteretic(Domain& d, double pinchX, double pinchY, double d1, double d2,
                                             double beta) {
  return build(d, "Hysteretic", args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, 18.0, 0.08, -12.0, -0.012, -16.0,
                                     -0.035, -17.0, -0.09, pinchX, pinchY, d1, d2, beta));
}

void step(UniaxialMaterial& m, double strain) {
  m.setTrialStrain(strain);
  m.commitState();
}

}  // namespace

TEST(HystereticMaterial, EnvelopeThroughThePointsBothWays) {
  Domain d;
  auto m = hysteretic(d, 1.0, 1.0, 0.0, 0.0, 0.0);
  const double strain[] = {0.005, 0.02, 0.05, 0.1};
  const double stress[] = {5.0, 12.5, 15.0 + 0.02 * 60.0, 18.0 + 0.02 * 60.0};  // slopes 1000, 250, 60, 60
  for (int i = 0; i < 4; ++i) {
    step(*m, strain[i]);
    EXPECT_NEAR(m->stress(), stress[i], 1e-12) << strain[i];
  }
  auto n = hysteretic(d, 1.0, 1.0, 0.0, 0.0, 0.0);
  step(*n, -0.02);
  EXPECT_NEAR(n->stress(), -12.0 - 4.0 / 0.023 * 0.008, 1e-12);
  // Two points a side: the second slope goes on.
  auto b = build(d, "Hysteretic", args("uniaxialMaterial", 2, 10.0, 0.01, 15.0, 0.03, -12.0, -0.012, -16.0, -0.035,
                                       1.0, 1.0, 0.0, 0.0));
  step(*b, 0.05);
  EXPECT_NEAR(b->stress(), 15.0 + 0.02 * 250.0, 1e-12);
  // A falling third branch ends in a plateau at its last point.
  auto s = build(d, "Hysteretic", args("uniaxialMaterial", 3, 10.0, 0.01, 15.0, 0.03, 5.0, 0.06, -12.0, -0.012, -16.0,
                                       -0.035, -4.0, -0.07, 1.0, 1.0, 0.0, 0.0));
  step(*s, 0.045);
  EXPECT_NEAR(s->stress(), 10.0, 1e-12);
  step(*s, 0.1);
  EXPECT_NEAR(s->stress(), 5.0, 1e-12);
  EXPECT_NEAR(s->tangent(), 1e-9 * 1000.0, 1e-18);
}

TEST(HystereticMaterial, UnloadsWithDegradedStiffnessAndReloadsToThePeak) {
  Domain d;
  const double beta = 0.5;
  auto m = hysteretic(d, 1.0, 1.0, 0.0, 0.0, beta);
  step(*m, 0.04);  // 15.6 on the envelope, ductility 4
  const double k = 1000.0 * std::pow(4.0, -beta);
  step(*m, 0.035);
  EXPECT_NEAR(m->stress(), 15.6 - k * 0.005, 1e-12);
  EXPECT_NEAR(m->tangent(), k, 1e-12);
  // Past zero stress: straight to the negative yield point (never exceeded).
  const double zero = 0.04 - 15.6 / k;
  step(*m, -0.005);
  const double slope = 12.0 / (zero + 0.012);
  EXPECT_NEAR(m->stress(), -slope * (zero + 0.005), 1e-12);
  EXPECT_NEAR(m->tangent(), slope, 1e-12);
  // Beyond it, the envelope.
  step(*m, -0.02);
  EXPECT_NEAR(m->stress(), -12.0 - 4.0 / 0.023 * 0.008, 1e-12);
  // Back: unload with the negative side's stiffness (ductility 0.02/0.012),
  // then reload to the positive peak (0.04, 15.6); a step past zero stress
  // gives the smaller of that path and an elastic step of stiffness k.
  const double kn = 1000.0 * std::pow(0.02 / 0.012, -beta);
  const double sigma = m->stress();
  step(*m, -0.019);
  EXPECT_NEAR(m->stress(), sigma + kn * 0.001, 1e-12);
  const double zeroP = -0.02 - sigma / kn;
  // Past zero stress (an elastic step of kn would end positive) the stress
  // is the smaller of the path and an elastic step of the positive side's k
  // (smaller than kn here, so the stress may stay negative for a while).
  auto path = [&](double e) { return 15.6 / (0.04 - zeroP) * (e - zeroP); };
  const double committed = m->stress();
  ASSERT_GT(committed + kn * 0.019, 0.0);
  step(*m, 0.0);
  EXPECT_NEAR(m->stress(), std::min(committed + k * 0.019, path(0.0)), 1e-12);
  const double before = m->stress();
  step(*m, 0.03);
  EXPECT_NEAR(m->stress(), std::min(before + k * 0.03, path(0.03)), 1e-12);
  step(*m, 0.039);
  EXPECT_NEAR(m->stress(), path(0.039), 1e-12);
  EXPECT_NEAR(m->tangent(), 15.6 / (0.04 - zeroP), 1e-9);
}

TEST(HystereticMaterial, PinchingBendsTheReloadingPath) {
  Domain d;
  const double px = 0.5, py = 0.3;
  auto m = hysteretic(d, px, py, 0.0, 0.0, 0.0);
  step(*m, 0.04);
  step(*m, 0.03);
  // Reloading towards (-0.012, -12) passes through stress py*(-12) at the
  // strain zero + px*((target - (1 - py)*(-12)/E) - zero).
  const double zero = 0.04 - 15.6 / 1000.0;
  const double pinchStrain = zero + px * ((-0.012 + (1.0 - py) * 12.0 / 1000.0) - zero);
  const double pinchStress = -py * 12.0;
  step(*m, 0.5 * (zero + pinchStrain));
  EXPECT_NEAR(m->stress(), 0.5 * pinchStress, 1e-12);
  EXPECT_NEAR(m->tangent(), pinchStress / (pinchStrain - zero), 1e-9);
  const double x = 0.5 * (pinchStrain - 0.012);
  step(*m, x);
  const double slope2 = (-12.0 - pinchStress) / (-0.012 - pinchStrain);
  EXPECT_NEAR(m->stress(), pinchStress + slope2 * (x - pinchStrain), 1e-12);
}

TEST(HystereticMaterial, DuctilityDamageMovesTheTarget) {
  Domain d;
  const double d1 = 0.1;
  auto m = hysteretic(d, 1.0, 1.0, d1, 0.0, 0.0);
  step(*m, 0.04);
  step(*m, 0.0);
  step(*m, -0.036);  // negative ductility 3
  step(*m, -0.03);   // reversal: the positive target becomes 0.04*(1 + d1*(3 - 1))
  const double sigma = m->stress();
  const double zero = -0.03 - sigma / 1000.0;
  const double target = 0.04 * (1.0 + d1 * 2.0);
  const double targetStress = 15.0 + 60.0 * (target - 0.03);
  step(*m, 0.02);
  EXPECT_NEAR(m->stress(), targetStress / (target - zero) * (0.02 - zero), 1e-12);
  // Not yet on the envelope at the old peak, which needs the damaged one.
  step(*m, 0.041);
  EXPECT_LT(m->stress(), 15.0 + 60.0 * 0.011);
}

TEST(HystereticMaterial, TangentAndRevert) {
  Domain d;
  auto m = hysteretic(d, 0.6, 0.2, 0.05, 0.05, 0.3);
  expectTangentMatchesFiniteDifference(*m, {0.02, -0.015, 0.04, 0.01, 0.03, -0.05, -0.02, 0.07, -0.08, 0.0}, 0.0013,
                                       1e-8, 1000.0);
  auto r = hysteretic(d, 0.6, 0.2, 0.05, 0.05, 0.3);
  expectRevertRestoresExactly(*r, {0.02, 0.004, -0.015, 0.001, 0.04, 0.012, -0.05, 0.0}, 0.03);
}

TEST(HystereticMaterial, InputErrors) {
  Domain d;
  auto err = [&](CommandArgs a) {
    return testsupport::errorOf([&] { build(d, "Hysteretic", std::move(a)); });
  };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, -12.0, -0.012, 1.0, 1.0, 0.0, 0.0))
                .find("12, 13, 16 or 17 numbers"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.03, 15.0, 0.01, -12.0, -0.012, -16.0, -0.035, 1.0, 1.0, 0.0, 0.0))
                .find("e2p must be positive and beyond"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, 12.0, 0.012, -16.0, -0.035, 1.0, 1.0, 0.0, 0.0))
                .find("e1n must be negative"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, -12.0, -0.012, -16.0, -0.035, 1.0, 1.0, -0.1, 0.0))
                .find("damage1 and damage2"),
            std::string::npos);
}
