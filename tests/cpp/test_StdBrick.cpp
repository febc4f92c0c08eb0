// stdBrick: finite-difference tangent, rigid-body modes, the patch test on a
// distorted mesh, oedometric compression against the closed form, a column
// under its own weight (base reaction = weight), lumped mass, responses,
// material stages and input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include "SolidsTestSupport.h"
#include "core/LoadPattern.h"
#include "core/OpenSeesError.h"
#include "elements/StdBrick.h"
#include "materials/nd/ElasticIsotropic3D.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

// A structured block of bricks with node tags 1 + i + (nx+1)(j + (ny+1) k),
// node coordinates from level vectors plus an optional perturbation.
struct BrickBlock {
  std::vector<double> xs, ys, zs;
  int nx() const { return static_cast<int>(xs.size()) - 1; }
  int ny() const { return static_cast<int>(ys.size()) - 1; }
  int nz() const { return static_cast<int>(zs.size()) - 1; }
  int node(int i, int j, int k) const { return 1 + i + (nx() + 1) * (j + (ny() + 1) * k); }
  bool onBoundary(int i, int j, int k) const {
    return i == 0 || j == 0 || k == 0 || i == nx() || j == ny() || k == nz();
  }

  // Adds nodes and elements (tags 1..) with material matTag and body force b.
  void build(Domain& d, int matTag, const Vector3& b = Vector3::Zero(),
             const std::function<Vector3(int, int, int)>& perturbation = nullptr) const {
    for (int k = 0; k <= nz(); ++k)
      for (int j = 0; j <= ny(); ++j)
        for (int i = 0; i <= nx(); ++i) {
          Vector3 x(xs[i], ys[j], zs[k]);
          if (perturbation) x += perturbation(i, j, k);
          addNode(d, node(i, j, k), 3, x(0), x(1), x(2));
        }
    int tag = 1;
    for (int k = 0; k < nz(); ++k)
      for (int j = 0; j < ny(); ++j)
        for (int i = 0; i < nx(); ++i) {
          const std::vector<int> n = {node(i, j, k),         node(i + 1, j, k),     node(i + 1, j + 1, k),
                                      node(i, j + 1, k),     node(i, j, k + 1),     node(i + 1, j, k + 1),
                                      node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)};
          if (b.isZero())
            addElement(d, "stdBrick", tag++, n, matTag);
          else
            addElement(d, "stdBrick", tag++, n, matTag, b(0), b(1), b(2));
        }
  }
};

std::vector<double> levels(double length, int n) {
  std::vector<double> v;
  for (int i = 0; i <= n; ++i) v.push_back(length * i / n);
  return v;
}

Eigen::Matrix<double, 6, 6> isotropicD(double E, double nu) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) D(i, i) += 2 * G, D(i + 3, i + 3) = G;
  return D;
}

StdBrick& brick(Domain& d, int tag) { return dynamic_cast<StdBrick&>(*d.findElement(tag)); }

// One distorted brick (counterclockwise bottom face, top face above it).
void addDistortedBrick(Domain& d, const Vector3& b = Vector3::Zero()) {
  const double X[8][3] = {{0, 0, 0},     {2.1, 0.2, -0.1}, {2.3, 1.8, 0.1}, {-0.2, 1.5, 0.0},
                          {0.1, -0.1, 1.2}, {1.9, 0.1, 1.4}, {2.2, 2.0, 1.1}, {0.2, 1.7, 1.3}};
  for (int a = 0; a < 8; ++a) addNode(d, a + 1, 3, X[a][0], X[a][1], X[a][2]);
  addNDMaterial(d, "ElasticIsotropic", 1, 1000.0, 0.3, 2.0);
  addElement(d, "stdBrick", 1, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 1, b(0), b(1), b(2));
}

using beamsolid::testsupport::errorOf;

// An ND material that records updateStage calls and may refuse 3D use.
class StageRecorder : public NDMaterial {
 public:
  StageRecorder(int tag, bool solid) : NDMaterial(tag), solid_(solid) {}
  std::string className() const override { return "StageRecorder"; }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override {
    if (!solid_ || kind != "ThreeDimensional") return nullptr;
    return std::make_unique<StageRecorder>(*this);
  }
  void setTrialStrain(const Eigen::Ref<const Vector>& e) override { strain_ = e; }
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(D_); }
  MatrixView initialTangent() const override { return viewOf(D_); }
  void commitState() override {}
  void revertToLastCommit() override {}
  void revertToStart() override {}
  void updateStage(int stage) override { stage_ = stage; }
  int stage() const { return stage_; }

 private:
  bool solid_;
  int stage_ = 0;
  Vector6 strain_ = Vector6::Zero(), stress_ = Vector6::Zero();
  Eigen::Matrix<double, 6, 6> D_ = Eigen::Matrix<double, 6, 6>::Identity();
};

class ConstantSeries : public TimeSeries {
 public:
  using TimeSeries::TimeSeries;
  std::string className() const override { return "Constant"; }
  double factor(double) const override { return 1.0; }
  double slope(double) const override { return 0.0; }
};

}  // namespace

TEST(StdBrick, FiniteDifferenceTangentOnADistortedBrick) {
  // Linear material: K is exact, central differences agree to round-off.
  // h = 1e-6 (element size ~2); tolerance 1e-7 relative to max |K|.
  Domain d;
  addDistortedBrick(d);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (const auto& [tag, n] : d.nodes())
    for (int k = 0; k < 3; ++k) n->setTrialDisp(k, u(rng));
  const TangentCheck c = checkTangent(*d.findElement(1), 1e-6);
  EXPECT_LE(c.relativeError(), 1e-7) << "max |K - K_fd| = " << c.maxError;
  EXPECT_GT(c.maxEntry, 0.0);
}

TEST(StdBrick, StiffnessIsSymmetricAndHasSixRigidBodyModes) {
  Domain d;
  addDistortedBrick(d);
  Element& e = *d.findElement(1);
  const Matrix K = e.tangentStiff();
  EXPECT_LE((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  // Translations and infinitesimal rotations produce no force.
  Matrix modes(24, 6);
  for (int a = 0; a < 8; ++a) {
    const Vector3 x = e.nodes()[a]->crd();
    for (int t = 0; t < 3; ++t) {
      modes.block<3, 1>(3 * a, t) = Vector3::Unit(t);
      modes.block<3, 1>(3 * a, 3 + t) = Vector3::Unit(t).cross(x);
    }
  }
  EXPECT_LE((K * modes).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
  // The remaining 18 eigenvalues are positive.
  Eigen::SelfAdjointEigenSolver<Matrix> eig(K);
  EXPECT_GT(eig.eigenvalues()(6), 1e-6 * eig.eigenvalues()(23));
}

TEST(StdBrick, PatchTestOnADistortedMesh) {
  // A linear displacement field u = u0 + A x imposed at the boundary nodes of
  // a distorted 3x3x3 mesh must be reproduced exactly: uniform strain
  // sym(A) and stress D sym(A) at every Gauss point, interior nodes in
  // equilibrium. Tolerances: 1e-10 relative.
  const double E = 1000.0, nu = 0.25;
  Domain d;
  addNDMaterial(d, "ElasticIsotropic", 1, E, nu);
  BrickBlock block{levels(2.0, 3), levels(1.5, 3), levels(1.2, 3)};
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> jitter(-0.12, 0.12);
  block.build(d, 1, Vector3::Zero(), [&](int, int, int) {
    return Vector3(jitter(rng) * 2.0 / 3, jitter(rng) * 1.5 / 3, jitter(rng) * 1.2 / 3);
  });
  Matrix3 A;
  A << 1.0, 0.4, -0.3, 0.2, -0.5, 0.6, 0.7, 0.1, 0.8;
  A *= 1e-3;
  const Vector3 u0(1e-3, -2e-3, 5e-4);
  auto field = [&](const Vector3& x) -> Vector3 { return u0 + A * x; };

  DenseStatics statics(d);
  for (int k = 0; k <= block.nz(); ++k)
    for (int j = 0; j <= block.ny(); ++j)
      for (int i = 0; i <= block.nx(); ++i) {
        if (!block.onBoundary(i, j, k)) continue;
        Node& n = d.node(block.node(i, j, k), "test");
        n.setTrialDisp(field(n.crd()));
        statics.fixAll(n.tag());
      }
  ASSERT_GE(statics.solve(1e-13), 0);

  for (const auto& [tag, n] : d.nodes())
    EXPECT_LE((n->trialDisp() - field(n->crd())).norm(), 1e-10 * 3e-3) << "node " << tag;

  Vector6 strain;
  strain << A(0, 0), A(1, 1), A(2, 2), A(0, 1) + A(1, 0), A(1, 2) + A(2, 1), A(2, 0) + A(0, 2);
  const Vector6 stress = isotropicD(E, nu) * strain;
  double worstStrain = 0.0, worstStress = 0.0;
  for (const auto& [tag, e] : d.elements()) {
    const StdBrick& b = dynamic_cast<const StdBrick&>(*e);
    for (int g = 0; g < 8; ++g) {
      worstStrain = std::max(worstStrain, (Vector(b.material(g).strain()) - strain).cwiseAbs().maxCoeff());
      worstStress = std::max(worstStress, (Vector(b.material(g).stress()) - stress).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LE(worstStrain, 1e-10 * strain.cwiseAbs().maxCoeff());
  EXPECT_LE(worstStress, 1e-10 * stress.cwiseAbs().maxCoeff());

  // Interior nodes carry no resisting force; boundary nodes carry the tractions.
  Matrix K;
  Vector R;
  d.update();
  statics.assemble(K, R);
  double interior = 0.0, boundary = 0.0;
  for (int i = 0; i < statics.size(); ++i)
    (statics.isFixed(i) ? boundary : interior) = std::max(statics.isFixed(i) ? boundary : interior, std::abs(R(i)));
  EXPECT_GT(boundary, 0.0);
  EXPECT_LE(interior, 1e-10 * boundary);
}

TEST(StdBrick, OedometricCompressionMatchesUniaxialStrain) {
  // A block on rollers (sides) and a fixed base under uniform top pressure p:
  // exact uniaxial strain eps_zz = -p/M with M = E(1-nu)/((1+nu)(1-2nu)),
  // sigma_zz = -p, sigma_xx = sigma_yy = nu/(1-nu) sigma_zz. Uneven layers
  // and displaced interior nodes; tolerance 1e-10 relative (round-off).
  const double E = 5e4, nu = 0.3, p = 120.0;
  const double Lx = 1.0, Ly = 1.2;
  Domain d;
  addNDMaterial(d, "ElasticIsotropic", 1, E, nu);
  BrickBlock block{levels(Lx, 2), levels(Ly, 2), {0.0, 0.3, 0.9, 1.4, 2.0}};
  const double H = 2.0;
  block.build(d, 1, Vector3::Zero(), [&](int i, int j, int k) {
    if (block.onBoundary(i, j, k)) return Vector3(Vector3::Zero());
    return Vector3(0.07 * k, -0.05, 0.04 * (k - 2));
  });
  DenseStatics statics(d);
  Vector& P = statics.load();
  const double dx = Lx / 2, dy = Ly / 2;
  for (int k = 0; k <= block.nz(); ++k)
    for (int j = 0; j <= block.ny(); ++j)
      for (int i = 0; i <= block.nx(); ++i) {
        const int tag = block.node(i, j, k);
        if (i == 0 || i == block.nx()) statics.fix(tag, 0);
        if (j == 0 || j == block.ny()) statics.fix(tag, 1);
        if (k == 0) statics.fix(tag, 2);
        if (k == block.nz()) {
          // Consistent nodal forces of a uniform pressure on bilinear faces: p*area/4 per corner.
          const int faces = (i == 0 || i == block.nx() ? 1 : 2) * (j == 0 || j == block.ny() ? 1 : 2);
          P(statics.index(tag, 2)) = -p * dx * dy / 4.0 * faces;
        }
      }
  ASSERT_GE(statics.solve(1e-11 * p), 0);

  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double epsZZ = -p / M;
  for (const auto& [tag, n] : d.nodes()) {
    EXPECT_NEAR(n->trialDisp()(2), epsZZ * n->crd()(2), 1e-10 * std::abs(epsZZ) * H) << "node " << tag;
    EXPECT_NEAR(n->trialDisp()(0), 0.0, 1e-10 * std::abs(epsZZ) * H) << "node " << tag;
    EXPECT_NEAR(n->trialDisp()(1), 0.0, 1e-10 * std::abs(epsZZ) * H) << "node " << tag;
  }
  const double lateral = nu / (1 - nu) * -p;
  for (const auto& [tag, e] : d.elements()) {
    const StdBrick& b = dynamic_cast<const StdBrick&>(*e);
    for (int g = 0; g < 8; ++g) {
      const Vector s = b.material(g).stress();
      EXPECT_NEAR(s(2), -p, 1e-10 * p);
      EXPECT_NEAR(s(0), lateral, 1e-10 * p);
      EXPECT_NEAR(s(1), lateral, 1e-10 * p);
      for (int c = 3; c < 6; ++c) EXPECT_NEAR(s(c), 0.0, 1e-10 * p);
    }
  }
}

TEST(StdBrick, ColumnUnderBodyForceHasBaseReactionEqualToWeight) {
  // b = (0, 0, -gamma) per unit volume on a 1x1x5 column with uneven layers
  // and a sheared cross-section, base fixed: the vertical base reaction is
  // gamma * V and the horizontal ones vanish, to round-off (1e-12 relative).
  const double gamma = 18.5;
  Domain d;
  addNDMaterial(d, "ElasticIsotropic", 1, 2e4, 0.3, 1.9);
  BrickBlock block{{0.0, 0.5}, {0.0, 0.4}, {0.0, 0.5, 1.1, 1.5, 2.3, 3.0}};
  block.build(d, 1, Vector3(0, 0, -gamma), [](int i, int j, int k) { return Vector3(0.1 * k + 0.05 * j, 0.02 * i, 0.0); });
  double volume = 0.0;
  for (const auto& [tag, e] : d.elements()) volume += dynamic_cast<const StdBrick&>(*e).volume();
  // The sheared cross-section is a parallelogram spanned by (0.5, 0.02) and
  // (0.05, 0.4): area 0.5*0.4 - 0.02*0.05 = 0.199; trilinear geometry is exact.
  EXPECT_NEAR(volume, 0.199 * 3.0, 1e-13);

  DenseStatics statics(d);
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i) statics.fixAll(block.node(i, j, 0));
  ASSERT_GE(statics.solve(1e-12 * gamma * volume), 0);
  d.calculateReactions();
  Vector3 reaction = Vector3::Zero();
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i) reaction += d.node(block.node(i, j, 0), "test").reaction();
  EXPECT_NEAR(reaction(2), gamma * volume, 1e-12 * gamma * volume);
  EXPECT_NEAR(reaction(0), 0.0, 1e-12 * gamma * volume);
  EXPECT_NEAR(reaction(1), 0.0, 1e-12 * gamma * volume);
  // The top settles under the load.
  EXPECT_LT(d.node(block.node(0, 0, 5), "test").trialDisp()(2), 0.0);
}

TEST(StdBrick, SelfWeightLoadsScaleTheElementBodyForce) {
  // OpenSees semantics (checked against OpenSeesPy 3.7.1): while eleLoad
  // -selfWeight loads are active the body force is sum factor * (f .* b),
  // replacing the element's b; the density plays no part. Two loads f1, f2
  // in a pattern with factor 1/2: base reaction -(f1 + f2) .* b V / 2, to
  // round-off (1e-12 relative). zeroLoad brings b back.
  const Vector3 b(0.4, -0.3, -18.0), f1(1.0, 1.0, 1.0), f2(0.0, 2.0, 3.0);
  const double scale = 0.5, volume = 0.5 * 0.4 * 2.0;
  Domain d;
  addNDMaterial(d, "ElasticIsotropic", 1, 2e4, 0.3, 1.9);
  BrickBlock block{{0.0, 0.5}, {0.0, 0.4}, {0.0, 1.0, 2.0}};
  block.build(d, 1, b);
  auto pattern = std::make_unique<LoadPattern>(1, std::make_shared<ConstantSeries>(1), scale);
  for (const auto& [tag, e] : d.elements()) {
    ASSERT_TRUE(e->acceptsLoad(ElementLoad::Type::SelfWeight));
    pattern->addElementLoad(tag, ElementLoad{ElementLoad::Type::SelfWeight, {f1(0), f1(1), f1(2)}});
    pattern->addElementLoad(tag, ElementLoad{ElementLoad::Type::SelfWeight, {f2(0), f2(1), f2(2)}});
  }
  d.addPattern(std::move(pattern), "test");
  d.applyLoad(0.0);

  DenseStatics statics(d);
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i) statics.fixAll(block.node(i, j, 0));
  const Vector3 expected = -scale * (f1 + f2).cwiseProduct(b) * volume;
  ASSERT_GE(statics.solve(1e-12 * expected.norm()), 0);
  d.calculateReactions();
  Vector3 reaction = Vector3::Zero();
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 1; ++i) reaction += d.node(block.node(i, j, 0), "test").reaction();
  EXPECT_LE((reaction - expected).norm(), 1e-12 * expected.norm());

  // Without the loads the element's own b acts again: -integral(N b dV) in
  // the resisting force at zero displacement.
  for (const auto& [tag, e] : d.elements()) e->zeroLoad();
  for (const auto& [tag, n] : d.nodes()) n->setTrialDisp(Vector::Zero(3));
  d.update();
  Vector3 total = Vector3::Zero();
  for (const auto& [tag, e] : d.elements()) {
    const Vector R = e->resistingForce();
    for (int a = 0; a < 8; ++a) total += R.segment<3>(3 * a);
  }
  EXPECT_LE((total + b * volume).norm(), 1e-12 * b.norm() * volume);
  EXPECT_THROW(d.findElement(1)->addLoad(ElementLoad{ElementLoad::Type::BeamUniform, {1.0, 0.0, 0.0}}, 1.0),
               OpenSeesError);
}

TEST(StdBrick, SelfWeightLoadAtFactorZeroSwitchesTheBodyForceOff) {
  // An active -selfWeight load with factor 0 leaves no body force at all.
  Domain d;
  addDistortedBrick(d, Vector3(1.0, -2.0, -9.0));
  Element& e = *d.findElement(1);
  e.zeroLoad();
  e.addLoad(ElementLoad{ElementLoad::Type::SelfWeight, {1.0, 1.0, 1.0}}, 0.0);
  EXPECT_EQ(Vector(e.resistingForce()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(StdBrick, BodyForceActsWithoutLoadPatterns) {
  // The constructor's body force is in the resisting force at zero
  // displacement: -integral(N_a b dV), summing to -b V.
  Domain d;
  const Vector3 b(1.0, -2.0, -9.0);
  addDistortedBrick(d, b);
  StdBrick& e = brick(d, 1);
  const Vector R = e.resistingForce();
  Vector3 total = Vector3::Zero();
  for (int a = 0; a < 8; ++a) total += R.segment<3>(3 * a);
  EXPECT_LE((total + b * e.volume()).norm(), 1e-12 * b.norm() * e.volume());
}

// Consistent mass, as OpenSees' stdBrick: symmetric, no coupling between
// directions, every direction's entries sum to rho V, and a rigid motion's
// kinetic energy is rho V v^2 / 2.
TEST(StdBrick, ConsistentMassSumsToDensityTimesVolume) {
  Domain d;
  addDistortedBrick(d);
  StdBrick& e = brick(d, 1);
  const Matrix M = e.massMatrix();
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-15 * M.cwiseAbs().maxCoeff());
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (i != j) EXPECT_EQ(M(3 * a + i, 3 * b + j), 0.0);
  for (int k = 0; k < 3; ++k) {
    Vector rigid = Vector::Zero(24);
    for (int a = 0; a < 8; ++a) rigid(3 * a + k) = 1.0;
    EXPECT_NEAR(rigid.dot(M * rigid), 2.0 * e.volume(), 1e-12 * e.volume());
  }
  Eigen::SelfAdjointEigenSolver<Matrix> eig(M);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  // Off-diagonal coupling between nodes: not lumped.
  EXPECT_GT(M(0, 3), 0.0);
}

TEST(StdBrick, ResponsesAndMaterialForwarding) {
  Domain d;
  addDistortedBrick(d);
  for (const auto& [tag, n] : d.nodes()) n->setTrialDisp(Vector3(1e-3 * tag, 0.0, -2e-3));
  Element& e = *d.findElement(1);
  e.update();
  Response stresses = e.setResponse({"stresses"});
  ASSERT_TRUE(stresses);
  EXPECT_EQ(stresses.size(), 48u);
  const StdBrick& b = brick(d, 1);
  EXPECT_EQ(stresses.value().segment<6>(12), Vector(b.material(2).stress()));
  EXPECT_EQ(e.setResponse({"strain"}).value().segment<6>(42), Vector(b.material(7).strain()));
  Response force = e.setResponse({"forces"});
  ASSERT_EQ(force.size(), 24u);
  EXPECT_EQ(force.value(), Vector(e.resistingForce()));
  Response mat = e.setResponse({"material", "3", "stress"});
  ASSERT_TRUE(mat);
  EXPECT_EQ(mat.value(), Vector(b.material(2).stress()));
  EXPECT_FALSE(e.setResponse({"material", "9", "stress"}));
  EXPECT_FALSE(e.setResponse({"material", "x"}));
  EXPECT_FALSE(e.setResponse({"nonsense"}));
}

TEST(StdBrick, GaussPointsAreNumberedAsInOpenSees) {
  // OpenSees numbers the 2x2x2 points with xi slowest and zeta fastest:
  // (-,-,-), (-,-,+), (-,+,-), (-,+,+), (+,-,-), ... (checked against
  // OpenSeesPy 3.7.1, tests/python/oracle_scripts). On the box
  // [0,2]x[0,3]x[0,5] point g sits at the centre plus (sx, sy, sz) times the
  // half sides over sqrt(3), to round-off.
  Domain d;
  addNDMaterial(d, "ElasticIsotropic", 1, 1000.0, 0.3, 2.0);
  BrickBlock block{{0.0, 2.0}, {0.0, 3.0}, {0.0, 5.0}};
  block.build(d, 1);
  const StdBrick& e = brick(d, 1);
  const Vector3 centre(1.0, 1.5, 2.5), half(1.0, 1.5, 2.5);
  for (int g = 0; g < StdBrick::kGaussPoints; ++g) {
    const Vector3 sign(g & 4 ? 1.0 : -1.0, g & 2 ? 1.0 : -1.0, g & 1 ? 1.0 : -1.0);
    const Vector3 expected = centre + sign.cwiseProduct(half) / std::sqrt(3.0);
    EXPECT_LE((e.gaussPointCoordinates(g) - expected).norm(), 1e-14) << "Gauss point " << g + 1;
  }
  // The 'material' index and the 'stresses' blocks follow the same order.
  for (const auto& [tag, n] : d.nodes()) n->setTrialDisp(Vector3(1e-3 * n->crd()(2) * n->crd()(0), 0.0, 0.0));
  d.findElement(1)->update();
  Element& element = *d.findElement(1);
  const Vector stresses = element.setResponse({"stresses"}).value();
  for (int g = 0; g < StdBrick::kGaussPoints; ++g) {
    const Vector s = element.setResponse({"material", std::to_string(g + 1), "stress"}).value();
    EXPECT_EQ(s, Vector(stresses.segment<6>(6 * g)));
    EXPECT_EQ(s, Vector(e.material(g).stress()));
  }
}

TEST(StdBrick, CommitAndRevertFollowTheMaterials) {
  Domain d;
  addDistortedBrick(d);
  Element& e = *d.findElement(1);
  Node& n7 = d.node(7, "test");
  n7.setTrialDisp(Vector3(1e-3, 2e-3, -1e-3));
  e.update();
  e.commitState();
  const Vector committed = e.resistingForce();
  n7.setTrialDisp(Vector3(5e-3, 0.0, 0.0));
  e.update();
  EXPECT_NE(Vector(e.resistingForce()), committed);
  e.revertToLastCommit();
  EXPECT_EQ(Vector(e.resistingForce()), committed);
  e.revertToStart();
  EXPECT_EQ(Vector(e.resistingForce()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(StdBrick, UpdateMaterialStageReachesCopiesWithThatTag) {
  Domain d;
  addDistortedBrick(d);
  d.ndMaterials.add(5, std::make_shared<StageRecorder>(5, true), "test");
  addNode(d, 9, 3, 5, 0, 0);
  addNode(d, 10, 3, 6, 0, 0);
  addNode(d, 11, 3, 6, 1, 0);
  addNode(d, 12, 3, 5, 1, 0);
  addNode(d, 13, 3, 5, 0, 1);
  addNode(d, 14, 3, 6, 0, 1);
  addNode(d, 15, 3, 6, 1, 1);
  addNode(d, 16, 3, 5, 1, 1);
  addElement(d, "stdBrick", 2, std::vector<int>{9, 10, 11, 12, 13, 14, 15, 16}, 5);
  for (const auto& [tag, e] : d.elements()) e->updateMaterialStage(5, 1);
  for (int g = 0; g < 8; ++g) EXPECT_EQ(dynamic_cast<const StageRecorder&>(brick(d, 2).material(g)).stage(), 1);
  EXPECT_EQ(dynamic_cast<const ElasticIsotropic3D&>(brick(d, 1).material(0)).E(), 1000.0);
}

TEST(StdBrick, SetParameterReachesTheMaterials) {
  Domain d;
  addDistortedBrick(d);
  Element& e = *d.findElement(1);
  const Matrix K1 = e.tangentStiff();
  EXPECT_TRUE(e.setParameter({"E"}, 3000.0));
  EXPECT_LE((Matrix(e.tangentStiff()) - 3.0 * K1).cwiseAbs().maxCoeff(), 1e-12 * 3.0 * K1.cwiseAbs().maxCoeff());
  EXPECT_FALSE(e.setParameter({"friction"}, 1.0));
}

TEST(StdBrick, InputErrorsAreClear) {
  auto cube = [](Domain& d, int ndfOfNode5) {
    const double X[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int a = 0; a < 8; ++a) addNode(d, a + 1, a == 4 ? ndfOfNode5 : 3, X[a][0], X[a][1], X[a][2]);
    addNDMaterial(d, "ElasticIsotropic", 1, 100.0, 0.2);
  };
  {
    Domain d;
    cube(d, 6);
    const std::string msg =
        errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 1); });
    EXPECT_NE(msg.find("element stdBrick 7: node 5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("ndf 3"), std::string::npos) << msg;
    EXPECT_EQ(d.findElement(7), nullptr);
  }
  {
    // Top and bottom faces swapped: the element is inside out.
    Domain d;
    cube(d, 3);
    const std::string msg =
        errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{5, 6, 7, 8, 1, 2, 3, 4}, 1); });
    EXPECT_NE(msg.find("element stdBrick 7"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Jacobian"), std::string::npos) << msg;
  }
  {
    Domain d;
    cube(d, 3);
    const std::string missingNode =
        errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 42}, 1); });
    EXPECT_NE(missingNode.find("element stdBrick 7: node 42 does not exist"), std::string::npos) << missingNode;
    const std::string missingMaterial =
        errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 9); });
    EXPECT_NE(missingMaterial.find("element stdBrick 7: nDMaterial 9 does not exist"), std::string::npos)
        << missingMaterial;
    d.ndMaterials.add(4, std::make_shared<StageRecorder>(4, false), "test");
    const std::string not3d =
        errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 4); });
    EXPECT_NE(not3d.find("ThreeDimensional"), std::string::npos) << not3d;
    const std::string partialB =
        errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 1, 0.0, -9.8); });
    EXPECT_NE(partialB.find("0 or 3 body force"), std::string::npos) << partialB;
    const std::string fewNodes = errorOf([&] { addElement(d, "stdBrick", 7, std::vector<int>{1, 2, 3}); });
    EXPECT_NE(fewNodes.find("(node4)"), std::string::npos) << fewNodes;
  }
}
