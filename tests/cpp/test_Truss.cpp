// truss and corotTruss: finite-difference tangents (including corotTruss at
// a large rotation and after yield), a statically determinate space truss
// against joint-by-joint statics, ElasticPP yielding at A*E*epsyP, rigid
// rotation, mass matrices, responses and input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/CorotTruss.h"
#include "elements/Truss.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using beamsolid::testsupport::errorOf;

Vector3 unit(const Vector3& v) { return v / v.norm(); }

// Large rotation about a unit axis (Rodrigues).
Matrix3 rotation(const Vector3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

}  // namespace

TEST(Truss, FiniteDifferenceTangentWithMixedNodeDofs) {
  // Linear in the displacements: exact to round-off. h = 1e-6, tolerance 1e-7 relative.
  Domain d;
  addNode(d, 1, 6, 0.0, 0.0, 0.0);
  addNode(d, 2, 3, 2.0, 1.0, 0.5);
  addUniaxialMaterial(d, "Elastic", 1, 1000.0);
  Element& e = addElement(d, "truss", 1, 1, 2, 0.1, 1);
  ASSERT_EQ(e.numDOF(), 9);
  d.node(2, "test").setTrialDisp(Vector3(0.01, -0.02, 0.03));
  const TangentCheck c = checkTangent(e, 1e-6);
  EXPECT_LE(c.relativeError(), 1e-7) << c.maxError;
  // Rotational rows and columns of node 1 are zero.
  const Matrix K = e.tangentStiff();
  EXPECT_EQ(K.block(3, 0, 3, 9).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(K.block(0, 3, 9, 3).cwiseAbs().maxCoeff(), 0.0);
}

TEST(CorotTruss, FiniteDifferenceTangentAtALargeRotation) {
  // The bar turned by 70 degrees and stretched 5%: the material plus the
  // geometric stiffness must match central differences. Nonlinear in u, so
  // the truncation error is O(h^2): h = 1e-6, tolerance 1e-6 relative.
  Domain d;
  const Vector3 Xi(0.0, 0.0, 0.0), Xj(2.0, 1.0, 0.5);
  addNode(d, 1, 3, Xi(0), Xi(1), Xi(2));
  addNode(d, 2, 6, Xj(0), Xj(1), Xj(2));
  addUniaxialMaterial(d, "Elastic", 1, 1000.0);
  Element& e = addElement(d, "corotTruss", 1, 1, 2, 0.1, 1);
  const Vector3 ui(0.05, -0.02, 0.01);
  const Vector3 xj = Xi + ui + 1.05 * rotation(Vector3(0.3, -0.5, 1.0), 70.0 * M_PI / 180.0) * (Xj - Xi);
  d.node(1, "test").setTrialDisp(ui);
  Vector uj = Vector::Zero(6);
  uj.head<3>() = xj - Xj;
  d.node(2, "test").setTrialDisp(uj);
  e.update();
  auto& bar = dynamic_cast<CorotTruss&>(e);
  EXPECT_NEAR(bar.axialForce(), 0.1 * 1000.0 * 0.05, 1e-10);
  const TangentCheck c = checkTangent(e, 1e-6);
  EXPECT_LE(c.relativeError(), 1e-6) << c.maxError;
}

TEST(CorotTruss, FiniteDifferenceTangentAfterYield) {
  // ElasticPP past yield: material tangent 0, the geometric stiffness alone
  // remains and must still match central differences (tolerance 1e-6 relative).
  Domain d;
  addNode(d, 1, 3, 0.0, 0.0, 0.0);
  addNode(d, 2, 3, 3.0, 0.0, 4.0);
  addUniaxialMaterial(d, "ElasticPP", 1, 1000.0, 0.01);
  Element& e = addElement(d, "corotTruss", 1, 1, 2, 0.2, 1);
  const Vector3 Xj(3.0, 0.0, 4.0);
  d.node(2, "test").setTrialDisp(Vector3(1.04 * rotation(Vector3::UnitY(), 0.8) * Xj - Xj));
  e.update();
  auto& bar = dynamic_cast<CorotTruss&>(e);
  EXPECT_DOUBLE_EQ(bar.material().tangent(), 0.0);
  EXPECT_NEAR(bar.axialForce(), 0.2 * 1000.0 * 0.01, 1e-12);
  const TangentCheck c = checkTangent(e, 1e-6);
  EXPECT_GT(c.maxEntry, 0.0);
  EXPECT_LE(c.relativeError(), 1e-6) << c.maxError;
}

TEST(CorotTruss, RigidRotationCausesNoForce) {
  Domain d;
  const Vector3 Xi(1.0, -1.0, 0.5), Xj(3.0, 2.0, -0.5);
  for (int tag : {1, 3}) addNode(d, tag, 3, Xi(0), Xi(1), Xi(2));
  for (int tag : {2, 4}) addNode(d, tag, 3, Xj(0), Xj(1), Xj(2));
  addUniaxialMaterial(d, "Elastic", 1, 1000.0);
  Element& corot = addElement(d, "corotTruss", 1, 1, 2, 0.1, 1);
  Element& small = addElement(d, "truss", 2, 3, 4, 0.1, 1);
  const Matrix3 R = rotation(Vector3(1.0, 2.0, 2.0), M_PI / 2);
  const Vector3 shift(0.3, 0.2, -0.1);
  for (int tag : {1, 3}) d.node(tag, "test").setTrialDisp(Vector3(R * Xi + shift - Xi));
  for (int tag : {2, 4}) d.node(tag, "test").setTrialDisp(Vector3(R * Xj + shift - Xj));
  d.update();
  EXPECT_LE(Vector(corot.resistingForce()).norm(), 1e-12 * 100.0);
  // The small-displacement bar sees a spurious strain under the same motion.
  EXPECT_GT(std::abs(dynamic_cast<Truss&>(small).axialForce()), 1.0);
}

TEST(Truss, StaticallyDeterminateSpaceTrussMatchesJointStatics) {
  // Supports A, B, C pinned; joint D hangs on A, B, C; joint E on D, B, C.
  // Bar forces from equilibrium of joint E, then of joint D (3x3 each);
  // displacements from bar elongations N L / (E A) by compatibility.
  // Tolerance 1e-10 relative.
  const Vector3 A(0, 0, 0), B(4, 0, 0), C(0, 3, 0), D(1, 1, 3), E(3, 2, 4);
  const Vector3 PD(0.0, 8.0, -15.0), PE(10.0, -5.0, -20.0);
  const double Emod = 2e5;
  Domain d;
  addNode(d, 1, 3, A(0), A(1), A(2));
  addNode(d, 2, 3, B(0), B(1), B(2));
  addNode(d, 3, 3, C(0), C(1), C(2));
  addNode(d, 4, 3, D(0), D(1), D(2));
  addNode(d, 5, 6, E(0), E(1), E(2));  // ndf 6: the bars leave its rotations unloaded
  addUniaxialMaterial(d, "Elastic", 1, Emod);
  struct Bar { int tag, i, j; double area; };
  const Bar bars[] = {{1, 4, 1, 0.010}, {2, 4, 2, 0.012}, {3, 4, 3, 0.008},
                      {4, 5, 4, 0.015}, {5, 5, 2, 0.010}, {6, 5, 3, 0.020}};
  for (const Bar& b : bars) addElement(d, b.tag % 2 ? "truss" : "Truss", b.tag, b.i, b.j, b.area, 1);

  DenseStatics statics(d);
  for (int tag : {1, 2, 3}) statics.fixAll(tag);
  for (int k = 3; k < 6; ++k) statics.fix(5, k);
  statics.load()(statics.index(4, 0)) = PD(0);
  statics.load()(statics.index(4, 1)) = PD(1);
  statics.load()(statics.index(4, 2)) = PD(2);
  for (int k = 0; k < 3; ++k) statics.load()(statics.index(5, k)) = PE(k);
  ASSERT_GE(statics.solve(1e-10), 0);

  // Joint E: N_ED u(E->D) + N_EB u(E->B) + N_EC u(E->C) + PE = 0.
  Matrix3 GE;
  GE << unit(D - E), unit(B - E), unit(C - E);
  const Vector3 NE = GE.fullPivLu().solve(-PE);  // N_ED, N_EB, N_EC
  // Joint D: N_DA u(D->A) + N_DB u(D->B) + N_DC u(D->C) + N_ED u(D->E) + PD = 0.
  Matrix3 GD;
  GD << unit(A - D), unit(B - D), unit(C - D);
  const Vector3 ND = GD.fullPivLu().solve(-PD - NE(0) * unit(E - D));
  const double expected[6] = {ND(0), ND(1), ND(2), NE(0), NE(1), NE(2)};
  for (const Bar& b : bars) {
    const auto& truss = dynamic_cast<const Truss&>(*d.findElement(b.tag));
    EXPECT_NEAR(truss.axialForce(), expected[b.tag - 1], 1e-10 * 30.0) << "bar " << b.tag;
  }

  // Compatibility: u(X->joint) . u_joint = elongation for bars to fixed supports.
  auto elongation = [&](int k, const Vector3& p, const Vector3& q, double area) {
    return expected[k] * (q - p).norm() / (Emod * area);
  };
  Matrix3 CD;
  CD << unit(D - A).transpose(), unit(D - B).transpose(), unit(D - C).transpose();
  const Vector3 uD = CD.fullPivLu().solve(
      Vector3(elongation(0, D, A, 0.010), elongation(1, D, B, 0.012), elongation(2, D, C, 0.008)));
  Matrix3 CE;
  CE << unit(E - D).transpose(), unit(E - B).transpose(), unit(E - C).transpose();
  const Vector3 uE = CE.fullPivLu().solve(Vector3(elongation(3, E, D, 0.015) + unit(E - D).dot(uD),
                                                  elongation(4, E, B, 0.010), elongation(5, E, C, 0.020)));
  EXPECT_LE((d.node(4, "test").trialDisp() - uD).norm(), 1e-10 * uD.norm());
  EXPECT_LE((d.node(5, "test").trialDisp().head<3>() - uE).norm(), 1e-10 * uE.norm());
  EXPECT_EQ(d.node(5, "test").trialDisp().tail<3>().norm(), 0.0);

  // Reactions balance the applied loads.
  d.calculateReactions();
  Vector3 reaction = Vector3::Zero();
  for (int tag : {1, 2, 3}) reaction += d.node(tag, "test").reaction();
  EXPECT_LE((reaction + PD + PE).norm(), 1e-10 * 30.0);
  // Bar forces act on translations only.
  for (int tag : {4, 5, 6}) {
    const Vector f = d.findElement(tag)->resistingForce();
    EXPECT_EQ(f.segment<3>(3).norm(), 0.0) << "bar " << tag;
  }
}

TEST(Truss, ElasticPPBarYieldsAtAEEpsyP) {
  // Bar along (1, 2, 2) of length 3, A = 0.02, E = 2e5, epsyP = 0.002:
  // Py = A*E*epsyP = 8. Displacement-controlled along the axis, committing
  // each step; axial forces worked by hand.
  Domain d;
  addNode(d, 1, 6, 0.0, 0.0, 0.0);
  addNode(d, 2, 6, 1.0, 2.0, 2.0);
  addUniaxialMaterial(d, "ElasticPP", 1, 2e5, 0.002);
  Element& e = addElement(d, "truss", 1, 1, 2, 0.02, 1);
  auto& bar = dynamic_cast<Truss&>(e);
  const Vector3 axis = Vector3(1, 2, 2) / 3.0;
  struct Step { double strain, axialForce, tangent; };
  const Step steps[] = {
      {0.001, 4.0, 2e5},    // elastic
      {0.002, 8.0, 0.0},    // exactly at the yield stress: plastic, as in OpenSees
      {0.003, 8.0, 0.0},    // yields: plastic strain 0.001
      {0.004, 8.0, 0.0},    // plastic strain 0.002
      {0.003, 4.0, 2e5},    // elastic unloading: E*(0.003 - 0.002) = 200
      {0.0, -8.0, 0.0},     // E*(0 - 0.002) = -400: on the compressive yield stress, plastic
      {-0.001, -8.0, 0.0},  // yields in compression: plastic strain 0.001
  };
  auto pull = [&](double strain) {
    Vector u = Vector::Zero(6);
    u.head<3>() = strain * 3.0 * axis;
    d.node(2, "test").setTrialDisp(u);
    e.update();
  };
  for (std::size_t s = 0; s < std::size(steps); ++s) {
    pull(steps[s].strain);
    EXPECT_NEAR(bar.axialForce(), steps[s].axialForce, 1e-10) << "step " << s;
    EXPECT_DOUBLE_EQ(bar.material().tangent(), steps[s].tangent) << "step " << s;
    const Vector f = e.resistingForce();
    EXPECT_LE((f.segment<3>(6) - steps[s].axialForce * axis).norm(), 1e-10) << "step " << s;
    EXPECT_EQ(f.segment<3>(9).norm(), 0.0) << "step " << s;
    e.commitState();
  }
  // Further compression stays on the plateau: zero tangent, matched by
  // central differences (h = 1e-8, tolerance 1e-6 absolute on K ~ 0).
  pull(-0.0015);
  EXPECT_NEAR(bar.axialForce(), -8.0, 1e-10);
  const TangentCheck c = checkTangent(e, 1e-8);
  EXPECT_EQ(c.maxEntry, 0.0);
  EXPECT_LE(c.maxError, 1e-6);
}

TEST(Truss, LumpedAndConsistentMass) {
  // rho is mass per unit length: total rho*L on each translation direction.
  Domain d;
  addNode(d, 1, 3, 0.0, 0.0, 0.0);
  addNode(d, 2, 6, 0.0, 3.0, 4.0);
  addUniaxialMaterial(d, "Elastic", 1, 1.0);
  Element& lumped = addElement(d, "truss", 1, 1, 2, 1.0, 1, "-rho", 2.0);
  Element& consistent = addElement(d, "corotTruss", 2, 1, 2, 1.0, 1, "-cMass", 1, "-rho", 2.0, "-doRayleigh", 1);
  const Matrix Ml = lumped.massMatrix();
  const Matrix Mc = consistent.massMatrix();
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(Ml(k, k), 5.0);          // rho L / 2
    EXPECT_DOUBLE_EQ(Ml(3 + k, 3 + k), 5.0);
    EXPECT_DOUBLE_EQ(Mc(k, k), 10.0 / 3.0);   // rho L / 3
    EXPECT_DOUBLE_EQ(Mc(k, 3 + k), 10.0 / 6.0);
    EXPECT_DOUBLE_EQ(Mc(3 + k, k), 10.0 / 6.0);
  }
  EXPECT_DOUBLE_EQ(Ml.sum(), 30.0);
  EXPECT_DOUBLE_EQ(Mc.sum(), 30.0);
  EXPECT_EQ(Ml.block(6, 0, 3, 9).norm(), 0.0);  // rotations of node 2 carry no mass
  EXPECT_TRUE(dynamic_cast<Truss&>(consistent).doRayleigh());
  EXPECT_FALSE(dynamic_cast<Truss&>(lumped).doRayleigh());
}

TEST(Truss, ResponsesAndState) {
  Domain d;
  addNode(d, 1, 3, 0.0, 0.0, 0.0);
  addNode(d, 2, 3, 0.0, 0.0, 2.0);
  addUniaxialMaterial(d, "Elastic", 1, 100.0);
  Element& e = addElement(d, "truss", 1, 1, 2, 0.5, 1);
  d.node(2, "test").setTrialDisp(Vector3(0.3, 0.0, 0.02));
  e.update();
  EXPECT_DOUBLE_EQ(e.setResponse({"axialForce"}).value()(0), 0.5 * 100.0 * 0.01);
  EXPECT_DOUBLE_EQ(e.setResponse({"basicDeformation"}).value()(0), 0.02);
  EXPECT_DOUBLE_EQ(e.setResponse({"deformations"}).value()(0), 0.02);
  Response f = e.setResponse({"globalForce"});
  ASSERT_EQ(f.size(), 6u);
  EXPECT_DOUBLE_EQ(f.value()(5), 0.5);
  EXPECT_DOUBLE_EQ(f.value()(2), -0.5);
  EXPECT_DOUBLE_EQ(e.setResponse({"material", "stress"}).value()(0), 1.0);
  EXPECT_DOUBLE_EQ(e.setResponse({"material", "1", "strain"}).value()(0), 0.01);
  EXPECT_FALSE(e.setResponse({"material", "2", "strain"}));
  EXPECT_FALSE(e.setResponse({"nonsense"}));
  e.commitState();
  d.node(2, "test").setTrialDisp(Vector3(0.0, 0.0, 0.1));
  e.update();
  e.revertToLastCommit();
  EXPECT_DOUBLE_EQ(dynamic_cast<Truss&>(e).axialForce(), 0.5);
  EXPECT_TRUE(e.setParameter({"A"}, 1.0));
  EXPECT_DOUBLE_EQ(dynamic_cast<Truss&>(e).axialForce(), 1.0);
}

TEST(Truss, InputErrorsAreClear) {
  Domain d;
  addNode(d, 1, 3, 0.0, 0.0, 0.0);
  addNode(d, 2, 2, 1.0, 0.0, 0.0);
  addNode(d, 3, 3, 0.0, 0.0, 0.0);
  addNode(d, 4, 3, 0.0, 1.0, 0.0);
  addUniaxialMaterial(d, "Elastic", 1, 100.0);
  const std::string ndf = errorOf([&] { addElement(d, "truss", 5, 1, 2, 1.0, 1); });
  EXPECT_NE(ndf.find("element truss 5: node 2 has 2 dofs"), std::string::npos) << ndf;
  const std::string zero = errorOf([&] { addElement(d, "corotTruss", 6, 1, 3, 1.0, 1); });
  EXPECT_NE(zero.find("element corotTruss 6: nodes 1 and 3 coincide"), std::string::npos) << zero;
  const std::string mat = errorOf([&] { addElement(d, "truss", 7, 1, 4, 1.0, 9); });
  EXPECT_NE(mat.find("element truss 7: uniaxialMaterial 9 does not exist"), std::string::npos) << mat;
  const std::string opt = errorOf([&] { addElement(d, "truss", 8, 1, 4, 1.0, 1, "-mass", 2.0); });
  EXPECT_NE(opt.find("'-rho', '-cMass' or '-doRayleigh'"), std::string::npos) << opt;
  const std::string area = errorOf([&] { addElement(d, "truss", 9, 1, 4, 0.0, 1); });
  EXPECT_NE(area.find("A must be positive"), std::string::npos) << area;
  EXPECT_EQ(d.elements().size(), 0u);
}

TEST(Truss, ViscousDampingTangentMatchesVelocityDifferences) {
  // A Viscous bar (C |rate|^0.5 sgn(rate)): d force / d nodal velocity by
  // central differences of the velocity (h = 1e-7, O(h^2) truncation) against
  // the damping tangent, for the truss and, turned and stretched, the
  // corotTruss (whose strain rate is along the current axis). Tolerance 1e-6 relative.
  for (const char* type : {"truss", "corotTruss"}) {
    Domain d;
    addNode(d, 1, 3, 0.0, 0.0, 0.0);
    addNode(d, 2, 3, 2.0, 1.0, 0.5);
    addUniaxialMaterial(d, "Viscous", 1, 40.0, 0.5);
    Element& e = addElement(d, type, 1, 1, 2, 0.3, 1);
    d.node(2, "test").setTrialDisp(Vector3(0.2, -0.3, 0.1));
    const Vector v0 = Vector3(0.4, 0.1, -0.2);
    d.node(2, "test").setTrialVel(v0);
    e.update();
    ASSERT_TRUE(e.hasDampingTangent()) << type;
    const Matrix C = e.dampingTangent();
    const double h = 1e-7;
    Matrix fd = Matrix::Zero(6, 6);
    for (int k = 0; k < 3; ++k) {
      Vector v = v0;
      v[k] += h;
      d.node(2, "test").setTrialVel(v);
      e.update();
      const Vector plus = e.resistingForce();
      v[k] -= 2 * h;
      d.node(2, "test").setTrialVel(v);
      e.update();
      const Vector minus = e.resistingForce();
      fd.col(3 + k) = (plus - minus) / (2 * h);
    }
    EXPECT_LE((C.rightCols(3) - fd.rightCols(3)).cwiseAbs().maxCoeff(), 1e-6 * C.cwiseAbs().maxCoeff()) << type;
    // The tangent taken before is untouched by forming the damping tangent.
    d.node(2, "test").setTrialVel(v0);
    e.update();
    const Matrix K = e.tangentStiff();
    e.dampingTangent();
    EXPECT_EQ((Matrix(e.tangentStiff()) - K).cwiseAbs().maxCoeff(), 0.0) << type;
  }
}
