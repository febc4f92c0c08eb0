// ModalDamping: the force M Phi diag(2 zeta_i w_i / m_i) Phi^T M v against
// hand values on a two-node model with nodal and element mass, one ratio for
// every mode and one per mode; mode shapes of any scale give the same force.
#include <gtest/gtest.h>

#include <cmath>

#include "SolidsTestSupport.h"
#include "core/Domain.h"
#include "core/ModalDamping.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

// Two 3-dof nodes with lumped masses; modes along x: phi1 = (1, 1), phi2 = (1, -1) on dof 1.
void twoNodes(Domain& d, double scale) {
  addNode(d, 1, 3, 0.0, 0.0, 0.0);
  addNode(d, 2, 3, 1.0, 0.0, 0.0);
  d.node(1, "test").setMass(Vector3(2.0, 2.0, 2.0));
  d.node(2, "test").setMass(Vector3(2.0, 2.0, 2.0));
  Matrix phi1 = Matrix::Zero(3, 2), phi2 = Matrix::Zero(3, 2);
  phi1(0, 0) = scale, phi1(0, 1) = scale;
  phi2(0, 0) = scale, phi2(0, 1) = -scale;
  d.node(1, "test").setEigenvectors(phi1);
  d.node(2, "test").setEigenvectors(phi2);
  d.setEigenvalues({4.0, 25.0});  // w = 2 and 5
}

}  // namespace

TEST(ModalDamping, ForceOfEachModeAgainstHandValues) {
  // v = (3, 1) on dof 1: q1 = phi1^T M v = 2*3 + 2*1 = 8, m1 = 4; q2 = 2*3 - 2*1 = 4, m2 = 4.
  // f = M phi1 (2 z1 w1 q1/m1) + M phi2 (2 z2 w2 q2/m2).
  for (double scale : {1.0, 0.37}) {
    Domain d;
    twoNodes(d, scale);
    d.node(1, "test").setTrialVel(Vector3(3.0, 0.5, 0.0));
    d.node(2, "test").setTrialVel(Vector3(1.0, 0.0, 0.7));
    const double z1 = 0.05, z2 = 0.1;
    const auto f = ModalDamping({z1, z2}).forces(d);
    const double c1 = 2 * z1 * 2.0 * 8.0 / 4.0, c2 = 2 * z2 * 5.0 * 4.0 / 4.0;
    EXPECT_NEAR(f.at(1)[0], 2.0 * (c1 + c2), 1e-12);
    EXPECT_NEAR(f.at(2)[0], 2.0 * (c1 - c2), 1e-12);
    // Dofs without mode shape components take no damping force.
    EXPECT_EQ(f.at(1)[1], 0.0);
    EXPECT_EQ(f.at(2)[2], 0.0);
    // One ratio damps every mode.
    const auto g = ModalDamping({z1}).forces(d);
    const double g2 = 2 * z1 * 5.0 * 4.0 / 4.0;
    EXPECT_NEAR(g.at(1)[0], 2.0 * (c1 + g2), 1e-12);
  }
}

TEST(ModalDamping, ElementMassCounts) {
  // A truss with rho adds lumped mass rho L / 2 = 1 to each node's translations.
  Domain d;
  twoNodes(d, 1.0);
  addUniaxialMaterial(d, "Elastic", 1, 100.0);
  addElement(d, "truss", 1, 1, 2, 1.0, 1, "-rho", 2.0);
  d.node(1, "test").setTrialVel(Vector3(1.0, 0.0, 0.0));
  d.node(2, "test").setTrialVel(Vector3(1.0, 0.0, 0.0));
  // Mode 1 only (v is along phi1): q1 = 3 + 3 = 6, m1 = 6, f = M phi1 2 z w q/m = 3 * 0.2.
  const auto f = ModalDamping({0.05, 0.0}).forces(d);
  EXPECT_NEAR(f.at(1)[0], 3.0 * 2 * 0.05 * 2.0, 1e-12);
  EXPECT_NEAR(f.at(2)[0], 3.0 * 2 * 0.05 * 2.0, 1e-12);
}
