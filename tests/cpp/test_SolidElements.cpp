// The locking-free solids bbarBrick, SSPbrick, bbarQuad and SSPquad, each
// on its own: finite-difference tangents (elastic and with a nonlinear
// material), rigid-body modes and no spurious zero-energy mode, the number
// of volumetric constraints (what locks), the patch test on distorted
// meshes, closed-form hourglass energies of the stabilized elements, body
// forces, mass, responses, material forwarding and input errors.
// stdBrick and quad (the same base class) are tested in their own files.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/BbarBrick.h"
#include "elements/BbarQuad.h"
#include "elements/SSPbrick.h"
#include "elements/SSPquad.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using beamsolid::testsupport::errorOf;

namespace {

constexpr double kE = 1000.0, kNu = 0.3, kThick = 0.7, kRho = 2.0;

bool isBrick(const std::string& type) { return type == "bbarBrick" || type == "SSPbrick" || type == "stdBrick"; }

// A distorted hexahedron (node order of OpenSees' bricks) and quadrilateral.
const double kBrick[8][3] = {{0, 0, 0},      {2.1, 0.2, -0.1}, {2.3, 1.8, 0.1}, {-0.2, 1.5, 0.0},
                             {0.1, -0.1, 1.2}, {1.9, 0.1, 1.4}, {2.2, 2.0, 1.1}, {0.2, 1.7, 1.3}};
const double kQuad[4][2] = {{0.0, 0.0}, {2.0, 0.2}, {2.3, 1.7}, {-0.2, 1.2}};

void addNode2(Domain& d, int tag, double x, double y) {
  d.addNode(std::make_unique<Node>(tag, 2, Vector3(x, y, 0.0), 2), "test");
}

// element(type, tag, *nodes, ...) with material matTag and body force b (may be empty).
Element& addSolid(Domain& d, const std::string& type, int tag, const std::vector<int>& nodes, int matTag,
                  const std::vector<double>& b = {}) {
  if (type == "bbarQuad") return addElement(d, type, tag, nodes, kThick, matTag);
  if (type == "SSPquad") return addElement(d, type, tag, nodes, matTag, "PlaneStrain", kThick, b);
  return addElement(d, type, tag, nodes, matTag, b);
}

// One distorted element of `type` (tag 1) with ElasticIsotropic(E, nu, rho) as material 1.
Element& single(Domain& d, const std::string& type, double nu = kNu, const std::vector<double>& b = {},
                double scale = 1.0) {
  if (isBrick(type)) {
    for (int a = 0; a < 8; ++a) addNode(d, a + 1, 3, scale * kBrick[a][0], scale * kBrick[a][1], scale * kBrick[a][2]);
    addNDMaterial(d, "ElasticIsotropic", 1, kE, nu, kRho);
    return addSolid(d, type, 1, {1, 2, 3, 4, 5, 6, 7, 8}, 1, b);
  }
  d.setModelSpace(2, 2);
  for (int a = 0; a < 4; ++a) addNode2(d, a + 1, scale * kQuad[a][0], scale * kQuad[a][1]);
  addNDMaterial(d, "ElasticIsotropic", 1, kE, nu, kRho);
  return addSolid(d, type, 1, {1, 2, 3, 4}, 1, b);
}

// Rigid-body modes of an element: translations and infinitesimal rotations.
Matrix rigidModes(const Element& e, bool brick) {
  const int n = static_cast<int>(e.nodes().size()), dim = brick ? 3 : 2;
  Matrix modes = Matrix::Zero(dim * n, brick ? 6 : 3);
  for (int a = 0; a < n; ++a) {
    const Vector3 x = e.nodes()[a]->crd();
    if (brick) {
      for (int t = 0; t < 3; ++t) {
        modes.block<3, 1>(3 * a, t) = Vector3::Unit(t);
        modes.block<3, 1>(3 * a, 3 + t) = Vector3::Unit(t).cross(x);
      }
    } else {
      modes(2 * a, 0) = modes(2 * a + 1, 1) = 1.0;
      modes(2 * a, 2) = -x.y();
      modes(2 * a + 1, 2) = x.x();
    }
  }
  return modes;
}

void setRandomDisplacements(Domain& d, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-size, size);
  for (const auto& [tag, n] : d.nodes())
    for (int k = 0; k < n->ndf(); ++k) n->setTrialDisp(k, u(rng));
}

// A smooth nonlinear elastic law for tangent checks (no nonlinear nD
// material exists yet): sigma = D eps + beta |eps|^2 eps, tangent D + beta
// (2 eps eps^T + |eps|^2 I), initial tangent D; in the ThreeDimensional and
// PlaneStrain forms (bbarQuad uses the ThreeDimensional one).
class CubicElastic : public NDMaterial {
 public:
  CubicElastic(int tag, Matrix D, double beta) : NDMaterial(tag), D_(std::move(D)), beta_(beta) {
    strain_ = stress_ = Vector::Zero(D_.rows());
    tangent_ = D_;
  }
  std::string className() const override { return "CubicElastic"; }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override {
    if (kind == "ThreeDimensional" && D_.rows() == 6) return std::make_unique<CubicElastic>(*this);
    if (kind == "PlaneStrain") {
      if (D_.rows() == 3) return std::make_unique<CubicElastic>(*this);
      const std::vector<int> keep = {0, 1, 3};
      Matrix D(3, 3);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) D(i, j) = D_(keep[i], keep[j]);
      return std::make_unique<CubicElastic>(tag(), D, beta_);
    }
    return nullptr;
  }
  void setTrialStrain(const Eigen::Ref<const Vector>& e) override {
    strain_ = e;
    const double s = e.squaredNorm();
    stress_ = D_ * e + beta_ * s * e;
    tangent_ = D_ + beta_ * (2.0 * e * e.transpose() + s * Matrix::Identity(e.size(), e.size()));
  }
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(tangent_); }
  MatrixView initialTangent() const override { return viewOf(D_); }
  void commitState() override {}
  void revertToLastCommit() override {}
  void revertToStart() override { setTrialStrain(Vector::Zero(D_.rows())); }

 private:
  Matrix D_;
  double beta_;
  Vector strain_, stress_;
  Matrix tangent_;
};

Matrix isotropicD(double E, double nu) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  Matrix D = Matrix::Zero(6, 6);
  D.topLeftCorner(3, 3).setConstant(lambda);
  for (int i = 0; i < 3; ++i) D(i, i) += 2 * G, D(i + 3, i + 3) = G;
  return D;
}

class LockingFree : public ::testing::TestWithParam<const char*> {};

TEST_P(LockingFree, TangentMatchesFiniteDifferences) {
  // Linear material: K is exact; central differences (h = 1e-6) agree to round-off.
  Domain d;
  Element& e = single(d, GetParam(), kNu, {});
  setRandomDisplacements(d, 1e-3, 11);
  const TangentCheck c = checkTangent(e, 1e-6);
  EXPECT_LE(c.relativeError(), 1e-8) << "max |K - K_fd| = " << c.maxError;
  EXPECT_TRUE(e.hasConstantTangent());
}

TEST_P(LockingFree, TangentMatchesFiniteDifferencesWithANonlinearMaterial) {
  // sigma = D eps + beta |eps|^2 eps at strains ~0.05: the cubic term is 2.5
  // times the linear one. The stabilized elements keep K_stab from the
  // initial tangent in both force and stiffness, so their tangent stays the
  // derivative of their force. h = 1e-7, tolerance 1e-6 relative (the
  // central difference error is ~beta h^2).
  Domain d;
  const std::string type = GetParam();
  if (isBrick(type)) {
    for (int a = 0; a < 8; ++a) addNode(d, a + 1, 3, kBrick[a][0], kBrick[a][1], kBrick[a][2]);
  } else {
    d.setModelSpace(2, 2);
    for (int a = 0; a < 4; ++a) addNode2(d, a + 1, kQuad[a][0], kQuad[a][1]);
  }
  d.ndMaterials.add(3, std::make_shared<CubicElastic>(3, isotropicD(kE, kNu), 1e6), "test");
  Element& e = addSolid(d, type, 1, isBrick(type) ? std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8} : std::vector<int>{1, 2, 3, 4},
                        3);
  EXPECT_FALSE(e.hasConstantTangent());
  setRandomDisplacements(d, 0.05, 5);
  const TangentCheck c = checkTangent(e, 1e-7);
  EXPECT_LE(c.relativeError(), 1e-6) << "max |K - K_fd| = " << c.maxError;
  // The material really is nonlinear here: the tangent moved away from the initial one.
  EXPECT_GT((Matrix(e.tangentStiff()) - Matrix(e.initialStiff())).cwiseAbs().maxCoeff(), 0.5 * c.maxEntry);
}

TEST_P(LockingFree, TangentMatchesFiniteDifferencesWithJ2Plasticity) {
  // J2Plasticity (K, G, sig0 = 1, sigInf = 1.5, delta = 20, H = 10), a
  // uniform shear strain of 2e-2 (about 20 times the yield strain) plus a
  // random field of 1e-3: every material point yields. The consistent
  // tangent of the return map is the derivative of the force; h = 1e-8,
  // tolerance 1e-6 relative to max |K|. Also after a committed plastic step
  // (unloading trial from a plastic state) and in the elastic range.
  const std::string type = GetParam();
  const bool brick = isBrick(type);
  Domain d;
  if (brick) {
    for (int a = 0; a < 8; ++a) addNode(d, a + 1, 3, kBrick[a][0], kBrick[a][1], kBrick[a][2]);
  } else {
    d.setModelSpace(2, 2);
    for (int a = 0; a < 4; ++a) addNode2(d, a + 1, kQuad[a][0], kQuad[a][1]);
  }
  const double K = 800.0, G = 300.0;
  addNDMaterial(d, "J2Plasticity", 3, K, G, 1.0, 1.5, 20.0, 10.0);
  Element& e = addSolid(d, type, 1, brick ? std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8} : std::vector<int>{1, 2, 3, 4}, 3);
  EXPECT_FALSE(e.hasConstantTangent());
  auto shear = [&](double gamma, double noise, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-noise, noise);
    for (const auto& [tag, n] : d.nodes()) {
      Vector v = Vector::Zero(n->ndf());
      v(0) = gamma * n->crd()(1);
      for (int k = 0; k < n->ndf(); ++k) v(k) += u(rng);
      n->setTrialDisp(v);
    }
    e.update();
  };
  shear(2e-2, 1e-3, 9);
  const TangentCheck plastic = checkTangent(e, 1e-8);
  EXPECT_LE(plastic.relativeError(), 1e-6) << type << " plastic: max |K - K_fd| = " << plastic.maxError;
  EXPECT_GT((Matrix(e.tangentStiff()) - Matrix(e.initialStiff())).cwiseAbs().maxCoeff(), 0.1 * plastic.maxEntry)
      << "the material should be yielding";
  e.commitState();
  shear(1.5e-2, 1e-3, 10);  // unloading from the committed plastic state
  const TangentCheck unloading = checkTangent(e, 1e-8);
  EXPECT_LE(unloading.relativeError(), 1e-6) << type << " unloading: " << unloading.maxError;
  e.revertToStart();
  shear(1e-4, 1e-5, 11);  // elastic
  const TangentCheck elastic = checkTangent(e, 1e-9);
  EXPECT_LE(elastic.relativeError(), 1e-6) << type << " elastic: " << elastic.maxError;
  EXPECT_LE((Matrix(e.tangentStiff()) - Matrix(e.initialStiff())).cwiseAbs().maxCoeff(), 1e-12 * elastic.maxEntry);
}

TEST_P(LockingFree, OnlyTheRigidBodyModesCostNoEnergy) {
  // K r = 0 for the 6 (3) rigid-body modes, and exactly 6 (3) eigenvalues
  // vanish: the hourglass modes of the single-point elements are
  // stabilized. Also for nu = 0.4999, where the smallest non-zero
  // eigenvalue must stay of the shear modulus' order (not shrink).
  const std::string type = GetParam();
  const bool brick = isBrick(type);
  for (double nu : {0.3, 0.4999}) {
    Domain d;
    Element& e = single(d, type, nu);
    const Matrix K = e.tangentStiff();
    EXPECT_LE((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
    EXPECT_LE((K * rigidModes(e, brick)).cwiseAbs().maxCoeff(), 1e-11 * K.cwiseAbs().maxCoeff());
    Eigen::SelfAdjointEigenSolver<Matrix> eig(K);
    const Vector& ev = eig.eigenvalues();
    const int zeros = brick ? 6 : 3;
    const double G = kE / (2 * (1 + nu));
    for (int k = 0; k < zeros; ++k) EXPECT_LE(std::abs(ev(k)), 1e-9 * ev(ev.size() - 1)) << type << " nu " << nu;
    // Element size ~2 (thickness 0.7 for quads): shear eigenvalues ~ G L (G t in 2D).
    EXPECT_GT(ev(zeros), 1e-3 * G) << type << " nu " << nu << ": a spurious soft mode";
  }
}

TEST_P(LockingFree, OneVolumetricConstraintPerElement) {
  // Eigenvalues that grow with the bulk modulus are volumetric constraints.
  // Raising nu from 0.49 to 0.49999 (the bulk modulus by ~1000) multiplies
  // exactly one eigenvalue by more than 100: the element dilatation. The
  // standard elements have as many as the dilatations of their field span
  // (3 for quad, 7 for stdBrick), which is their locking.
  const std::string type = GetParam();
  auto eigenvalues = [&](double nu) {
    Domain d;
    Element& e = single(d, type, nu);
    Eigen::SelfAdjointEigenSolver<Matrix> eig(Matrix(e.tangentStiff()));
    return Vector(eig.eigenvalues());
  };
  const Vector soft = eigenvalues(0.49), stiff = eigenvalues(0.49999);
  int grown = 0;
  const int zeros = isBrick(type) ? 6 : 3;
  for (Eigen::Index k = zeros; k < soft.size(); ++k) grown += stiff(k) > 100.0 * soft(k) ? 1 : 0;
  EXPECT_EQ(grown, 1) << type;
}

TEST(SolidElements, StandardElementsHaveManyVolumetricConstraints) {
  // The counterpart of LockingFree.OneVolumetricConstraintPerElement for
  // stdBrick and quad: the constraints that lock them.
  for (const char* type : {"stdBrick", "quad"}) {
    auto eigenvalues = [&](double nu) {
      Domain d;
      Element* e = nullptr;
      if (std::string(type) == "stdBrick") {
        e = &single(d, "stdBrick", nu);
      } else {
        d.setModelSpace(2, 2);
        for (int a = 0; a < 4; ++a) addNode2(d, a + 1, kQuad[a][0], kQuad[a][1]);
        addNDMaterial(d, "ElasticIsotropic", 1, kE, nu);
        e = &addElement(d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrain", 1);
      }
      Eigen::SelfAdjointEigenSolver<Matrix> eig(Matrix(e->tangentStiff()));
      return Vector(eig.eigenvalues());
    };
    const Vector soft = eigenvalues(0.49), stiff = eigenvalues(0.49999);
    int grown = 0;
    for (Eigen::Index k = 0; k < soft.size(); ++k) grown += stiff(k) > 100.0 * std::max(soft(k), 1e-9) ? 1 : 0;
    // The dilatation of a bilinear field spans {1, x, y} (3 constraints at
    // the 4 Gauss points), that of a trilinear field {1, x, y, z, yz, zx,
    // xy} (7 at the 8 points); the mean dilatation is one of them.
    EXPECT_EQ(grown, std::string(type) == "stdBrick" ? 7 : 3) << type;
  }
}

// Patch test: a mesh with moved interior nodes and a linear displacement
// field on its boundary must reproduce the field inside, the constant
// strain at every material point, and interior nodes in equilibrium.
TEST_P(LockingFree, PatchTestOnADistortedMesh) {
  const std::string type = GetParam();
  const bool brick = isBrick(type);
  const int n = 3;
  const int perSide = n + 1;
  auto tag = [&](int i, int j, int k) { return 1 + i + perSide * (j + perSide * k); };
  Domain d;
  if (!brick) d.setModelSpace(2, 2);
  addNDMaterial(d, "ElasticIsotropic", 1, kE, 0.45);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  const int nz = brick ? n : 0;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const bool inside = i > 0 && i < n && j > 0 && j < n && (!brick || (k > 0 && k < n));
        const double x = 1.0 * i + 0.1 * j + (inside ? jitter(rng) : 0.0);
        const double y = 0.8 * j + 0.05 * i * i + (inside ? jitter(rng) : 0.0);
        const double z = 0.9 * k + 0.04 * i + (inside ? jitter(rng) : 0.0);
        if (brick)
          addNode(d, tag(i, j, k), 3, x, y, z);
        else
          addNode2(d, tag(i, j, 0), x, y);
      }
  int e = 0;
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::vector<int> nodes = {tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k)};
        if (brick)
          for (int a = 0; a < 4; ++a) nodes.push_back(nodes[a] + perSide * perSide);
        addSolid(d, type, ++e, nodes, 1);
      }
  Matrix3 A;
  A << 1.0, 0.4, -0.3, 0.2, -0.5, 0.6, 0.7, 0.1, 0.8;
  A *= 1e-3;
  const Vector3 u0(1e-3, -2e-3, 5e-4);
  const int dim = brick ? 3 : 2;
  auto exact = [&](const Vector3& x) -> Vector {
    Vector3 xx = x;
    if (!brick) xx(2) = 0.0;
    const Vector3 u = u0 + A * xx;
    return u.head(dim);
  };
  DenseStatics statics(d);
  for (const auto& [t, node] : d.nodes()) {
    const int i = (t - 1) % perSide, j = ((t - 1) / perSide) % perSide, k = (t - 1) / (perSide * perSide);
    const bool boundary = i == 0 || j == 0 || i == n || j == n || (brick && (k == 0 || k == n));
    if (!boundary) continue;
    node->setTrialDisp(exact(node->crd()));
    statics.fixAll(t);
  }
  ASSERT_GE(statics.solve(1e-12), 0);
  for (const auto& [t, node] : d.nodes())
    EXPECT_LE((node->trialDisp() - exact(node->crd())).cwiseAbs().maxCoeff(), 1e-12) << type << " node " << t;

  // The expected strain and stress at every material point, in the element's own vector form.
  const Matrix3 eps3 = 0.5 * (A + A.transpose());
  Eigen::Matrix<double, 6, 1> e6;
  e6 << eps3(0, 0), eps3(1, 1), brick ? eps3(2, 2) : 0.0, 2 * eps3(0, 1), brick ? 2 * eps3(1, 2) : 0.0,
      brick ? 2 * eps3(0, 2) : 0.0;
  const Vector s6 = isotropicD(kE, 0.45) * e6;
  Vector strain, stress;
  if (brick) {
    strain = e6, stress = s6;
  } else if (type == "bbarQuad") {
    strain = Vector(4), stress = Vector(4);
    strain << e6(0), e6(1), 0.0, e6(3);
    stress << s6(0), s6(1), s6(2), s6(3);
  } else {
    strain = Vector(3), stress = Vector(3);
    strain << e6(0), e6(1), e6(3);
    stress << s6(0), s6(1), s6(3);
  }
  for (const auto& [t, el] : d.elements()) {
    const Vector strains = el->setResponse({"strains"}).value(), stresses = el->setResponse({"stresses"}).value();
    ASSERT_EQ(strains.size() % strain.size(), 0);
    for (Eigen::Index p = 0; p < strains.size() / strain.size(); ++p) {
      EXPECT_LE((strains.segment(p * strain.size(), strain.size()) - strain).cwiseAbs().maxCoeff(),
                1e-12 * strain.cwiseAbs().maxCoeff());
      EXPECT_LE((stresses.segment(p * stress.size(), stress.size()) - stress).cwiseAbs().maxCoeff(),
                1e-11 * stress.cwiseAbs().maxCoeff());
    }
  }
  Matrix K;
  Vector R;
  d.update();
  statics.assemble(K, R);
  double interior = 0.0, boundary = 0.0;
  for (int i = 0; i < statics.size(); ++i) {
    double& worst = statics.isFixed(i) ? boundary : interior;
    worst = std::max(worst, std::abs(R(i)));
  }
  EXPECT_GT(boundary, 0.0);
  EXPECT_LE(interior, 1e-11 * boundary);
}

TEST_P(LockingFree, BodyForceAndMass) {
  // Body force: the resisting force at rest is -integral(N b dV), summing
  // to -b V (thick V for quads). Mass: every direction sums to rho V; bbar
  // elements consistent (nodes coupled), SSP lumped.
  const std::string type = GetParam();
  const bool brick = isBrick(type);
  const std::vector<double> b = brick ? std::vector<double>{1.0, -2.0, -9.0} : std::vector<double>{1.5, -8.0};
  Domain d;
  Element& e = single(d, type, kNu, type == "bbarQuad" ? std::vector<double>{} : b);
  const int dim = brick ? 3 : 2;
  double volume = 0.0;
  if (brick) {
    volume = dynamic_cast<const SolidElement<3>&>(e).volume();
  } else {
    volume = kThick * dynamic_cast<const SolidElement<2>&>(e).volume();
  }
  const Vector R = e.resistingForce();
  for (int i = 0; i < dim; ++i) {
    double total = 0.0;
    for (Eigen::Index a = 0; a < R.size() / dim; ++a) total += R(dim * a + i);
    const double expected = type == "bbarQuad" ? 0.0 : -b[i] * volume;
    EXPECT_NEAR(total, expected, 1e-12 * 10.0 * volume) << type;
  }
  const Matrix M = e.massMatrix();
  EXPECT_LE((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  for (int i = 0; i < dim; ++i) {
    Vector rigid = Vector::Zero(M.rows());
    for (Eigen::Index a = 0; a < M.rows() / dim; ++a) rigid(dim * a + i) = 1.0;
    EXPECT_NEAR(rigid.dot(M * rigid), kRho * volume, 1e-12 * kRho * volume) << type;
  }
  const bool lumped = type.rfind("SSP", 0) == 0;
  EXPECT_EQ(M(0, dim) == 0.0, lumped) << type;
  if (type == "SSPbrick")  // rho V / 8 on every dof
    for (Eigen::Index k = 0; k < M.rows(); ++k) EXPECT_NEAR(M(k, k), kRho * volume / 8, 1e-14) << k;
}

TEST_P(LockingFree, SelfWeightLoadsScaleTheBodyForce) {
  // eleLoad -selfWeight f: body force f .* b instead of b (OpenSees' rule).
  // bbarQuad takes no body force: the load has nothing to scale.
  const std::string type = GetParam();
  const bool brick = isBrick(type);
  const std::vector<double> b = brick ? std::vector<double>{1.0, -2.0, -9.0} : std::vector<double>{1.5, -8.0};
  Domain d;
  Element& e = single(d, type, kNu, type == "bbarQuad" ? std::vector<double>{} : b);
  if (type == "bbarQuad") {
    e.addLoad(ElementLoad{ElementLoad::Type::SelfWeight, {1.0, 1.0, 1.0}}, 1.0);
    EXPECT_EQ(Vector(e.resistingForce()).cwiseAbs().maxCoeff(), 0.0);
    return;
  }
  const Vector R0 = e.resistingForce();
  e.zeroLoad();
  e.addLoad(ElementLoad{ElementLoad::Type::SelfWeight, {2.0, 2.0, 2.0}}, 0.5);
  EXPECT_LE((Vector(e.resistingForce()) - R0).cwiseAbs().maxCoeff(), 1e-14);
  e.zeroLoad();
  e.addLoad(ElementLoad{ElementLoad::Type::SelfWeight, {0.0, 0.0, 0.0}}, 1.0);
  EXPECT_EQ(Vector(e.resistingForce()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(e.addLoad(ElementLoad{ElementLoad::Type::SelfWeight, {1.0}}, 1.0), OpenSeesError);
  e.zeroLoad();
  EXPECT_LE((Vector(e.resistingForce()) - R0).cwiseAbs().maxCoeff(), 0.0);
}

TEST_P(LockingFree, ResponsesFollowTheMaterialPoints) {
  const std::string type = GetParam();
  const bool brick = isBrick(type);
  Domain d;
  Element& e = single(d, type);
  setRandomDisplacements(d, 1e-3, 3);
  e.update();
  const bool ssp = type.rfind("SSP", 0) == 0;
  const std::size_t points = ssp ? 1 : (brick ? 8 : 4);
  const std::size_t components = brick ? 6 : (type == "bbarQuad" ? 4 : 3);
  const Response stresses = e.setResponse({"stresses"}), strains = e.setResponse({"strain"});
  ASSERT_TRUE(stresses);
  EXPECT_EQ(stresses.size(), points * components);
  EXPECT_EQ(strains.size(), points * components);
  EXPECT_EQ(stresses.componentNames[0].rfind("sigma11", 0), 0u);
  if (type == "bbarQuad") EXPECT_EQ(stresses.componentNames[2], "sigma33");
  const Response forces = e.setResponse({"forces"});
  ASSERT_EQ(forces.size(), brick ? 24u : 8u);
  EXPECT_EQ(forces.value(), Vector(e.resistingForce()));
  EXPECT_EQ(forces.componentNames[brick ? 23 : 7], brick ? "P3_8" : "P2_4");
  for (std::size_t p = 1; p <= points; ++p) {
    const Response m = e.setResponse({"material", std::to_string(p), "stress"});
    ASSERT_TRUE(m);
    EXPECT_EQ(m.value(), Vector(stresses.value().segment((p - 1) * components, components)));
  }
  EXPECT_FALSE(e.setResponse({"material", std::to_string(points + 1), "stress"}));
  EXPECT_FALSE(e.setResponse({"nonsense"}));
}

TEST_P(LockingFree, SetParameterReachesTheMaterialsAndTheStabilization) {
  // E times 3 scales the whole stiffness, the stabilization included (it
  // is rebuilt from the new initial tangent).
  Domain d;
  Element& e = single(d, GetParam());
  const Matrix K1 = e.tangentStiff();
  EXPECT_TRUE(e.setParameter({"E"}, 3.0 * kE));
  EXPECT_LE((Matrix(e.tangentStiff()) - 3.0 * K1).cwiseAbs().maxCoeff(), 1e-12 * 3.0 * K1.cwiseAbs().maxCoeff());
  EXPECT_FALSE(e.setParameter({"friction"}, 1.0));
}

INSTANTIATE_TEST_SUITE_P(Elements, LockingFree, ::testing::Values("bbarBrick", "SSPbrick", "bbarQuad", "SSPquad"));

TEST(SSPquad, HourglassEnergyOfARectangleIsTheClosedForm) {
  // Rectangle of half sides a, b (thick t): the hourglass mode u_x = xi eta
  // has q_x = 1, hourglass strain e_xx = eta / a (and g_xy = xi / b, which
  // the assumed strain drops), of which the dilatation-free part 1/2 eta/a
  // [1, -1, 0] is kept: energy u^T K u = (A t / 3) 4G (1 / 2a)^2 = A t G /
  // (3 a^2). Likewise u_y = xi eta: A t G / (3 b^2). Round-off.
  const double a = 1.5, bHalf = 0.4, G = kE / (2 * (1 + kNu));
  Domain d;
  d.setModelSpace(2, 2);
  const double X[4][2] = {{-a, -bHalf}, {a, -bHalf}, {a, bHalf}, {-a, bHalf}};
  for (int k = 0; k < 4; ++k) addNode2(d, k + 1, X[k][0] + 3.0, X[k][1] - 1.0);
  addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu);
  Element& e = addSolid(d, "SSPquad", 1, {1, 2, 3, 4}, 1);
  const Matrix K = e.tangentStiff();
  const double h[4] = {1, -1, 1, -1}, A = 4 * a * bHalf;
  for (int dir = 0; dir < 2; ++dir) {
    Vector u = Vector::Zero(8);
    for (int k = 0; k < 4; ++k) u(2 * k + dir) = h[k];
    const double half = dir == 0 ? a : bHalf;
    EXPECT_NEAR(u.dot(K * u), A * kThick * G / (3 * half * half), 1e-12 * kE);
  }
}

TEST(SSPbrick, HourglassEnergiesOfABoxAreTheClosedForms) {
  // Box of half sides (a, b, c) along x, y, z, volume V = 8abc. For the
  // hourglass modes u_d = h_k (gamma_k . h_k = 1) the enhanced strains give
  // (Puso 2000; OpenSees' SSPbrick has the same values, checked):
  //  u_x = eta zeta (twist, pure shear): G (V/3) (1/b^2 + 1/c^2)
  //  u_y = eta zeta (bending about x): (V/3) E' / b^2, E' = E / (1 - nu^2):
  //         the shear g_yz ~ eta is removed and e_zz ~ zeta relaxed
  //  u_x = xi eta zeta: G (V/9) (1/b^2 + 1/c^2) (its e_xx ~ eta zeta removed)
  // Round-off; also at nu = 0.4999 (bounded: no locking).
  const double a = 1.0, b = 0.5, c = 0.25, V = 8 * a * b * c;
  for (double nu : {0.25, 0.4999}) {
    Domain d;
    for (int k = 0; k < 8; ++k) {
      const auto xi = TrilinearHexahedron::nodeNatural(k);
      addNode(d, k + 1, 3, a * xi(0) + 2.0, b * xi(1) - 1.0, c * xi(2) + 0.5);
    }
    addNDMaterial(d, "ElasticIsotropic", 1, kE, nu);
    Element& e = addSolid(d, "SSPbrick", 1, {1, 2, 3, 4, 5, 6, 7, 8}, 1);
    const Matrix K = e.tangentStiff();
    const double G = kE / (2 * (1 + nu)), Ebend = kE / (1 - nu * nu);
    auto energy = [&](int dir, std::function<double(const Eigen::Vector3d&)> h) {
      Vector u = Vector::Zero(24);
      for (int k = 0; k < 8; ++k) u(3 * k + dir) = h(TrilinearHexahedron::nodeNatural(k));
      return u.dot(K * u);
    };
    auto etaZeta = [](const Eigen::Vector3d& x) { return x(1) * x(2); };
    auto xiEtaZeta = [](const Eigen::Vector3d& x) { return x(0) * x(1) * x(2); };
    EXPECT_NEAR(energy(0, etaZeta), G * V / 3 * (1 / (b * b) + 1 / (c * c)), 1e-12 * kE) << nu;
    EXPECT_NEAR(energy(1, etaZeta), V / 3 * Ebend / (b * b), 1e-12 * kE) << nu;
    EXPECT_NEAR(energy(0, xiEtaZeta), G * V / 9 * (1 / (b * b) + 1 / (c * c)), 1e-12 * kE) << nu;
  }
}

TEST(SolidElements, StabilizedElementsAreInvariantUnderRotation) {
  // Ours are objective: K of a rotated element is R K R^T (OpenSees' SSP
  // elements are not; docs/solid_elements.md). The SSPquad's assumed strain
  // is written in the x-y axes, so only SSPbrick is checked.
  Domain a, b;
  Element& e1 = single(a, "SSPbrick");
  Eigen::Matrix3d R = (Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  for (int k = 0; k < 8; ++k) {
    const Vector3 x = R * Vector3(kBrick[k][0], kBrick[k][1], kBrick[k][2]);
    addNode(b, k + 1, 3, x(0), x(1), x(2));
  }
  addNDMaterial(b, "ElasticIsotropic", 1, kE, kNu, kRho);
  Element& e2 = addSolid(b, "SSPbrick", 1, {1, 2, 3, 4, 5, 6, 7, 8}, 1);
  Matrix Rb = Matrix::Zero(24, 24);
  for (int k = 0; k < 8; ++k) Rb.block<3, 3>(3 * k, 3 * k) = R;
  const Matrix K1 = e1.tangentStiff(), K2 = e2.tangentStiff();
  EXPECT_LE((Rb * K1 * Rb.transpose() - K2).cwiseAbs().maxCoeff(), 1e-12 * K1.cwiseAbs().maxCoeff());
}

TEST(SolidElements, UpdateMaterialStageAndInitialStateReachTheCopies) {
  // A stage change is passed to the copies of that material tag.
  class Staged : public CubicElastic {
   public:
    using CubicElastic::CubicElastic;
    std::unique_ptr<NDMaterial> clone(const std::string& kind) const override {
      auto c = CubicElastic::clone(kind);
      return c ? std::make_unique<Staged>(*this) : nullptr;
    }
    void updateStage(int s) override { stage = s; }
    int stage = 0;
  };
  for (const char* type : {"bbarBrick", "SSPbrick"}) {
    Domain d;
    for (int a = 0; a < 8; ++a) addNode(d, a + 1, 3, kBrick[a][0], kBrick[a][1], kBrick[a][2]);
    d.ndMaterials.add(5, std::make_shared<Staged>(5, isotropicD(kE, kNu), 0.0), "test");
    Element& e = addSolid(d, type, 1, {1, 2, 3, 4, 5, 6, 7, 8}, 5);
    e.updateMaterialStage(4, 1);
    auto& s = dynamic_cast<SolidElement<3>&>(e);
    for (int p = 0; p < s.materialPoints(); ++p) EXPECT_EQ(dynamic_cast<const Staged&>(s.material(p)).stage, 0);
    e.updateMaterialStage(5, 1);
    for (int p = 0; p < s.materialPoints(); ++p) EXPECT_EQ(dynamic_cast<const Staged&>(s.material(p)).stage, 1);
  }
}

TEST(SolidElements, BadInputIsRefusedByName) {
  {
    Domain d;
    for (int a = 0; a < 8; ++a) addNode(d, a + 1, 3, kBrick[a][0], kBrick[a][1], kBrick[a][2]);
    addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu);
    for (const char* type : {"bbarBrick", "SSPbrick"}) {
      const std::string t = type;
      EXPECT_NE(errorOf([&] { addElement(d, t, 7, std::vector<int>{1, 2, 3}); }).find("element " + t + " 7"),
                std::string::npos);
      EXPECT_NE(errorOf([&] { addElement(d, t, 7, std::vector<int>{1, 2, 3}); }).find("(node4)"), std::string::npos);
      EXPECT_NE(errorOf([&] { addElement(d, t, 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 9); })
                    .find("element " + t + " 7: nDMaterial 9 does not exist"),
                std::string::npos);
      EXPECT_NE(errorOf([&] { addElement(d, t, 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8}, 1, 0.0, -9.8); })
                    .find("0 or 3 body force"),
                std::string::npos);
      EXPECT_NE(errorOf([&] { addElement(d, t, 7, std::vector<int>{5, 6, 7, 8, 1, 2, 3, 4}, 1); }).find("Jacobian"),
                std::string::npos);
      EXPECT_NE(errorOf([&] { addElement(d, t, 7, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 42}, 1); })
                    .find("node 42 does not exist"),
                std::string::npos);
    }
  }
  {
    Domain d;
    d.setModelSpace(2, 2);
    for (int a = 0; a < 4; ++a) addNode2(d, a + 1, kQuad[a][0], kQuad[a][1]);
    addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu);
    auto has = [&](const std::function<void()>& f, const std::string& text) {
      const std::string msg = errorOf(f);
      EXPECT_NE(msg.find(text), std::string::npos) << msg;
    };
    has([&] { addElement(d, "bbarQuad", 7, 1, 2, 3, 4, -1.0, 1); }, "element bbarQuad 7: argument 6 (thick)");
    has([&] { addElement(d, "bbarQuad", 7, 1, 2, 3, 4, kThick); }, "(matTag)");
    has([&] { addElement(d, "bbarQuad", 7, 1, 2, 3, 4, kThick, 1, 0.0, -9.8); }, "no arguments after matTag");
    has([&] { addElement(d, "SSPquad", 7, 1, 2, 3, 4, 1, "PlaneStrian", kThick); },
        "element SSPquad 7: argument 7 (type): expected 'PlaneStrain' or 'PlaneStress'");
    has([&] { addElement(d, "SSPquad", 7, 1, 2, 3, 4, 1, "PlaneStrain"); }, "(thick)");
    has([&] { addElement(d, "SSPquad", 7, 1, 2, 3, 4, 1, "PlaneStrain", kThick, 1.0); }, "0 or 2 body force");
    has([&] { addElement(d, "SSPquad", 7, 1, 2, 3, 4, 1, "PlaneStrain", kThick, 1.0, 2.0, 3.0); },
        "0 or 2 body force");
    has([&] { addElement(d, "SSPquad", 7, 1, 2, 3, 4, 9, "PlaneStrain", kThick); }, "nDMaterial 9 does not exist");
    has([&] { addElement(d, "SSPquad", 7, 1, 4, 3, 2, 1, "PlaneStrain", kThick); }, "Jacobian determinant");
  }
  {
    Domain d;
    for (int a = 0; a < 4; ++a) addNode(d, a + 1, 3, kQuad[a][0], kQuad[a][1], 0.0);
    addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu);
    EXPECT_NE(errorOf([&] { addElement(d, "SSPquad", 7, 1, 2, 3, 4, 1, "PlaneStrain", kThick); })
                  .find("SSPquad is a 2D element"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(d, "bbarQuad", 7, 1, 2, 3, 4, kThick, 1); }).find("bbarQuad is a 2D element"),
              std::string::npos);
  }
}

TEST(BbarQuad, ItsMaterialPointsAreThreeDimensionalWithoutOutOfPlaneShear) {
  // The 3D law with e23 = e13 = 0: 'material' k 'stress' gives [11 22 33 12]
  // (OpenSees' AxiSymmetric form), the 3D material the rest.
  Domain d;
  Element& e = single(d, "bbarQuad");
  setRandomDisplacements(d, 1e-3, 4);
  e.update();
  const auto& q = dynamic_cast<const SolidElement<2>&>(e);
  for (int p = 0; p < q.materialPoints(); ++p) {
    const Vector strain6 = q.material(p).strain(), stress6 = q.material(p).stress();
    ASSERT_EQ(strain6.size(), 6);
    EXPECT_EQ(strain6(4), 0.0);
    EXPECT_EQ(strain6(5), 0.0);
    EXPECT_LE((stress6 - isotropicD(kE, kNu) * strain6).cwiseAbs().maxCoeff(), 1e-12 * kE * strain6.norm());
    const Response r = e.setResponse({"material", std::to_string(p + 1), "stress"});
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r.componentNames[2], "sigma33");
    EXPECT_EQ(r.value(), Vector(stress6.head(4)));
  }
  EXPECT_EQ(e.setResponse({"material", "1", "tangent"}).size(), 36u);
}

}  // namespace
