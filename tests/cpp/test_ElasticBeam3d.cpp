// elasticBeamColumn (3D): tangent against finite differences, closed-form
// cantilevers (tip loads, element loads, joint offsets), fixed-end forces,
// P-Delta against beam-column theory, responses, mass, and command errors.
// Models are built by hand and solved with a dense Newton loop
// (BeamTestModel.h).
#include <gtest/gtest.h>

#include <sstream>

#include "BeamTestModel.h"
#include "core/OpenSeesError.h"
#include "elements/ElasticBeam3d.h"
#include "support/ErrorOf.h"

using namespace beamtest;
using beamsolid::ElasticBeam3d;
using beamsolid::ElementLoad;
using beamsolid::OpenSeesError;
using Vector6 = ElasticBeam3d::Vector6;
using Vector12 = ElasticBeam3d::Vector12;
using Matrix12 = ElasticBeam3d::Matrix12;

namespace {

// Section and material: deliberately different Iy and Iz.
constexpr double kA = 0.05, kE = 2.0e5, kG = 8.0e4, kJ = 3.0e-4, kIy = 2.0e-4, kIz = 5.0e-4;

Args beamArgs(int tag, int i, int j, int transf, Args extra = {}) {
  Args a{(long long)tag, (long long)i, (long long)j, kA, kE, kG, kJ, kIy, kIz, (long long)transf};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

ElasticBeam3d& addBeam(Domain& d, int tag, int i, int j, int transf, Args extra = {}) {
  return dynamic_cast<ElasticBeam3d&>(addElement(d, "elasticBeamColumn", beamArgs(tag, i, j, transf, extra)));
}

Vector12 copyOf(beamsolid::VectorView v) { return Vector12(v); }

// Central differences of the element's resisting force over the 12 end dofs.
Matrix12 finiteDifferenceStiffness(Element& e, double h) {
  Matrix12 k;
  for (int col = 0; col < 12; ++col) {
    Node& n = *e.nodes()[col / 6];
    const int dof = col % 6;
    const double u0 = n.trialDisp()(dof);
    n.setTrialDisp(dof, u0 + h);
    e.update();
    const Vector12 plus = copyOf(e.resistingForce());
    n.setTrialDisp(dof, u0 - h);
    e.update();
    const Vector12 minus = copyOf(e.resistingForce());
    n.setTrialDisp(dof, u0);
    e.update();
    k.col(col) = (plus - minus) / (2.0 * h);
  }
  return k;
}

double maxAbs(const Matrix12& m) { return m.cwiseAbs().maxCoeff(); }

// Cantilever tip response (local) to tip forces F and moments M (local).
Vector6 cantileverTip(double L, const Vector3& F, const Vector3& M) {
  Vector6 u;
  u[0] = F.x() * L / (kE * kA);
  u[1] = F.y() * L * L * L / (3 * kE * kIz) + M.z() * L * L / (2 * kE * kIz);
  u[2] = F.z() * L * L * L / (3 * kE * kIy) - M.y() * L * L / (2 * kE * kIy);
  u[3] = M.x() * L / (kG * kJ);
  u[4] = -F.z() * L * L / (2 * kE * kIy) + M.y() * L / (kE * kIy);
  u[5] = F.y() * L * L / (2 * kE * kIz) + M.z() * L / (kE * kIz);
  return u;
}

Vector6 toGlobal(const Matrix3& axes, const Vector6& local) {
  return stack(axes.transpose() * local.head<3>(), axes.transpose() * local.tail<3>());
}

double relativeError(const Vector& a, const Vector& b) { return (a - b).norm() / b.norm(); }

// A skew single-element cantilever, node 1 clamped.
struct SkewCantilever {
  Domain domain;
  ElasticBeam3d* beam = nullptr;
  Matrix3 axes;
  double L = 0.0;
  explicit SkewCantilever(const char* transf = "Linear", Args offsets = {}) {
    addNode(domain, 1, {0.3, -1.2, 0.7});
    addNode(domain, 2, {2.1, 0.4, 3.3});
    Args t{1LL, 0.4, -0.9, 0.2};
    t.insert(t.end(), offsets.begin(), offsets.end());
    addTransf(domain, transf, t);
    beam = &addBeam(domain, 1, 1, 2, 1);
    axes = beam->transformation().localAxes();
    L = beam->length();
  }
  Vector nodeDisp(int tag) { return domain.node(tag, "test").trialDisp(); }
};

}  // namespace

TEST(ElasticBeam3d, IsRegistered) { EXPECT_TRUE(Registry::global().elements.has("elasticBeamColumn")); }

// Linear transform, skew axes, joint offsets, element loads present, an
// arbitrary state: the tangent is the exact derivative of the resisting
// force. Tolerance 1e-6 of the largest entry (central differences, h = 1e-6;
// the force is linear in u, so only round-off is measured).
TEST(ElasticBeam3d, TangentMatchesFiniteDifferencesLinear) {
  SkewCantilever m("Linear", {"-jntOffset", 0.1, 0.2, -0.1, -0.3, 0.05, 0.2});
  m.beam->addLoad({ElementLoad::Type::BeamUniform, {1.5, -2.0, 0.7}}, 1.0);
  m.beam->addLoad({ElementLoad::Type::BeamPoint, {3.0, 1.0, 0.3, -2.0}}, 1.0);
  std::srand(3);
  m.domain.node(1, "t").setTrialDisp(Vector(1e-2 * Vector6::Random()));
  m.domain.node(2, "t").setTrialDisp(Vector(1e-2 * Vector6::Random()));
  m.beam->update();
  const Matrix12 k = Matrix12(m.beam->tangentStiff());
  const Matrix12 fd = finiteDifferenceStiffness(*m.beam, 1e-6);
  EXPECT_LT(maxAbs(fd - k), 1e-6 * maxAbs(k));
  EXPECT_LT(maxAbs(k - k.transpose()), 1e-12 * maxAbs(k));
  EXPECT_LT(maxAbs(Matrix12(m.beam->initialStiff()) - k), 1e-12 * maxAbs(k));
}

// PDelta with an axial force (stretch plus an axial element load) at a state
// whose chord is not rotated (end rotations arbitrary): there the tangent is
// exact, geometric stiffness included. Tolerance 1e-6 of the largest entry.
TEST(ElasticBeam3d, TangentMatchesFiniteDifferencesPDeltaWithAxialForce) {
  SkewCantilever m("PDelta");
  m.beam->addLoad({ElementLoad::Type::BeamUniform, {0.0, 0.0, 40.0}}, 1.0);
  const Vector3 x = m.axes.row(0);
  const Vector3 shift(0.01, -0.02, 0.005);
  std::srand(5);
  m.domain.node(1, "t").setTrialDisp(stack(shift, 1e-2 * Vector3::Random()));
  m.domain.node(2, "t").setTrialDisp(stack(shift - 2e-3 * x, 1e-2 * Vector3::Random()));
  m.beam->update();
  const double N = m.beam->basicForce()[0];
  ASSERT_LT(N, -50.0);  // compression, mostly from the axial load (-wx L/2)
  const Matrix12 k = Matrix12(m.beam->tangentStiff());
  const Matrix12 fd = finiteDifferenceStiffness(*m.beam, 1e-6);
  EXPECT_LT(maxAbs(fd - k), 1e-6 * maxAbs(k));
  // The geometric part is really there: N/L compared with the tolerance.
  EXPECT_GT(maxAbs(k - Matrix12(m.beam->initialStiff())), 0.5 * std::abs(N) / m.L);
}

// At a general state the PDelta tangent (as OpenSees') leaves out only the
// rank-one term g dN/du, where g = d(force)/dN holds the chord-rotation
// shears per unit N and dN/du = EA/L (x_J - x_I). Built independently here.
TEST(ElasticBeam3d, PDeltaTangentOmitsOnlyTheAxialForceVariation) {
  SkewCantilever m("PDelta");
  std::srand(11);
  const Vector6 uI = 1e-2 * Vector6::Random(), uJ = 1e-2 * Vector6::Random();
  m.domain.node(1, "t").setTrialDisp(Vector(uI));
  m.domain.node(2, "t").setTrialDisp(Vector(uJ));
  m.beam->update();
  const Vector3 x = m.axes.row(0), y = m.axes.row(1), z = m.axes.row(2);
  const Vector3 chord = uJ.head<3>() - uI.head<3>();
  const Vector3 shear = (chord.dot(y) * y + chord.dot(z) * z) / m.L;
  Vector12 g = Vector12::Zero(), dN = Vector12::Zero();
  g.segment<3>(0) = -shear;
  g.segment<3>(6) = shear;
  dN.segment<3>(0) = -kE * kA / m.L * x;
  dN.segment<3>(6) = kE * kA / m.L * x;
  const Matrix12 omitted = g * dN.transpose();
  const Matrix12 k = Matrix12(m.beam->tangentStiff());
  const Matrix12 fd = finiteDifferenceStiffness(*m.beam, 1e-6);
  EXPECT_LT(maxAbs(fd - (k + omitted)), 1e-6 * maxAbs(k));
  EXPECT_GT(maxAbs(omitted), 1e-4 * maxAbs(k));  // the check is not vacuous
}

// One element, clamped at node 1, all six tip actions at once in local
// directions: axial PL/EA, deflections PL^3/3EI in both planes (Iy != Iz),
// tip rotations, torsion TL/GJ. Tolerance 1e-10 relative.
TEST(ElasticBeam3d, SkewCantileverMatchesClosedForm) {
  SkewCantilever m;
  DenseModel model(m.domain, DenseModel::clamp({1}));
  const Vector3 F(30.0, -4.0, 2.5), M(1.2, -0.8, 2.0);  // local
  Vector f = Vector::Zero(model.size());
  model.addLoad(f, 2, toGlobal(m.axes, stack(F, M)));
  ASSERT_GE(model.solve(f), 0);
  const Vector6 expected = toGlobal(m.axes, cantileverTip(m.L, F, M));
  EXPECT_LT(relativeError(m.nodeDisp(2), expected), 1e-10);
  // Each local component separately (the axial one is much smaller).
  const Vector6 tipLocal = cantileverTip(m.L, F, M);
  const Vector u = m.nodeDisp(2);
  const Vector3 uLocal = m.axes * u.head<3>(), thLocal = m.axes * u.tail<3>();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(uLocal[i], tipLocal[i], 1e-10 * std::abs(tipLocal[i])) << i;
    EXPECT_NEAR(thLocal[i], tipLocal[3 + i], 1e-10 * std::abs(tipLocal[3 + i])) << i;
  }
  // Reaction at the clamp balances the tip actions.
  const Vector6 fg = toGlobal(m.axes, stack(F, M));
  const Vector3 arm = m.domain.node(2, "t").crd() - m.domain.node(1, "t").crd();
  const Vector reaction = model.nodeForce(1);
  EXPECT_LT((reaction.head<3>() + fg.head<3>()).norm(), 1e-10 * F.norm());
  EXPECT_LT((reaction.tail<3>() + fg.tail<3>() + arm.cross(Vector3(fg.head<3>()))).norm(), 1e-10 * F.norm() * m.L);
}

// Uniform load {Wy, Wz, Wx} on a skew cantilever: tip wL^4/8EI in both planes,
// rotation wL^3/6EI, axial wx L^2/2EA; clamp reactions -wL and -(L^2/2) x X w.
// One element with exact fixed-end forces gives exact nodal values: 1e-10.
TEST(ElasticBeam3d, UniformLoadOnCantilever) {
  SkewCantilever m;
  const double wy = -3.0, wz = 1.5, wx = 2.0;
  m.beam->addLoad({ElementLoad::Type::BeamUniform, {wy, wz, wx}}, 1.0);
  DenseModel model(m.domain, DenseModel::clamp({1}));
  const double L = m.L;
  ASSERT_GE(model.solve(Vector::Zero(model.size()), 1e-12, 10, std::abs(wy) * L), 0);
  Vector6 tip;
  tip << wx * L * L / (2 * kE * kA), wy * std::pow(L, 4) / (8 * kE * kIz), wz * std::pow(L, 4) / (8 * kE * kIy), 0.0,
      -wz * std::pow(L, 3) / (6 * kE * kIy), wy * std::pow(L, 3) / (6 * kE * kIz);
  EXPECT_LT(relativeError(m.nodeDisp(2), toGlobal(m.axes, tip)), 1e-10);
  const Vector3 x = m.axes.row(0), y = m.axes.row(1), z = m.axes.row(2);
  const Vector3 w = wx * x + wy * y + wz * z;
  const Vector reaction = model.nodeForce(1);
  EXPECT_LT((reaction.head<3>() + w * L).norm(), 1e-10 * w.norm() * L);
  EXPECT_LT((reaction.tail<3>() + 0.5 * L * L * x.cross(w)).norm(), 1e-10 * w.norm() * L * L);
}

// Point load {Py, Pz, xL, Px} on the cantilever: tip P a^2 (3L - a) / 6EI,
// rotation P a^2 / 2EI, axial Px a / EA. Exact with one element: 1e-10.
TEST(ElasticBeam3d, PointLoadOnCantilever) {
  SkewCantilever m;
  const double py = 5.0, pz = -2.0, xL = 0.3, px = -7.0;
  m.beam->addLoad({ElementLoad::Type::BeamPoint, {py, pz, xL, px}}, 2.0);  // factor 2
  DenseModel model(m.domain, DenseModel::clamp({1}));
  const double L = m.L, a = xL * L;
  ASSERT_GE(model.solve(Vector::Zero(model.size()), 1e-12, 10, std::abs(py)), 0);
  Vector6 tip;
  tip << 2 * px * a / (kE * kA), 2 * py * a * a * (3 * L - a) / (6 * kE * kIz),
      2 * pz * a * a * (3 * L - a) / (6 * kE * kIy), 0.0, -2 * pz * a * a / (2 * kE * kIy),
      2 * py * a * a / (2 * kE * kIz);
  EXPECT_LT(relativeError(m.nodeDisp(2), toGlobal(m.axes, tip)), 1e-10);
}

// Both ends clamped, nothing moves: the local end forces are the textbook
// fixed-end reactions. Uniform: wL/2, wL^2/12; point load at a (b = L - a):
// P b^2 (3a + b)/L^3, P a b^2/L^2 at I and P a^2 (a + 3b)/L^3, P a^2 b/L^2 at J;
// axial share b/L at I, a/L at J. Tolerance 1e-12 relative.
TEST(ElasticBeam3d, FixedEndForcesOfElementLoads) {
  SkewCantilever m;
  const double L = m.L;
  auto localForce = m.beam->setResponse({"localForce"});
  ASSERT_TRUE(localForce);
  const double wy = -3.0, wz = 1.5, wx = 2.0;
  m.beam->addLoad({ElementLoad::Type::BeamUniform, {wy, wz, wx}}, 1.0);
  m.beam->update();
  Vector12 expected;
  expected << -wx * L / 2, -wy * L / 2, -wz * L / 2, 0, wz * L * L / 12, -wy * L * L / 12,  //
      -wx * L / 2, -wy * L / 2, -wz * L / 2, 0, -wz * L * L / 12, wy * L * L / 12;
  EXPECT_LT(relativeError(localForce.value(), expected), 1e-12);

  m.beam->zeroLoad();
  EXPECT_LT(localForce.value().norm(), 1e-300);
  const double py = 5.0, pz = -2.0, xL = 0.3, px = -7.0, a = xL * L, b = L - a;
  m.beam->addLoad({ElementLoad::Type::BeamPoint, {py, pz, xL, px}}, 1.0);
  const double shearI = b * b * (3 * a + b) / (L * L * L), shearJ = a * a * (a + 3 * b) / (L * L * L);
  const double momentI = a * b * b / (L * L), momentJ = a * a * b / (L * L);
  expected << -px * b / L, -py * shearI, -pz * shearI, 0, pz * momentI, -py * momentI,  //
      -px * a / L, -py * shearJ, -pz * shearJ, 0, -pz * momentJ, py * momentJ;
  EXPECT_LT(relativeError(localForce.value(), expected), 1e-12);
  // Globally the resisting force is the local one rotated.
  const Vector12 global = copyOf(m.beam->resistingForce());
  for (int k = 0; k < 4; ++k)
    EXPECT_LT((m.axes * global.segment<3>(3 * k) - expected.segment<3>(3 * k)).norm(), 1e-12 * std::abs(py) * L);
}

// Rigid joint offsets: node 1 clamped, the flexible part runs from
// X1 + dI to X2 + dJ. Tip actions at node 2 reach the flexible end as F and
// M - dJ x F; node 2 then moves as u_e - theta x dJ. Tolerance 1e-10.
TEST(ElasticBeam3d, CantileverWithJointOffsets) {
  const Vector3 dI(0.1, 0.2, -0.1), dJ(-0.3, 0.05, 0.2);
  SkewCantilever m("Linear", {"-jntOffset", dI.x(), dI.y(), dI.z(), dJ.x(), dJ.y(), dJ.z()});
  const Vector3 X1 = m.domain.node(1, "t").crd(), X2 = m.domain.node(2, "t").crd();
  const Vector3 chord = (X2 + dJ) - (X1 + dI);
  const double L = chord.norm();
  const Vector3 x = chord / L;
  const Vector3 y = Vector3(0.4, -0.9, 0.2).cross(x).normalized(), z = x.cross(y);
  Matrix3 axes;
  axes << x.transpose(), y.transpose(), z.transpose();
  EXPECT_NEAR(m.L, L, 1e-14);

  const Vector3 F(3.0, -4.0, 2.5), M(1.2, -0.8, 2.0);  // global, at node 2
  DenseModel model(m.domain, DenseModel::clamp({1}));
  Vector f = Vector::Zero(model.size());
  model.addLoad(f, 2, stack(F, M));
  ASSERT_GE(model.solve(f), 0);
  const Vector3 Mend = M - dJ.cross(F);
  const Vector6 end = toGlobal(axes, cantileverTip(L, axes * F, axes * Mend));
  const Vector3 theta = end.tail<3>();
  const Vector6 expected = stack(end.head<3>() - theta.cross(dJ), theta);
  EXPECT_LT(relativeError(m.nodeDisp(2), expected), 1e-10);
}

namespace {

// Column along global Z on a clamped base, n PDelta elements, axial
// compression P and lateral loads Hx, Hy at the top; returns the top
// displacement after Newton iteration.
Vector pdeltaColumnTop(int n, double L, double P, double Hx, double Hy, int* iterations = nullptr) {
  Domain d;
  for (int i = 0; i <= n; ++i) addNode(d, i + 1, {0.0, 0.0, L * i / n});
  addTransf(d, "PDelta", {1LL, 1.0, 0.0, 0.0});  // local z = X (Iy), local y = -Y (Iz)
  for (int i = 1; i <= n; ++i) addBeam(d, i, i, i + 1, 1);
  DenseModel model(d, DenseModel::clamp({1}));
  Vector f = Vector::Zero(model.size());
  Vector load = Vector::Zero(6);
  load << Hx, Hy, -P, 0, 0, 0;
  model.addLoad(f, n + 1, load);
  // Round-off leaves an unbalance of 1e-11 to 2e-10 |f| with 20 to 40 short,
  // stiff elements; 1e-8 is far below what the deflection checks resolve.
  const int it = model.solve(f, 1e-8, 50);
  if (iterations) *iterations = it;
  return d.node(n + 1, "t").trialDisp();
}

// Beam-column theory: cantilever under compression P and tip shear H,
// k = sqrt(P / EI): top deflection H (tan kL - kL) / (P k).
double amplifiedDeflection(double H, double P, double EI, double L) {
  const double k = std::sqrt(P / EI);
  return H * (std::tan(k * L) - k * L) / (P * k);
}

}  // namespace

// P-Delta: PDelta elements carry the chord effect only, so they converge to
// the exact second-order deflection with refinement, at second order. Here
// P = 0.5 Pcr of the weak plane (amplification about 2). Measured relative
// errors (worse of the two planes): n = 5: 0.81%, 10: 0.20%, 20: 0.051%,
// 40: 0.013%. Asserted: below 0.5% with 10 elements, below 0.02% with 40,
// and each halving of the element size divides the error by 3.3 to 5.
TEST(ElasticBeam3d, PDeltaCantileverColumnConvergesToBeamColumnTheory) {
  const double L = 4.0;
  const double pcrWeak = M_PI * M_PI * kE * kIy / (4 * L * L);
  const double P = 0.5 * pcrWeak, Hx = 2.0, Hy = -3.0;
  // vecxz = X: lateral X bends about local y (Iy), lateral Y about local z (Iz).
  const double exactX = amplifiedDeflection(Hx, P, kE * kIy, L);
  const double exactY = amplifiedDeflection(Hy, P, kE * kIz, L);
  ASSERT_GT(exactX / (Hx * L * L * L / (3 * kE * kIy)), 1.9);  // second-order effect is large
  double previous = 0.0;
  for (int n : {5, 10, 20, 40}) {
    int iterations = -1;
    const Vector top = pdeltaColumnTop(n, L, P, Hx, Hy, &iterations);
    ASSERT_GE(iterations, 1) << n;
    ASSERT_LE(iterations, 10) << n;
    const double error = std::max(std::abs(top[0] / exactX - 1), std::abs(top[1] / exactY - 1));
    if (std::getenv("BEAMTEST_TRACE")) std::fprintf(stderr, "n %d error %.3e\n", n, error);
    if (n == 10) {
      EXPECT_LT(error, 0.005);
    }
    if (n == 40) {
      EXPECT_LT(error, 2e-4);
    }
    if (previous > 0.0) {
      EXPECT_LT(error, previous / 3.3) << n;
      EXPECT_GT(error, previous / 5.0) << n;
    }
    previous = error;
  }
}

// Without axial load the PDelta column is the linear cantilever: HL^3/3EI.
TEST(ElasticBeam3d, PDeltaWithoutAxialLoadIsLinear) {
  const double L = 4.0, H = 2.0;
  const Vector top = pdeltaColumnTop(4, L, 0.0, H, 0.0);
  EXPECT_NEAR(top[0], H * L * L * L / (3 * kE * kIy), 1e-10 * H * L * L * L / (3 * kE * kIy));
}

// localForce, basicForce, force and deformation of the loaded cantilever
// against statics and the basic flexibility. Tolerance 1e-10 relative.
TEST(ElasticBeam3d, ResponsesOfCantileverEqualStatics) {
  SkewCantilever m;
  DenseModel model(m.domain, DenseModel::clamp({1}));
  const Vector3 F(30.0, -4.0, 2.5), M(1.2, -0.8, 2.0);  // local tip actions
  Vector f = Vector::Zero(model.size());
  model.addLoad(f, 2, toGlobal(m.axes, stack(F, M)));
  ASSERT_GE(model.solve(f), 0);
  const double L = m.L;

  const auto local = m.beam->setResponse({"localForce"});
  ASSERT_EQ(local.size(), 12u);
  EXPECT_EQ(local.componentNames[0], "N_1");
  EXPECT_EQ(local.componentNames[1], "Vy_1");
  EXPECT_EQ(local.componentNames[5], "Mz_1");
  EXPECT_EQ(local.componentNames[11], "Mz_2");
  // End J carries the tip actions; end I balances them about I.
  const Vector3 momentI = -M - Vector3(L, 0, 0).cross(F);
  Vector12 expected;
  expected << -F, momentI, F, M;
  EXPECT_LT(relativeError(local.value(), expected), 1e-10);

  const auto basic = m.beam->setResponse({"basicForce"});
  ASSERT_EQ(basic.size(), 6u);
  Vector6 q;
  q << F.x(), momentI.z(), M.z(), momentI.y(), M.y(), M.x();
  EXPECT_LT(relativeError(basic.value(), q), 1e-10);

  // Basic deformations from the basic flexibility: L/(6EI) [2 -1; -1 2].
  const auto deformation = m.beam->setResponse({"deformation"});
  ASSERT_EQ(deformation.size(), 6u);
  Vector6 v;
  v << q[0] * L / (kE * kA), L / (6 * kE * kIz) * (2 * q[1] - q[2]), L / (6 * kE * kIz) * (2 * q[2] - q[1]),
      L / (6 * kE * kIy) * (2 * q[3] - q[4]), L / (6 * kE * kIy) * (2 * q[4] - q[3]), q[5] * L / (kG * kJ);
  EXPECT_LT(relativeError(deformation.value(), v), 1e-10);
  EXPECT_TRUE(m.beam->setResponse({"basicDeformation"}).value() == deformation.value());

  const auto global = m.beam->setResponse({"globalForce"});
  ASSERT_EQ(global.size(), 12u);
  EXPECT_EQ(global.componentNames[0], "Px_1");
  EXPECT_EQ(global.componentNames[9], "Mx_2");
  Vector12 g;
  g << toGlobal(m.axes, expected.head<6>()), toGlobal(m.axes, expected.tail<6>());
  EXPECT_LT(relativeError(global.value(), g), 1e-10);
  EXPECT_TRUE(m.beam->setResponse({"force"}).value() == global.value());

  EXPECT_FALSE(m.beam->setResponse({"stresses"}));
  EXPECT_FALSE(m.beam->setResponse({}));
}

// Under P-Delta, 'localForce' is OpenSees': end shears (Mi + Mj)/L from the
// basic forces only, without the chord shear N*dv/L (checked against
// OpenSeesPy 3.7.1, tests/python/oracle_scripts/cantilever3d.py). The global
// 'force' includes it and balances the node. Tolerance 1e-10 relative.
TEST(ElasticBeam3d, PDeltaLocalForceLeavesTheChordShearOut) {
  // P well below the critical load (EI = 40: Pcr = pi^2 EI / 4L^2 = 6.2).
  const double L = 4.0, P = 2.0, H = 2.0;
  Domain d;
  addNode(d, 1, {0, 0, 0});
  addNode(d, 2, {0, 0, L});
  addTransf(d, "PDelta", {1LL, 1.0, 0.0, 0.0});
  auto& beam = addBeam(d, 1, 1, 2, 1);
  DenseModel model(d, DenseModel::clamp({1}));
  Vector f = Vector::Zero(model.size());
  model.addLoad(f, 2, stack(Vector3(H, 0, -P), Vector3::Zero()));
  ASSERT_GE(model.solve(f), 0);
  const Vector local = beam.setResponse({"localForce"}).value();
  const double sway = d.node(2, "t").trialDisp()[0];
  ASSERT_GT(sway, 0.0);
  // local x = Z, z = X: N_2 = -P; the base moment about local y (= -Y) is
  // H L + P sway, and the shear is that moment over L.
  EXPECT_NEAR(local[6], -P, 1e-10 * P);
  EXPECT_NEAR(local[4], H * L + P * sway, 1e-10 * H * L);
  EXPECT_NEAR(local[8], H + P * sway / L, 1e-10 * H);
  EXPECT_NEAR(local[2], -(H + P * sway / L), 1e-10 * H);
  // The global force adds the chord shear -P sway / L and balances H.
  const Vector global = beam.setResponse({"force"}).value();
  EXPECT_NEAR(global[6], H, 1e-10 * H);
  EXPECT_NEAR(global[8], -P, 1e-10 * P);
}

// Mass: lumped m L/2 per node on translations; consistent mass is exact for
// rigid motions: translation m L, rotation about the end perpendicular to
// the axis m L^3/3 w^2, torsion (m J/A) L w^2. Tolerance 1e-12 relative.
TEST(ElasticBeam3d, LumpedAndConsistentMass) {
  const double m = 7.5;
  for (bool consistent : {false, true}) {
    Domain d;
    addNode(d, 1, {0.3, -1.2, 0.7});
    addNode(d, 2, {2.1, 0.4, 3.3});
    addTransf(d, "Linear", {1LL, 0.4, -0.9, 0.2});
    Args extra{"-mass", m};
    if (consistent) extra.push_back("-cMass");
    auto& beam = addBeam(d, 1, 1, 2, 1, extra);
    const Matrix12 mass = Matrix12(beam.massMatrix());
    const double L = beam.length();
    const Matrix3 axes = beam.transformation().localAxes();
    EXPECT_LT(maxAbs(mass - mass.transpose()), 1e-14 * m * L);
    const Vector3 dir = unit(0.3, -0.5, 0.8);
    Vector12 u = Vector12::Zero();
    u.segment<3>(0) = dir;
    u.segment<3>(6) = dir;
    EXPECT_NEAR(u.dot(mass * u), m * L, 1e-12 * m * L) << consistent;
    if (!consistent) {
      Matrix12 lumped = Matrix12::Zero();
      for (int k : {0, 1, 2, 6, 7, 8}) lumped(k, k) = m * L / 2;
      EXPECT_LT(maxAbs(mass - lumped), 1e-14 * m * L);
      continue;
    }
    const double w = 0.01;
    const Vector3 omega = w * Vector3(axes.row(1));  // about local y through node 1
    u.setZero();
    u.segment<3>(3) = omega;
    u.segment<3>(6) = omega.cross(L * Vector3(axes.row(0)));
    u.segment<3>(9) = omega;
    EXPECT_NEAR(u.dot(mass * u), m * L * L * L / 3 * w * w, 1e-12 * m * L * L * L * w * w);
    u.setZero();
    u.segment<3>(3) = u.segment<3>(9) = w * Vector3(axes.row(0));
    EXPECT_NEAR(u.dot(mass * u), m * kJ / kA * L * w * w, 1e-12 * m * kJ / kA * L * w * w);
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Matrix12>(mass).eigenvalues().minCoeff(), -1e-12 * m * L);
  }
}

TEST(ElasticBeam3d, NoMassByDefault) {
  SkewCantilever m;
  EXPECT_EQ(maxAbs(Matrix12(m.beam->massMatrix())), 0.0);
}

TEST(ElasticBeam3d, PrintAndJSONDescribeTheElement) {
  SkewCantilever m;
  std::ostringstream text, json;
  m.beam->print(text);
  m.beam->printJSON(json);
  EXPECT_NE(text.str().find("ElasticBeam3d 1"), std::string::npos);
  EXPECT_NE(text.str().find("geomTransf Linear 1"), std::string::npos);
  EXPECT_NE(json.str().find("\"type\": \"ElasticBeam3d\""), std::string::npos);
  EXPECT_NE(json.str().find("\"nodes\": [1, 2]"), std::string::npos);
  EXPECT_NE(json.str().find("\"Iz\": 0.0005"), std::string::npos);
  EXPECT_NE(json.str().find("\"crdTransformation\": \"1\""), std::string::npos);
}

namespace {

using beamsolid::testsupport::errorOf;

}  // namespace

TEST(ElasticBeam3d, CommandAndSetupErrorsAreClear) {
  Domain d;
  addNode(d, 1, {0, 0, 0});
  addNode(d, 2, {1, 0, 0});
  addNode(d, 3, {2, 0, 0}, 3);
  addTransf(d, "Linear", {1LL, 0.0, 0.0, 1.0});
  auto build = [&](Args args) { return errorOf([&] { addElement(d, "elasticBeamColumn", std::move(args)); }); };
  EXPECT_EQ(build(beamArgs(1, 2, 3, 1)),
            "element elasticBeamColumn 1: node 3 has 3 dofs, the 3D elasticBeamColumn needs 6 (create its nodes "
            "after model('basic', '-ndm', 3, '-ndf', 6))");
  EXPECT_NE(build({2LL, 1LL, 2LL, 1.0, 1.0, 1.0, 1LL}).find("the 2D form (A, E, Iz, transfTag) needs a 2D model (-ndm 2)"),
            std::string::npos);
  EXPECT_NE(build({2LL, 1LL, 2LL, 5LL, 1LL}).find("section 5 does not exist"), std::string::npos);
  EXPECT_NE(build({2LL, 1LL, 2LL, 1.0, 1.0, 1.0}).find("expected A, E, G, J, Iy, Iz, transfTag (7 numbers)"),
            std::string::npos);
  EXPECT_EQ(build({2LL, 1LL, 2LL, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1LL}),
            "element elasticBeamColumn 2: argument 4 (A): expected a positive number, got 0");
  EXPECT_NE(build({2LL, 1LL, 2LL, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.5}).find("(transfTag): expected an integer"),
            std::string::npos);
  EXPECT_NE(build(beamArgs(2, 1, 2, 1, {"-mass", -1.0})).find("(massPerLength): expected a number >= 0"),
            std::string::npos);
  EXPECT_NE(build(beamArgs(2, 1, 2, 1, {"-lumped"})).find("unknown option '-lumped'"), std::string::npos);
  EXPECT_NE(build(beamArgs(2, 1, 2, 7)).find("geomTransf 7 does not exist"), std::string::npos);
  EXPECT_NE(build(beamArgs(2, 1, 9, 1)).find("element elasticBeamColumn 2: node 9 does not exist"),
            std::string::npos);
  EXPECT_EQ(d.elements().size(), 0u);

  auto& beam = addBeam(d, 2, 1, 2, 1);
  EXPECT_TRUE(beam.acceptsLoad(ElementLoad::Type::BeamUniform));
  EXPECT_TRUE(beam.acceptsLoad(ElementLoad::Type::BeamPoint));
  EXPECT_FALSE(beam.acceptsLoad(ElementLoad::Type::SelfWeight));
  EXPECT_NE(errorOf([&] { beam.addLoad({ElementLoad::Type::BeamPoint, {1.0, 0.0, 1.5}}, 1.0); })
                .find("element elasticBeamColumn 2: -beamPoint xL must lie in [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { beam.addLoad({ElementLoad::Type::BeamUniform, {1.0}}, 1.0); })
                .find("-beamUniform needs Wy, Wz and optionally Wx"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { beam.addLoad({ElementLoad::Type::SelfWeight, {0.0, 0.0, -9.81}}, 1.0); })
                .find("does not accept element load -selfWeight"),
            std::string::npos);
}
