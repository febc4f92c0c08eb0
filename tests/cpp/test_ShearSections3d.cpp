// Shear components of 3D sections in forceBeamColumn: the force interpolation
// rows of Vy and Vz, the element's initial flexibility against the closed form
// of the simply supported basic system, and the element tangent against
// finite differences with a Steel01 shear spring past yield. Models are built
// through the interpreter (support/Script.h).
#include <gtest/gtest.h>

#include "core/Node.h"
#include "elements/ForceBeamColumn3d.h"
#include "sections/SectionForceDeformation.h"
#include "support/Script.h"

namespace sheartest {

using beamsolid::Element;
using beamsolid::ForceBeamColumn3d;
using beamsolid::Node;
using beamsolid::SectionCode;
using beamsolid::Vector;
using beamsolid::testing::Script;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

constexpr double kE = 200.0, kA = 10.0, kIz = 3.0, kIy = 2.0, kG = 80.0, kJ = 5.0, kL = 2.5;

ForceBeamColumn3d& cantilever(Script& s, const char* shear, int points) {
  s("model", "basic", "-ndm", 3, "-ndf", 6);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, kL, 0.0, 0.0);
  s("fix", 1, 1, 1, 1, 1, 1, 1);
  s("uniaxialMaterial", "Elastic", 2, 50.0);
  s("uniaxialMaterial", "Steel01", 3, 0.6, 70.0, 0.05);
  s("section", "Elastic", 1, kE, kA, kIz, kIy, kG, kJ);
  if (std::string(shear) == "elastic8") s("section", "Elastic", 10, kE, kA, kIz, kIy, kG, kJ, 0.5, 0.7);
  else s("section", "Aggregator", 10, 3, "Vz", 2, "Vy", "-section", 1);
  s("geomTransf", "Linear", 1, 0.0, 0.0, 1.0);
  s("beamIntegration", "Lobatto", 1, 10, points);
  s("element", "forceBeamColumn", 1, 1, 2, 1, 1, "-iter", 50, 1e-16);
  return dynamic_cast<ForceBeamColumn3d&>(s.interp.domain().element(1, "test"));
}

TEST(ShearSections3d, InterpolationRowsAreTheMomentSlopes) {
  Script s;
  ForceBeamColumn3d& e = cantilever(s, "aggregator", 3);
  ASSERT_TRUE(e.shearDeformable());
  const auto& section = e.section(0);
  ASSERT_EQ(section.numShear(), 2);
  EXPECT_EQ(section.shearCode(0), SectionCode::Vz);  // the command's order
  const auto b = ForceBeamColumn3d::forceInterpolation(section, 0.3, kL);
  ASSERT_EQ(b.rows(), 6);
  Eigen::Matrix<double, 2, 6> expected = Eigen::Matrix<double, 2, 6>::Zero();
  expected(0, 3) = expected(0, 4) = 1.0 / kL;  // Vz = (My_i + My_j) / L
  expected(1, 1) = expected(1, 2) = 1.0 / kL;  // Vy = (Mz_i + Mz_j) / L
  EXPECT_TRUE(b.bottomRows(2).isApprox(expected, 1e-15));
  const Eigen::Matrix<double, 4, 6> bending = ForceBeamColumn3d::forceInterpolation(0.3);
  EXPECT_TRUE(b.topRows(4) == bending);
}

TEST(ShearSections3d, InitialFlexibilityIsTheClosedForm) {
  // F = integral of b^T f b: bending L/(3 EI) on the diagonal, -L/(6 EI) off
  // it, plus 1/(k_v L) on all four terms of the plane's shear.
  for (const char* shear : {"aggregator", "elastic8"}) {
    Script s;
    ForceBeamColumn3d& e = cantilever(s, shear, 3);
    const bool agg = std::string(shear) == "aggregator";
    const double kvy = agg ? 50.0 : 0.5 * kG * kA, kvz = agg ? 70.0 : 0.7 * kG * kA;
    Matrix6 F = Matrix6::Zero();
    F(0, 0) = kL / (kE * kA);
    F(5, 5) = kL / (kG * kJ);
    for (const auto& [first, EI, kv] : {std::tuple{1, kE * kIz, kvy}, std::tuple{3, kE * kIy, kvz}}) {
      F(first, first) = F(first + 1, first + 1) = kL / (3 * EI) + 1.0 / (kv * kL);
      F(first, first + 1) = F(first + 1, first) = -kL / (6 * EI) + 1.0 / (kv * kL);
    }
    EXPECT_LT((e.initialBasicStiffness() * F - Matrix6::Identity()).norm(), 1e-12) << shear;
  }
}

TEST(ShearSections3d, TangentMatchesFiniteDifferencesWithYieldedShear) {
  Script s;
  ForceBeamColumn3d& e = cantilever(s, "aggregator", 4);
  Node& n2 = s.interp.domain().node(2, "test");
  // Vz = 70 (u_z / L - ...) beyond its yield (0.6 / 70 strain) at the base.
  Vector u(6);
  u << 1.0e-3, 0.02, 0.05, 2.0e-3, -1.0e-3, 3.0e-3;
  n2.setTrialDisp(u);
  e.update();
  ASSERT_TRUE(e.converged());
  const double vz = e.section(0).shearForce()[0];
  ASSERT_GT(std::abs(vz), 0.6) << "the Vz spring should have yielded";
  const Matrix12 k = e.tangentStiff();
  Matrix12 fd;
  const double h = 1e-8;
  for (int col = 0; col < 12; ++col) {
    Node& n = *e.nodes()[col / 6];
    const double u0 = n.trialDisp()(col % 6);
    n.setTrialDisp(col % 6, u0 + h);
    e.update();
    const Vector12 plus = e.resistingForce();
    n.setTrialDisp(col % 6, u0 - h);
    e.update();
    const Vector12 minus = e.resistingForce();
    n.setTrialDisp(col % 6, u0);
    e.update();
    fd.col(col) = (plus - minus) / (2.0 * h);
  }
  EXPECT_LT((k - fd).norm(), 1e-6 * k.norm()) << (k - fd).cwiseAbs().maxCoeff();
  // Section equilibrium with the shear rows: s = b q at every section.
  const auto q = e.basicForce();
  for (int i = 0; i < e.numSections(); ++i) {
    const auto b = ForceBeamColumn3d::forceInterpolation(e.section(i), e.sectionLocations()[i], kL);
    Eigen::Matrix<double, 6, 1> force;
    force << e.section(i).force(), e.section(i).shearForce();
    EXPECT_LT((force - b * q).norm(), 1e-9 * q.norm()) << i;
  }
}

}  // namespace sheartest
