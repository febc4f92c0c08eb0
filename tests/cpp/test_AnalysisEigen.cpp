// Eigen analysis (sparse shift-invert Lanczos and dense -fullGenLapack)
// against closed forms for spring-mass chains and an independent dense solve.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "AnalysisTestSupport.h"
#include "analysis/EigenAnalysis.h"

using namespace beamsolid;
using namespace beamsolid::analysistest;

namespace {

// Runs eigen on the model's own numbering (as the interpreter does).
std::vector<double> runEigen(Model& m, int numModes, bool dense) {
  Registry& r = Registry::global();
  m.components.handler = build<ConstraintHandler>(r.constraintHandlers, m.domain, "Transformation");
  m.components.numberer = build<Numberer>(r.numberers, m.domain, "RCM");
  auto solver = build<LinearSolver>(r.systems, m.domain, "UmfPack");
  AnalysisModel model(m.domain);
  model.setup(*m.components.handler, *m.components.numberer, *solver);
  return EigenAnalysis::solve(model, numModes, dense);
}

// Fixed-free chain: ground -k- m -k- m ... -k- m (N masses at nodes 2..N+1).
// With `massless` each spring k is two springs 2k in series meeting at a
// massless node: the same dynamics, plus N dofs without mass.
void buildChain(Model& m, int N, double k, double mass, bool massless) {
  m.addNode(1, 0.0);
  m.fixX(1);
  int nextNode = 2, nextElement = 1, previous = 1;
  for (int i = 1; i <= N; ++i) {
    if (massless) {
      const int mid = 1000 + i;
      m.addNode(mid, i - 0.5);
      m.addSpring(nextElement++, previous, mid, linearLaw(2.0 * k));
      previous = mid;
    }
    m.addNode(nextNode, i, mass);
    m.addSpring(nextElement++, previous, nextNode, linearLaw(massless ? 2.0 * k : k));
    previous = nextNode++;
  }
}

double chainOmega2(int j, int N, double k, double m) {
  const double s = std::sin((2 * j - 1) * std::numbers::pi / (2.0 * (2 * N + 1)));
  return 4.0 * k / m * s * s;
}

// Mode j of the fixed-free chain: u_i = sin(i theta_j), theta_j = (2j-1) pi / (2N+1).
double chainShape(int i, int j, int N) { return std::sin(i * (2 * j - 1) * std::numbers::pi / (2 * N + 1)); }

void expectChainModes(Model& m, const std::vector<double>& omega2, int N, double k, double mass) {
  const int numModes = static_cast<int>(omega2.size());
  for (int j = 1; j <= numModes; ++j) {
    // Tolerance: 1e-9 relative (shift-invert Lanczos at tol 1e-12, Rayleigh-quotient refined).
    EXPECT_NEAR(omega2[j - 1], chainOmega2(j, N, k, mass), 1e-9 * chainOmega2(j, N, k, mass)) << "mode " << j;
    // Mass normalization phi^T M phi = 1 (1e-10) and the closed-form shape:
    // the closed form scaled to unit modal mass, up to sign, within 1e-7.
    double modalMass = 0.0, shapeNorm = 0.0, dot = 0.0;
    for (int i = 1; i <= N; ++i) {
      const double phi = m.domain.node(i + 1, "test").eigenvectors()(0, j - 1);
      modalMass += mass * phi * phi;
      shapeNorm += mass * chainShape(i, j, N) * chainShape(i, j, N);
      dot += phi * chainShape(i, j, N);
    }
    EXPECT_NEAR(modalMass, 1.0, 1e-10) << "mode " << j;
    const double scale = (dot < 0 ? -1.0 : 1.0) / std::sqrt(shapeNorm);
    for (int i = 1; i <= N; ++i)
      EXPECT_NEAR(m.domain.node(i + 1, "test").eigenvectors()(0, j - 1), scale * chainShape(i, j, N), 1e-7)
          << "mode " << j << " mass " << i;
  }
}

}  // namespace

TEST(AnalysisEigen, FixedFreeChainSparseMatchesClosedForm) {
  for (int N : {40, 300}) {  // 300: a Lanczos basis (20) much smaller than the problem
    Model m;
    buildChain(m, N, 1000.0, 2.0, false);
    const auto omega2 = runEigen(m, 8, false);
    ASSERT_EQ(omega2.size(), 8u);
    expectChainModes(m, omega2, N, 1000.0, 2.0);
  }
}

TEST(AnalysisEigen, FixedFreeChainDenseMatchesClosedForm) {
  Model m;
  const int N = 40;
  buildChain(m, N, 1000.0, 2.0, false);
  const auto omega2 = runEigen(m, 6, true);
  ASSERT_EQ(omega2.size(), 6u);
  expectChainModes(m, omega2, N, 1000.0, 2.0);
}

TEST(AnalysisEigen, MasslessDofsAreCondensedExactlyBothPaths) {
  for (bool dense : {false, true}) {
    Model m;
    const int N = 25;
    buildChain(m, N, 500.0, 3.0, true);
    const auto omega2 = runEigen(m, 5, dense);
    expectChainModes(m, omega2, N, 500.0, 3.0);
    // A massless node between two equal springs moves by the mean of its
    // neighbours (its static condensation), within 1e-12 of the mode scale.
    for (int j = 0; j < 5; ++j)
      for (int i = 1; i <= N; ++i) {
        const double left = i == 1 ? 0.0 : m.domain.node(i, "test").eigenvectors()(0, j);
        const double right = m.domain.node(i + 1, "test").eigenvectors()(0, j);
        EXPECT_NEAR(m.domain.node(1000 + i, "test").eigenvectors()(0, j), 0.5 * (left + right), 1e-12)
            << (dense ? "dense" : "sparse") << " mode " << j + 1 << " node " << 1000 + i;
      }
  }
}

TEST(AnalysisEigen, FixedAndConstrainedDofsInModeShapes) {
  Model m;
  const int N = 8;
  buildChain(m, N, 10.0, 1.0, false);
  // Node 50 follows the free end in x through an equalDOF-type constraint.
  m.addNode(50, N + 1.0);
  MPConstraint mp;
  mp.retainedNode = N + 1;
  mp.constrainedNode = 50;
  mp.constrainedDofs = {0};
  mp.retainedDofs = {0};
  mp.C = Matrix::Identity(1, 1);
  m.domain.addMP(mp, "test");
  const auto omega2 = runEigen(m, 3, false);
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(m.domain.node(50, "test").eigenvectors()(0, j), m.domain.node(N + 1, "test").eigenvectors()(0, j));
    EXPECT_EQ(m.domain.node(1, "test").eigenvectors()(0, j), 0.0);  // fixed in x
    for (int tag = 1; tag <= N + 1; ++tag) {
      EXPECT_EQ(m.domain.node(tag, "test").eigenvectors().rows(), 3);
      EXPECT_EQ(m.domain.node(tag, "test").eigenvectors()(1, j), 0.0);  // y fixed
      EXPECT_EQ(m.domain.node(tag, "test").eigenvectors()(2, j), 0.0);  // rz fixed
    }
  }
  expectChainModes(m, omega2, N, 10.0, 1.0);
}

// Element (consistent) mass and unequal springs: compared with a dense
// generalized eigensolve of K and M assembled by hand in this test.
TEST(AnalysisEigen, ConsistentElementMassMatchesIndependentDenseSolve) {
  const int n = 12;  // free nodes 2..n+1
  std::vector<double> k(n), mass(n);
  for (int e = 0; e < n; ++e) {
    k[e] = 100.0 + 37.0 * ((e * 7) % 5);
    mass[e] = 1.0 + 0.25 * ((e * 3) % 4);
  }
  Matrix K = Matrix::Zero(n, n), M = Matrix::Zero(n, n);
  for (int e = 0; e < n; ++e) {  // element e joins free dof e-1 (or ground) and e
    const int a = e - 1, b = e;
    K(b, b) += k[e];
    M(b, b) += mass[e] / 3.0;
    if (a >= 0) {
      K(a, a) += k[e];
      K(a, b) -= k[e];
      K(b, a) -= k[e];
      M(a, a) += mass[e] / 3.0;
      M(a, b) += mass[e] / 6.0;
      M(b, a) += mass[e] / 6.0;
    }
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> reference(K, M);
  for (bool dense : {false, true}) {
    Model m;
    m.addNode(1, 0.0);
    m.fixX(1);
    for (int e = 0; e < n; ++e) {
      m.addNode(e + 2, e + 1.0);
      m.addSpring(e + 1, e + 1, e + 2, linearLaw(k[e]), mass[e]);
    }
    const auto omega2 = runEigen(m, 4, dense);
    for (int j = 0; j < 4; ++j) {
      EXPECT_NEAR(omega2[j], reference.eigenvalues()[j], 1e-9 * reference.eigenvalues()[j]);
      Vector phi(n);
      for (int i = 0; i < n; ++i) phi[i] = m.domain.node(i + 2, "test").eigenvectors()(0, j);
      EXPECT_NEAR(phi.dot(M * phi), 1.0, 1e-10);  // mass-normalized with the consistent mass
      const Vector ref = reference.eigenvectors().col(j);
      EXPECT_NEAR(std::fabs(phi.dot(M * ref)), 1.0, 1e-9) << (dense ? "dense" : "sparse") << " mode " << j + 1;
    }
  }
}

// Free-free chain of 3 equal masses: omega^2 = 0, k/m, 3k/m. K is singular,
// so the sparse path must shift.
TEST(AnalysisEigen, RigidBodyModeWithSingularStiffness) {
  for (bool dense : {false, true}) {
    Model m;
    const double k = 40.0, mass = 2.0;
    for (int i = 1; i <= 3; ++i) m.addNode(i, i, mass);
    m.addSpring(1, 1, 2, linearLaw(k));
    m.addSpring(2, 2, 3, linearLaw(k));
    const auto omega2 = runEigen(m, 2, dense);
    EXPECT_NEAR(omega2[0], 0.0, 1e-9 * k / mass);
    EXPECT_NEAR(omega2[1], k / mass, 1e-9 * k / mass);
    for (int i = 1; i <= 3; ++i)  // the rigid mode: equal motion, unit modal mass
      EXPECT_NEAR(m.domain.node(i, "test").eigenvectors()(0, 0), 1.0 / std::sqrt(3.0 * mass), 1e-7);
  }
}

TEST(AnalysisEigen, AsManyModesAsMassedDofsAndNoMore) {
  Model m;
  const int N = 3;
  buildChain(m, N, 10.0, 1.0, true);  // 6 free dofs, 3 with mass
  // All 3 modes: Spectra cannot (needs nev < n), the exact dense solve is used.
  const auto omega2 = runEigen(m, 3, false);
  expectChainModes(m, omega2, N, 10.0, 1.0);
  try {
    runEigen(m, 4, false);
    FAIL() << "expected OpenSeesError";
  } catch (const OpenSeesError& e) {
    EXPECT_NE(std::string(e.what()).find("only 3 of the 6 free dofs have mass"), std::string::npos) << e.what();
  }
  EXPECT_THROW(runEigen(m, 4, true), OpenSeesError);
}

TEST(AnalysisEigen, MasslessMechanismIsAClearError) {
  // Node 3 has no mass and no stiffness in x: it cannot be condensed out.
  for (bool dense : {false, true}) {
    Model m;
    m.addNode(1, 0.0);
    m.fixX(1);
    m.addNode(2, 1.0, 1.0);
    m.addNode(3, 2.0);
    m.addNode(4, 3.0, 1.0);
    m.addSpring(1, 1, 2, linearLaw(10.0));
    m.addSpring(2, 3, 4, linearLaw(0.0));
    m.addSpring(3, 2, 4, linearLaw(10.0));
    EXPECT_THROW(runEigen(m, 1, dense), OpenSeesError) << (dense ? "dense" : "sparse");
  }
}
