// BeamContact3D through static analyses driven by the command interpreter:
// stick-slip of a soil node dragged along a pile (closed form), rotational
// friction of a twisted pile, opening and closing with the one-step status
// lag of C20, and Newton's convergence order while sliding in two directions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/OpenSeesError.h"
#include "support/Script.h"
#include "support/TestSpring.h"

using namespace beamsolid;
using namespace beamsolid::testing;

namespace {

constexpr double R = 0.3;
constexpr double mu = 0.3, G = 1e5, c = 0.5;
constexpr double P = 100.0;  // normal load pressing the soil node onto the pile

// A rigid pile segment from (0,0,0) to (0,0,2) (beam nodes 1, 2, elastic
// beam 10), the soil node 3 on its surface at (R, 0, 1) pressed by P in -x,
// multiplier node 4 and BeamContact3D 1 with ContactMaterial3D 1.
void buildPileAndSoilNode(Script& s) {
  registerTestTypes();
  s("wipe");
  s("model", "basic", "-ndm", 3, "-ndf", 6);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 0.0, 0.0, 2.0);
  s("fix", 1, 1, 1, 1, 1, 1, 1);
  s("fix", 2, 1, 1, 1, 1, 1, 1);
  s("geomTransf", "Linear", 1, 1.0, 0.0, 0.0);
  s("element", "elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1);
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 3, R, 0.0, 1.0);
  s("node", 4, R, 0.0, 1.0);
  s("nDMaterial", "ContactMaterial3D", 1, mu, G, c, 0.0);
  s("element", "BeamContact3D", 1, 1, 2, 3, 4, R, 1, 1, 1e-8, 1e-8);
}

void staticAnalysis(Script& s, double dt, const char* testType = "NormDispIncr", double tol = 1e-12) {
  s("constraints", "Transformation");
  s("numberer", "RCM");
  s("system", "UmfPack");
  s("test", testType, tol, 25);
  s("algorithm", "Newton");
  s("integrator", "LoadControl", dt);
  s("analysis", "Static");
}

// Presses the soil node with P (pattern 1), then holds it constant. The
// driver dofs (node, 1-based dof) are held while pressing -- at t_n = 0 the
// friction has no stiffness, so nothing else holds them -- and then freed for
// the imposed displacements of the next pattern (driver nodes have ndf 3).
void pressSoilNode(Script& s, const std::vector<std::pair<int, int>>& drivers = {}) {
  for (auto [node, dof] : drivers) {
    std::vector<CommandArgs::Value> flags{static_cast<long long>(node)};
    for (int d = 1; d <= 3; ++d) flags.emplace_back(static_cast<long long>(d == dof));
    s.interp.call("fix", flags);
  }
  s("timeSeries", "Linear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 3, -P, 0.0, 0.0);
  staticAnalysis(s, 1.0);
  ASSERT_EQ(s.integer("analyze", 1), 0);
  s("loadConst", "-time", 0.0);
  s("wipeAnalysis");
  for (auto [node, dof] : drivers) s("remove", "sp", node, dof);
}

}  // namespace

TEST(BeamContactAnalysis, StickSlipAlongThePileMatchesTheClosedForm) {
  // The soil node (held around the pile) is dragged along the axis through a
  // spring k from a driver node 5 whose z displacement is imposed:
  //   spring force F = min(k G/(k + G) u5, mu P + c), then unloading with the
  //   series stiffness and sliding back at -(mu P + c).
  Script s;
  buildPileAndSoilNode(s);
  const double k = 2e5;
  s("node", 5, R, 0.0, 2.0);
  s("fix", 3, 0, 1, 0);
  s("fix", 5, 1, 1, 0);
  s("element", "testSpring", 2, 3, 5, k);
  pressSoilNode(s, {{5, 3}});
  EXPECT_NEAR(s.list("eleResponse", 1, "physicalForceScalar")[0], P, 1e-9 * P);

  const double capacity = mu * P + c;
  const double series = k * G / (k + G);
  const double uMax = 3.0 * capacity / series;
  s("timeSeries", "Path", 2, "-time", 0.0, 1.0, 2.0, "-values", 0.0, uMax, -uMax);
  s("pattern", "Plain", 2, 2);
  s("sp", 5, 3, 1.0);
  const int steps = 40;
  staticAnalysis(s, 2.0 / steps);
  // Elastic-plastic history of the spring force, tracked by hand.
  double elasticSlip = 0.0;  // soil node's stick displacement G * elasticSlip = friction
  double plasticSlip = 0.0;
  double previousU3 = 0.0;
  for (int step = 1; step <= steps; ++step) {
    ASSERT_EQ(s.integer("analyze", 1), 0) << "step " << step;
    const double t = s.number("getTime");
    const double u5 = t <= 1.0 ? uMax * t : uMax * (2.0 - t) - uMax * (t - 1.0);
    // Sticking trial: spring and stick spring in series.
    const double trial = k * (u5 - plasticSlip) / (k + G);  // elastic soil-node slip
    const double force = std::clamp(G * trial, -capacity, capacity);
    elasticSlip = force / G;
    const double u3 = u5 - force / k;
    plasticSlip = u3 - elasticSlip;
    EXPECT_NEAR(s.number("nodeDisp", 3, 3), u3, 1e-12) << "step " << step;
    const auto scalars = s.list("eleResponse", 1, "physicalForceScalar");
    EXPECT_NEAR(scalars[0], P, 1e-9 * P) << "step " << step;
    // Friction on the soil node opposes the spring: -F along the axis.
    EXPECT_NEAR(scalars[1], -force, 1e-8 * capacity) << "step " << step;
    EXPECT_NEAR(s.list("eleResponse", 1, "totalSlip")[0], u3, 1e-12) << "step " << step;
    // OpenSees' names: forcescalar's friction is the traction on the
    // unnormalised axial base vector (length L = 2: -L times ours), and slip
    // is this step's slip as a fraction of the segment.
    EXPECT_NEAR(s.list("eleResponse", 1, "forcescalar")[1], -2.0 * scalars[1], 2e-8 * capacity) << "step " << step;
    EXPECT_NEAR(s.list("eleResponse", 1, "slip")[0], (u3 - previousU3) / 2.0, 1e-12) << "step " << step;
    previousU3 = u3;
    EXPECT_EQ(s.list("eleResponse", 1, "status")[0], std::abs(G * trial) > capacity ? 2.0 : 1.0) << "step " << step;
  }
  EXPECT_NEAR(s.list("eleResponse", 1, "physicalForceScalar")[1], capacity, 1e-8 * capacity);
}

TEST(BeamContactAnalysis, TwistedPileDragsTheSoilNodeAroundItsCircumference) {
  // Soil node held in y and z, pile twisted by phi at both ends: the surface
  // slides R phi under the node; friction F = min(G R phi, mu P + c) acts on
  // the node along +y and the pile feels the torque -R F about its axis.
  Script s;
  buildPileAndSoilNode(s);
  s("fix", 3, 0, 1, 1);
  // The pile's twist is held while the node is pressed (at t_n = 0 friction
  // has no stiffness), then driven.
  pressSoilNode(s);
  s("remove", "sp", 1, 6);
  s("remove", "sp", 2, 6);
  const double capacity = mu * P + c;
  const double phiMax = 2.5 * capacity / (G * R);
  s("timeSeries", "Linear", 2);
  s("pattern", "Plain", 2, 2);
  s("sp", 1, 6, phiMax);
  s("sp", 2, 6, phiMax);
  const int steps = 20;
  staticAnalysis(s, 1.0 / steps);
  for (int step = 1; step <= steps; ++step) {
    ASSERT_EQ(s.integer("analyze", 1), 0) << "step " << step;
    const double phi = phiMax * step / steps;
    const double F = std::min(G * R * phi, capacity);
    const auto scalars = s.list("eleResponse", 1, "physicalForceScalar");
    EXPECT_NEAR(scalars[2], F, 1e-6 * capacity) << "step " << step;
    const auto moments = s.list("eleResponse", 1, "mastermoment");
    EXPECT_NEAR(moments[2] + moments[5], -R * F, 1e-6 * R * capacity) << "step " << step;
    // The node moved -R phi relative to the surface.
    EXPECT_NEAR(s.list("eleResponse", 1, "totalSlip")[1], -R * phi, 1e-6 * R * phiMax) << "step " << step;
  }
  s("reactions");
  EXPECT_NEAR(s.number("nodeReaction", 3, 2), -capacity, 1e-6 * capacity);
}

TEST(BeamContactAnalysis, OpeningAndClosingAreSeenOneStepLate) {
  // The soil node hangs on a spring kn (to fixed node 6) normal to the pile
  // and is pushed (f > 0) or pulled (f < 0) by f P. In contact the gap is
  // zero and lambda = f P; released, the node sits at u = -f P / kn. The
  // status follows C20: released at the commit of the first step with
  // lambda < -forceTol, closed at the commit of the first step that ends
  // within gapTol -- each one step late.
  Script s;
  buildPileAndSoilNode(s);
  const double kn = 1e4;
  s("node", 6, R + 1.0, 0.0, 1.0);
  s("fix", 6, 1, 1, 1);
  s("fix", 3, 0, 1, 1);
  s("element", "testSpring", 2, 3, 6, kn);
  s("timeSeries", "Path", 1, "-time", 0.0, 1.0, 2.0, 3.0, "-values", 0.0, 1.0, -1.0, 1.0);
  s("pattern", "Plain", 1, 1);
  s("load", 3, -P, 0.0, 0.0);
  // Steps that never land on f = 0 (at t = 1.5 and 2.5).
  const double dt = 0.14;
  staticAnalysis(s, dt);
  bool inContact = true;  // cSwitch 0
  int releases = 0, closings = 0;
  for (int step = 1; step <= 21; ++step) {
    ASSERT_EQ(s.integer("analyze", 1), 0) << "step " << step;
    const double t = step * dt;
    const double f = t <= 1.0 ? t : t <= 2.0 ? 1.0 - 2.0 * (t - 1.0) : -1.0 + 2.0 * (t - 2.0);
    const double u = s.number("nodeDisp", 3, 1);
    const double lambda = s.list("eleResponse", 1, "physicalForceScalar")[0];
    if (inContact) {
      EXPECT_NEAR(u, 0.0, 1e-12) << "step " << step;
      EXPECT_NEAR(lambda, f * P, 1e-9 * P) << "step " << step;
    } else {
      EXPECT_NEAR(u, -f * P / kn, 1e-12) << "step " << step;
      EXPECT_EQ(lambda, 0.0) << "step " << step;
    }
    // C20 for this one-dof system, decided at the commit of this step.
    const double gap = u;
    const bool next = gap < 1e-8 && !(inContact && lambda <= -1e-8);
    if (inContact && !next) ++releases;
    if (!inContact && next) {
      ++closings;
      // The closing step ends with the node inside the pile: the lag's cost.
      EXPECT_LT(gap, 0.0) << "step " << step;
    }
    EXPECT_EQ(s.list("eleResponse", 1, "status")[0] != 0.0, inContact) << "step " << step;
    inContact = next;
  }
  EXPECT_EQ(releases, 1);
  EXPECT_EQ(closings, 1);
}

TEST(BeamContactAnalysis, NewtonConvergesQuadraticallyWhileSlidingInTwoDirections) {
  // The soil node, pressed onto the pile, is dragged along the axis into
  // sliding and then sideways: the return map turns the traction within the
  // step, a genuinely nonlinear equilibrium that the consistent tangent
  // (C16, C18) must solve at a quadratic rate.
  Script s;
  buildPileAndSoilNode(s);
  const double k = 2e4;
  s("node", 5, R, 0.0, 2.0);
  s("node", 7, R, 1.0, 1.0);
  s("fix", 5, 1, 1, 0);
  s("fix", 7, 1, 0, 1);
  s("element", "testSpring", 2, 3, 5, k);
  s("element", "testSpring", 3, 3, 7, k);
  pressSoilNode(s, {{5, 3}, {7, 2}});
  const double capacity = mu * P + c;
  s("timeSeries", "Linear", 2);
  s("pattern", "Plain", 2, 2);
  s("sp", 5, 3, 4.0 * capacity / k);
  s("sp", 7, 2, 3.0 * capacity / k);
  staticAnalysis(s, 0.5, "NormUnbalance", 1e-11);
  ASSERT_EQ(s.integer("analyze", 1), 0);
  ASSERT_EQ(s.list("eleResponse", 1, "status")[0], 2.0);
  ASSERT_EQ(s.integer("analyze", 1), 0);
  ASSERT_EQ(s.list("eleResponse", 1, "status")[0], 2.0);
  // testNorms has maxIter entries as in OpenSees: the iterations, then zeros.
  auto norms = s.list("testNorms");
  norms.resize(static_cast<std::size_t>(s.integer("testIter")));
  ASSERT_GE(norms.size(), 3u);
  EXPECT_LE(norms.size(), 6u) << ::testing::PrintToString(norms);
  // Quadratic rate: with e_k = |r_k| / |r_0|, e_{k+1} <= e_k^2 once e_k < 1e-3
  // (a linear rate rho would need rho <= e_k to pass), down to round-off.
  int checked = 0;
  for (std::size_t k = 1; k + 1 < norms.size(); ++k) {
    const double a = norms[k] / norms[0], b = norms[k + 1] / norms[0];
    if (b < 1e-13) break;
    if (a >= 1e-3) continue;
    EXPECT_LE(b, a * a) << "iteration " << k + 1 << ": " << ::testing::PrintToString(norms);
    ++checked;
  }
  EXPECT_GE(checked, 1) << ::testing::PrintToString(norms);
  // Sliding: the friction force on the node is mu lambda + c in magnitude
  // (lambda dips below P: the node rides up the curved surface).
  const auto scalars = s.list("eleResponse", 1, "physicalForceScalar");
  EXPECT_NEAR(std::hypot(scalars[1], scalars[2]), mu * scalars[0] + c, 1e-6 * capacity);
  EXPECT_NEAR(scalars[0], P, 1e-2 * P);
}

TEST(BeamContactAnalysis, DonutPulloutResistanceIsMuTimesTheNormalForces) {
  // The paper's donut test: a pile (elasticBeamColumn, nodes z = 0..3) pulled
  // up through a ring of stdBrick soil (inner radius R at the pile surface,
  // outer radius 1, soil node levels between the beam nodes). Stage 1,
  // frictionless: the outer boundary is pushed in radially, confining the
  // pile. Stage 2, friction on: the pile top is pulled up until every contact
  // slides. Then the pull force equals the sum of mu lambda_i over the
  // contacts (c = 0), every level's contacts carry the same lambda by
  // symmetry, and the contact forces are axial.
  registerTestTypes();
  Script s;
  const double muPile = 0.4, Gpile = 2e4;
  const int nTheta = 8, nRadial = 2;
  const double radii[nRadial + 1] = {R, 0.65, 1.0};
  const double levels[] = {0.25, 0.75, 1.25, 1.75};
  const int nLevels = 4;
  auto soilNode = [&](int level, int ring, int sector) { return 100 + (level * nTheta + sector) * (nRadial + 1) + ring; };

  s("model", "basic", "-ndm", 3, "-ndf", 6);
  for (int k = 0; k < 4; ++k) s("node", 1 + k, 0.0, 0.0, double(k));
  for (int k = 0; k < 4; ++k) s("fix", 1 + k, 0, 0, k == 3 ? 1 : 0, 0, 0, 1);  // no twist; top held in stage 1
  s("geomTransf", "Linear", 1, 1.0, 0.0, 0.0);
  const double A = M_PI * R * R, I = M_PI * std::pow(R, 4) / 4.0;
  for (int k = 0; k < 3; ++k) s("element", "elasticBeamColumn", 1 + k, 1 + k, 2 + k, A, 3e7, 1.2e7, 2 * I, I, I, 1);

  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("nDMaterial", "ElasticIsotropic", 2, 1e4, 0.3);
  s("nDMaterial", "ContactMaterial3D", 1, muPile, Gpile, 0.0, 0.0);
  for (int k = 0; k < nLevels; ++k)
    for (int j = 0; j < nTheta; ++j)
      for (int i = 0; i <= nRadial; ++i) {
        const double theta = 2.0 * M_PI * j / nTheta;
        s("node", soilNode(k, i, j), radii[i] * std::cos(theta), radii[i] * std::sin(theta), levels[k]);
      }
  int brick = 100;
  for (int k = 0; k + 1 < nLevels; ++k)
    for (int j = 0; j < nTheta; ++j)
      for (int i = 0; i < nRadial; ++i) {
        const int jn = (j + 1) % nTheta;
        s("element", "stdBrick", brick++, soilNode(k, i, j), soilNode(k, i + 1, j), soilNode(k, i + 1, jn),
          soilNode(k, i, jn), soilNode(k + 1, i, j), soilNode(k + 1, i + 1, j), soilNode(k + 1, i + 1, jn),
          soilNode(k + 1, i, jn), 2);
      }
  // One contact per pile-surface soil node, on the segment holding its level.
  std::vector<int> contacts;
  for (int k = 0; k < nLevels; ++k)
    for (int j = 0; j < nTheta; ++j) {
      const int sNode = soilNode(k, 0, j), lNode = 1000 + sNode, tag = 1000 + sNode;
      const int segment = int(levels[k]);  // beam nodes segment + 1, segment + 2
      s("node", lNode, 0.0, 0.0, levels[k]);
      s("element", "BeamContact3D", tag, 1 + segment, 2 + segment, sNode, lNode, R, 1, 1, 1e-8, 1e-8);
      contacts.push_back(tag);
    }
  s("updateMaterialStage", "-material", 1, "-stage", 0);

  // Stage 1: confinement by an inward radial displacement of the outer ring.
  const double squeeze = 2e-3;
  s("timeSeries", "Linear", 1);
  s("pattern", "Plain", 1, 1);
  for (int k = 0; k < nLevels; ++k)
    for (int j = 0; j < nTheta; ++j) {
      const int n = soilNode(k, nRadial, j);
      const double theta = 2.0 * M_PI * j / nTheta;
      s("sp", n, 1, -squeeze * std::cos(theta));
      s("sp", n, 2, -squeeze * std::sin(theta));
      s("sp", n, 3, 0.0);
    }
  staticAnalysis(s, 0.5, "NormUnbalance", 1e-9);
  ASSERT_EQ(s.integer("analyze", 2), 0);
  double normalSum = 0.0;
  for (int tag : contacts) {
    const auto f = s.list("eleResponse", tag, "physicalForceScalar");
    EXPECT_GT(f[0], 0.0) << "contact " << tag;
    EXPECT_NEAR(f[1], 0.0, 1e-12) << "frictionless stage";
    normalSum += f[0];
  }
  s("loadConst", "-time", 0.0);
  s("wipeAnalysis");

  // Stage 2: friction on, the pile top pulled up.
  s("updateMaterialStage", "-material", 1, "-stage", 1);
  s("remove", "sp", 4, 3);
  s("timeSeries", "Linear", 2);
  s("pattern", "Plain", 2, 2);
  s("sp", 4, 3, 0.02);
  staticAnalysis(s, 0.05, "NormUnbalance", 1e-9);
  ASSERT_EQ(s.integer("analyze", 20), 0);

  double frictionSum = 0.0, muLambdaSum = 0.0;
  Vector3 onPile = Vector3::Zero();
  for (int k = 0; k < nLevels; ++k) {
    const double lambda0 = s.list("eleResponse", contacts[k * nTheta], "physicalForceScalar")[0];
    for (int j = 0; j < nTheta; ++j) {
      const int tag = contacts[k * nTheta + j];
      const auto f = s.list("eleResponse", tag, "physicalForceScalar");
      EXPECT_EQ(s.list("eleResponse", tag, "status")[0], 2.0) << "contact " << tag << " slides";
      EXPECT_NEAR(f[0], lambda0, 1e-8 * lambda0) << "symmetry at level " << k;
      EXPECT_NEAR(f[1], muPile * f[0], 1e-8 * muPile * f[0]) << "contact " << tag;
      EXPECT_NEAR(f[2], 0.0, 1e-8 * f[1]) << "contact " << tag;
      frictionSum += f[1];
      muLambdaSum += muPile * f[0];
      const auto m = s.list("eleResponse", tag, "masterforce");
      onPile += Vector3(m[0] + m[3], m[1] + m[4], m[2] + m[5]);
    }
  }
  EXPECT_NEAR(frictionSum, muLambdaSum, 1e-8 * muLambdaSum);
  // The contacts pull the pile down with the friction sum, laterally nothing.
  EXPECT_NEAR(onPile.z(), -frictionSum, 1e-8 * frictionSum);
  EXPECT_LE(std::hypot(onPile.x(), onPile.y()), 1e-8 * frictionSum);
  // The support at the pile top carries it.
  s("reactions");
  EXPECT_NEAR(s.number("nodeReaction", 4, 3), frictionSum, 1e-6 * frictionSum);
  // Friction raised the confinement only slightly (Poisson effect of the shear).
  EXPECT_NEAR(muLambdaSum / muPile, normalSum, 0.1 * normalSum);
}
