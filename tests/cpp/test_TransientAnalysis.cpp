// Transient analysis through the Interpreter on a spring-mass oscillator:
// the first step of each integrator against its own recurrence written out
// by hand, and the Viscous dashpot against its force law.
#include <gtest/gtest.h>

#include <cmath>

#include "core/OpenSeesError.h"
#include "materials/uniaxial/ViscousMaterial.h"
#include "support/Script.h"

using namespace beamsolid;
using namespace beamsolid::testing;

namespace {

constexpr double k = 400.0, m = 4.0, P = 10.0, dt = 0.01;

// 1D spring k with mass m under a constant load P from rest.
void buildOscillator(Script& s, const std::string& integrator, const std::string& algorithm = "Newton") {
  s("wipe");
  s("model", "basic", "-ndm", 1, "-ndf", 1);
  s("node", 1, 0.0);
  s("node", 2, 0.0);
  s("fix", 1, 1);
  s("mass", 2, m);
  s("uniaxialMaterial", "Elastic", 1, k);
  s("element", "zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1);
  s("timeSeries", "Constant", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 2, P);
  s("test", "NormDispIncr", 1e-14, 10);
  s("algorithm", algorithm);
  if (integrator == "Newmark") s("integrator", "Newmark", 0.5, 0.25);
  else if (integrator == "HHT") s("integrator", "HHT", 0.8);
  else s("integrator", integrator);
  s("analysis", "Transient");
}

}  // namespace

// Average acceleration from rest with a0 = 0 (no initial solve, as OpenSees):
// (k + 4 m / dt^2) u1 = P, v1 = 2 u1 / dt, a1 = 4 u1 / dt^2.
TEST(TransientAnalysis, NewmarkFirstStepIsTheRecurrence) {
  Script s;
  buildOscillator(s, "Newmark");
  ASSERT_EQ(s.integer("analyze", 1, dt), 0);
  const double u1 = P / (k + 4.0 * m / (dt * dt));
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), u1, 1e-15);
  EXPECT_NEAR(s.number("nodeVel", 2, 1), 2.0 * u1 / dt, 1e-13);
  EXPECT_NEAR(s.number("nodeAccel", 2, 1), 4.0 * u1 / (dt * dt), 1e-10);
  EXPECT_NEAR(s.number("getTime"), dt, 1e-15);
  // reactions('-dynamic'): support force plus inertia balances the load.
  s("reactions", "-dynamic");
  EXPECT_NEAR(s.number("nodeReaction", 1, 1) + s.number("nodeReaction", 2, 1), -P + m * 4.0 * u1 / (dt * dt),
              1e-10);
}

// HHT (alpha, gamma = 1.5 - alpha, beta = (2 - alpha)^2 / 4) from rest:
// alpha k u1 + m u1 / (beta dt^2) = P.
TEST(TransientAnalysis, HHTFirstStepIsTheRecurrence) {
  Script s;
  buildOscillator(s, "HHT");
  ASSERT_EQ(s.integer("analyze", 1, dt), 0);
  const double alpha = 0.8, beta = 0.25 * (2.0 - alpha) * (2.0 - alpha), gamma = 1.5 - alpha;
  const double u1 = P / (alpha * k + m / (beta * dt * dt));
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), u1, 1e-15);
  EXPECT_NEAR(s.number("nodeVel", 2, 1), gamma * u1 / (beta * dt), 1e-13);
}

// Central difference from rest: m u1 / dt^2 = P (U_-1 = U_0 = 0); needs Linear.
TEST(TransientAnalysis, CentralDifferenceFirstStepsAndLinearOnly) {
  Script s;
  buildOscillator(s, "CentralDifference", "Linear");
  ASSERT_EQ(s.integer("analyze", 1, dt), 0);
  const double u1 = P * dt * dt / m;
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), u1, 1e-16);
  ASSERT_EQ(s.integer("analyze", 1, dt), 0);
  // m (u2 - 2 u1) / dt^2 + k u1 = P
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), 2.0 * u1 + (P - k * u1) * dt * dt / m, 1e-16);
  // Newton's second update (the first one moved: not converged) is refused,
  // and the model stays at rest.
  buildOscillator(s, "CentralDifference", "Newton");
  EXPECT_EQ(s.integer("analyze", 1, dt), -3);
  EXPECT_EQ(s.number("nodeDisp", 2, 1), 0.0);
  EXPECT_EQ(s.number("getTime"), 0.0);
}

TEST(TransientAnalysis, StaticIntegratorIsRefusedByTransientAnalysis) {
  Script s;
  buildOscillator(s, "Newmark");
  s("integrator", "LoadControl", 0.1);
  EXPECT_THROW(s("analysis", "Transient"), OpenSeesError);
  EXPECT_THROW(s("analyze", 1, dt), OpenSeesError);
}

TEST(ViscousMaterial, ForceLawAndDampingTangent) {
  ViscousMaterial d(1, 3.0, 0.5);
  d.setTrialStrain(0.2, -0.16);
  EXPECT_NEAR(d.stress(), -3.0 * 0.4, 1e-15);
  EXPECT_NEAR(d.dampingTangent(), 0.5 * 3.0 / 0.4, 1e-14);
  EXPECT_EQ(d.tangent(), 0.0);
  // Finite difference of the stress in the rate.
  const double h = 1e-7;
  d.setTrialStrain(0.2, 0.3 + h);
  const double sp = d.stress();
  d.setTrialStrain(0.2, 0.3 - h);
  const double sm = d.stress();
  d.setTrialStrain(0.2, 0.3);
  EXPECT_NEAR((sp - sm) / (2 * h), d.dampingTangent(), 1e-7);
  d.setTrialStrain(0.0, 0.0);
  EXPECT_EQ(d.stress(), 0.0);
  EXPECT_TRUE(std::isfinite(d.dampingTangent()));
}
