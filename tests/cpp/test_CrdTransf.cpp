// Linear and PDelta geometric transformations: local axes, basic
// deformations, contragredience of the force map, joint offsets, the P-Delta
// terms, and the errors of geomTransf.
#include <gtest/gtest.h>

#include "BeamTestModel.h"
#include "core/OpenSeesError.h"
#include "elements/transforms/LinearCrdTransf.h"

using namespace beamtest;
using beamsolid::CrdTransf;
using beamsolid::OpenSeesError;
using Vector6 = CrdTransf::Vector6;
using Vector12 = CrdTransf::Vector12;
using Matrix6 = CrdTransf::Matrix6;
using Matrix12 = CrdTransf::Matrix12;

namespace {

// A clone of geomTransf `tag` bound to nodes i and j, as an element holds it.
std::unique_ptr<CrdTransf> bind(Domain& d, int tag, int i, int j) {
  auto t = d.geomTransfs.get(tag, "test").clone();
  t->initialize(d.node(i, "test"), d.node(j, "test"));
  return t;
}

void setDisp(Node& n, const Vector3& u, const Vector3& theta) { n.setTrialDisp(stack(u, theta)); }

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const OpenSeesError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(CrdTransf, LinearAndPDeltaAreRegistered) {
  EXPECT_TRUE(Registry::global().geomTransfs.has("Linear"));
  EXPECT_TRUE(Registry::global().geomTransfs.has("PDelta"));
}

TEST(CrdTransf, LocalAxesOfAHorizontalBeamAndAColumn) {
  Domain d;
  addNode(d, 1, {0, 0, 0});
  addNode(d, 2, {4, 0, 0});
  addNode(d, 3, {0, 0, 3});
  addTransf(d, "Linear", {1LL, 0.0, 0.0, 1.0});
  addTransf(d, "Linear", {2LL, 1.0, 0.0, 0.0});
  // Beam along X with vecxz = Z: local axes are the global ones.
  const Matrix3 beam = bind(d, 1, 1, 2)->localAxes();
  EXPECT_LT((beam - Matrix3::Identity()).norm(), 1e-15);
  // Column along Z with vecxz = X: y = X x Z = -Y, z = x x y = X.
  const Matrix3 column = bind(d, 2, 1, 3)->localAxes();
  Matrix3 expected;
  expected << 0, 0, 1,  //
      0, -1, 0,         //
      1, 0, 0;
  EXPECT_LT((column - expected).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(bind(d, 2, 1, 3)->initialLength(), 3.0);
}

TEST(CrdTransf, SkewLocalAxesFollowTheVecxzConvention) {
  Domain d;
  addNode(d, 1, {0.3, -1.2, 0.7});
  addNode(d, 2, {2.1, 0.4, 3.3});
  const Vector3 vecxz(0.4, -0.9, 0.2);
  addTransf(d, "PDelta", {5LL, vecxz.x(), vecxz.y(), vecxz.z()});
  auto t = bind(d, 5, 1, 2);
  const Matrix3 r = t->localAxes();
  const Vector3 x = r.row(0), y = r.row(1), z = r.row(2);
  const double tol = 1e-14;
  EXPECT_LT((r * r.transpose() - Matrix3::Identity()).norm(), tol);
  EXPECT_NEAR(r.determinant(), 1.0, tol);
  EXPECT_LT((x - unit(1.8, 1.6, 2.6)).norm(), tol);
  EXPECT_LT((y - vecxz.cross(x).normalized()).norm(), tol);  // y = vecxz x x
  EXPECT_LT((y - z.cross(x)).norm(), tol);                   // y = z x x
  EXPECT_NEAR(z.dot(x.cross(vecxz)), 0.0, tol);              // z in the x-vecxz plane
  EXPECT_GT(z.dot(vecxz), 0.0);                              // on vecxz's side
  EXPECT_TRUE(t->vecxz() == vecxz);
}

TEST(CrdTransf, RigidBodyMotionLeavesNoBasicDeformation) {
  for (const char* type : {"Linear", "PDelta"}) {
    Domain d;
    Node& a = addNode(d, 1, {0.3, -1.2, 0.7});
    Node& b = addNode(d, 2, {2.1, 0.4, 3.3});
    addTransf(d, type, {1LL, 0.4, -0.9, 0.2, "-jntOffset", 0.1, 0.2, -0.1, -0.3, 0.05, 0.2});
    auto t = bind(d, 1, 1, 2);
    // Infinitesimal rigid motion u(x) = c + w x x, rotation w.
    const Vector3 c(0.01, -0.02, 0.03), w(0.002, 0.003, -0.001);
    setDisp(a, c + w.cross(a.crd()), w);
    setDisp(b, c + w.cross(b.crd()), w);
    t->update();
    EXPECT_LT(t->basicTrialDisp().norm(), 1e-16) << type;
  }
}

TEST(CrdTransf, BasicDeformationsOfSingleModesWithJointOffsets) {
  Domain d;
  Node& a = addNode(d, 1, {0.0, 0.0, 0.0});
  Node& b = addNode(d, 2, {3.0, 1.0, -2.0});
  const Vector3 offI(0.2, -0.1, 0.3), offJ(-0.25, 0.1, 0.05);
  addTransf(d, "Linear", {1LL, 0.0, 0.0, 1.0, "-jntOffset", offI.x(), offI.y(), offI.z(), offJ.x(), offJ.y(),
                          offJ.z()});
  auto t = bind(d, 1, 1, 2);
  const double L = ((b.crd() + offJ) - (a.crd() + offI)).norm();
  EXPECT_NEAR(t->initialLength(), L, 1e-15);
  const Matrix3 r = t->localAxes();
  const Vector3 x = r.row(0), y = r.row(1), z = r.row(2);
  const double delta = 1e-3;
  auto basicOf = [&](const Vector3& uI, const Vector3& thI, const Vector3& uJ, const Vector3& thJ) {
    setDisp(a, uI, thI);
    setDisp(b, uJ, thJ);
    t->update();
    return Vector6(t->basicTrialDisp());
  };
  const Vector3 zero = Vector3::Zero();
  Vector6 expected;
  // Stretch along x.
  expected << delta, 0, 0, 0, 0, 0;
  EXPECT_LT((basicOf(zero, zero, delta * x, zero) - expected).norm(), 1e-15);
  // End J moved along y: chord rotates by +delta/L about z.
  expected << 0, -delta / L, -delta / L, 0, 0, 0;
  EXPECT_LT((basicOf(zero, zero, delta * y, zero) - expected).norm(), 1e-15);
  // End J moved along z: chord rotates by -delta/L about y.
  expected << 0, 0, 0, delta / L, delta / L, 0;
  EXPECT_LT((basicOf(zero, zero, delta * z, zero) - expected).norm(), 1e-15);
  // Twist at J; the rigid arm moves end J by theta x offJ.
  const Vector3 armJ = (delta * x).cross(offJ);
  expected << armJ.dot(x), -armJ.dot(y) / L, -armJ.dot(y) / L, armJ.dot(z) / L, armJ.dot(z) / L, delta;
  EXPECT_LT((basicOf(zero, zero, zero, delta * x) - expected).norm(), 1e-15);
  // Rotation of node I about local z: the rigid arm moves end I by theta x offI.
  const Vector3 thI = delta * z;
  const Vector3 armI = thI.cross(offI);
  const double dv = -armI.dot(y), du = -armI.dot(x);  // relative end motion J - I
  expected << du, delta - dv / L, -dv / L, -armI.dot(z) / L, -armI.dot(z) / L, 0;
  EXPECT_LT((basicOf(zero, thI, zero, zero) - expected).norm(), 1e-15);
}

TEST(CrdTransf, GlobalForceIsTheTransposeOfTheDeformationMap) {
  // Virtual work: u . (B^T q) = (B u) . q for any u and q, offsets included.
  for (const char* type : {"Linear", "PDelta"}) {
    Domain d;
    Node& a = addNode(d, 1, {0.3, -1.2, 0.7});
    Node& b = addNode(d, 2, {2.1, 0.4, 3.3});
    addTransf(d, type, {1LL, 0.4, -0.9, 0.2, "-jntOffset", 0.1, 0.2, -0.1, -0.3, 0.05, 0.2});
    auto t = bind(d, 1, 1, 2);
    std::srand(7);
    const Vector12 u = 1e-3 * Vector12::Random();
    a.setTrialDisp(Vector(u.head<6>()));
    b.setTrialDisp(Vector(u.tail<6>()));
    t->update();
    Vector6 q = Vector6::Random();
    q[0] = 0.0;  // no axial force: the P-Delta term adds work of its own
    const Vector12 f = t->globalResistingForce(q, Vector12::Zero());
    EXPECT_NEAR(u.dot(f), t->basicTrialDisp().dot(q), 1e-14 * q.norm() * u.norm()) << type;
    // The stiffness is B^T kb B: its action on u is the force of q = kb B u.
    Matrix6 kb = Matrix6::Random();
    kb = kb * kb.transpose();
    kb.row(0).setZero();  // again no axial force, for the same reason
    kb.col(0).setZero();
    const Vector12 ku = t->globalStiffMatrix(kb, q) * u;
    const Vector12 fu = t->globalResistingForce(kb * t->basicTrialDisp(), Vector12::Zero());
    EXPECT_LT((ku - fu).norm(), 1e-12 * fu.norm()) << type;
  }
}

TEST(CrdTransf, FixedEndForcesAreRotatedToGlobal) {
  Domain d;
  addNode(d, 1, {0.3, -1.2, 0.7});
  addNode(d, 2, {2.1, 0.4, 3.3});
  addTransf(d, "Linear", {1LL, 0.4, -0.9, 0.2});
  auto t = bind(d, 1, 1, 2);
  const Matrix3 r = t->localAxes();
  Vector12 p0 = Vector12::Zero();
  p0[1] = 2.0;   // Vy at I
  p0[11] = 3.0;  // Mz at J
  const Vector12 f = t->globalResistingForce(Vector6::Zero(), p0);
  EXPECT_LT((f.segment<3>(0) - 2.0 * Vector3(r.row(1))).norm(), 1e-15);
  EXPECT_LT((f.segment<3>(9) - 3.0 * Vector3(r.row(2))).norm(), 1e-15);
  EXPECT_LT(f.segment<6>(3).norm(), 1e-15);
  EXPECT_TRUE(t->localResistingForce(Vector6::Zero(), p0) == p0);
}

TEST(CrdTransf, PDeltaAddsChordShearAndGeometricStiffness) {
  Domain d;
  addNode(d, 1, {0.3, -1.2, 0.7});
  Node& b = addNode(d, 2, {2.1, 0.4, 3.3});
  addTransf(d, "Linear", {1LL, 0.4, -0.9, 0.2});
  addTransf(d, "PDelta", {2LL, 0.4, -0.9, 0.2});
  auto linear = bind(d, 1, 1, 2);
  auto pdelta = bind(d, 2, 1, 2);
  const double L = pdelta->initialLength();
  const Matrix3 r = pdelta->localAxes();
  const Vector3 y = r.row(1), z = r.row(2);
  // Move end J by (dv, dw) in the local y and z directions.
  const double dv = 2e-3, dw = -1e-3, N = -50.0;
  b.setTrialDisp(stack(dv * y + dw * z, Vector3::Zero()));
  linear->update();
  pdelta->update();
  Vector6 q = Vector6::Zero();
  q[0] = N;
  Vector12 expected = Vector12::Zero();
  expected[0] = -N;
  expected[6] = N;
  expected[1] = -N * dv / L;
  expected[7] = N * dv / L;
  expected[2] = -N * dw / L;
  expected[8] = N * dw / L;
  EXPECT_LT((pdelta->localResistingForce(q, Vector12::Zero()) - expected).norm(), 1e-13 * std::abs(N));
  // Geometric stiffness N/L on the relative transverse translation.
  Matrix6 kb = Matrix6::Identity();
  const Matrix12 kg = pdelta->globalStiffMatrix(kb, q) - linear->globalStiffMatrix(kb, q);
  Vector12 u = Vector12::Zero();
  u.segment<3>(6) = y;
  const Vector12 ku = kg * u;
  EXPECT_LT((ku.segment<3>(6) - N / L * y).norm(), 1e-12 * std::abs(N));
  EXPECT_LT((ku.segment<3>(0) + N / L * y).norm(), 1e-12 * std::abs(N));
  EXPECT_LT((ku.segment<3>(3).norm() + ku.segment<3>(9).norm()), 1e-12 * std::abs(N));
  // Axial and rotational dofs feel no geometric stiffness.
  u.setZero();
  u.segment<3>(6) = Vector3(r.row(0));
  EXPECT_LT((kg * u).norm(), 1e-12 * std::abs(N));
  EXPECT_LT((pdelta->initialGlobalStiffMatrix(kb) - linear->initialGlobalStiffMatrix(kb)).norm(), 1e-15);
}

TEST(CrdTransf, CloneKeepsTheDefinition) {
  Domain d;
  auto& proto = addTransf(d, "PDelta", {4LL, 0.0, 1.0, 0.0, "-jntOffset", 1.0, 2.0, 3.0, 4.0, 5.0, 6.0});
  auto copy = proto.clone();
  EXPECT_EQ(copy->className(), "PDelta");
  EXPECT_EQ(copy->tag(), 4);
  EXPECT_TRUE(copy->vecxz() == Vector3(0.0, 1.0, 0.0));
  auto* offsets = dynamic_cast<beamsolid::LinearCrdTransf*>(copy.get());
  ASSERT_NE(offsets, nullptr);
  EXPECT_TRUE(offsets->jointOffsetI() == Vector3(1.0, 2.0, 3.0));
  EXPECT_TRUE(offsets->jointOffsetJ() == Vector3(4.0, 5.0, 6.0));
}

TEST(CrdTransf, CommandErrorsNameTheArgument) {
  Domain d;
  auto build = [&](Args args) { return messageOf([&] { addTransf(d, "Linear", std::move(args)); }); };
  EXPECT_EQ(build({3LL}),
            "geomTransf Linear 3: argument 2 (vecxzX): expected a number (3D beams need vecxz = vecxzX, vecxzY, "
            "vecxzZ after the tag), but the command has only 1 argument(s)");
  EXPECT_NE(build({3LL, 0.0, std::string("up"), 1.0}).find("argument 3 (vecxzY): expected a number"),
            std::string::npos);
  EXPECT_NE(build({3LL, 0.0, 0.0, 0.0}).find("geomTransf Linear 3: vecxz is the zero vector"), std::string::npos);
  EXPECT_NE(build({3LL, 0.0, 0.0, 1.0, "-jntOffset", 1.0, 2.0, 3.0}).find("-jntOffset needs 6 numbers"),
            std::string::npos);
  EXPECT_NE(build({3LL, 0.0, 0.0, 1.0, "-offset"}).find("unknown option '-offset'"), std::string::npos);
  EXPECT_NE(build({3LL, 0.0, 0.0, 1.0, 5.0}).find("unexpected extra argument 5"), std::string::npos);
  EXPECT_NE(build({std::string("a")}).find("(transfTag): expected an integer"), std::string::npos);
}

TEST(CrdTransf, ParallelVecxzAndZeroLengthFailAtTheElement) {
  Domain d;
  addNode(d, 1, {0, 0, 0});
  addNode(d, 2, {0, 0, 3});
  addNode(d, 3, {0, 0, 0});
  addNode(d, 4, {1, 0, 0});
  addTransf(d, "Linear", {1LL, 0.0, 0.0, 2.0});
  addTransf(d, "PDelta", {2LL, 0.0, 1.0, 0.0, "-jntOffset", 0.5, 0.0, 0.0, -0.5, 0.0, 0.0});
  auto beam = [&](int tag, int i, int j, int transf) {
    return messageOf([&] {
      addElement(d, "elasticBeamColumn", {(long long)tag, (long long)i, (long long)j, 1.0, 1.0, 1.0, 1.0, 1.0,
                                          1.0, (long long)transf});
    });
  };
  EXPECT_EQ(beam(5, 1, 2, 1),
            "element elasticBeamColumn 5: geomTransf Linear 1: vecxz (0, 0, 2) is parallel to the element axis "
            "(0, 0, 1) from node 1 to node 2; choose a vecxz that is not parallel to the element");
  EXPECT_EQ(beam(6, 1, 3, 1),
            "element elasticBeamColumn 6: geomTransf Linear 1: element has zero length: the ends at node 1 "
            "(0, 0, 0) and node 3 (0, 0, 0) coincide");
  EXPECT_NE(beam(7, 1, 4, 2).find("coincide (after joint offsets)"), std::string::npos);
  EXPECT_EQ(d.elements().size(), 0u);
  EXPECT_NE(beam(8, 1, 2, 9).find("element elasticBeamColumn 8: geomTransf 9 does not exist"), std::string::npos);
}

TEST(CrdTransf, IncrementsSinceCommitAndSincePreviousUpdate) {
  Domain d;
  Node& a = addNode(d, 1, {0.3, -1.2, 0.7});
  Node& b = addNode(d, 2, {2.1, 0.4, 3.3});
  addTransf(d, "Linear", {1LL, 0.4, -0.9, 0.2, "-jntOffset", 0.1, 0.2, -0.1, -0.3, 0.05, 0.2});
  auto t = bind(d, 1, 1, 2);
  std::srand(13);
  auto basicAt = [&](const Vector12& u) {
    a.setTrialDisp(Vector(u.head<6>()));
    b.setTrialDisp(Vector(u.tail<6>()));
    t->update();
    return Vector6(t->basicTrialDisp());
  };
  const Vector12 u1 = 1e-3 * Vector12::Random(), u2 = 1e-3 * Vector12::Random(), u3 = 1e-3 * Vector12::Random();
  const Vector6 v1 = basicAt(u1);
  a.commitState();
  b.commitState();
  t->commitState();
  const Vector6 v2 = basicAt(u2);
  EXPECT_LT((t->basicIncrDisp() - (v2 - v1)).norm(), 1e-15);
  EXPECT_LT((t->basicIncrDeltaDisp() - (v2 - v1)).norm(), 1e-15);
  const Vector6 v3 = basicAt(u3);
  EXPECT_LT((t->basicIncrDisp() - (v3 - v1)).norm(), 1e-15);
  EXPECT_LT((t->basicIncrDeltaDisp() - (v3 - v2)).norm(), 1e-15);
  // Small displacements: the deformed length is the initial one.
  EXPECT_EQ(t->deformedLength(), t->initialLength());
}
