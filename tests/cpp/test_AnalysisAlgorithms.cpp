// NewtonLineSearch and KrylovNewton on a stiffening spring chain, against
// the closed-form (Cardano) solution; iteration counts are reported.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "AnalysisTestSupport.h"
#include "analysis/KrylovNewton.h"
#include "analysis/NewtonLineSearch.h"

using namespace beamsolid;
using namespace beamsolid::analysistest;

namespace {

struct Cubic {
  double k, k3;  // f = k d + k3 d^3
  SpringLaw law() const {
    const double a = k, b = k3;
    return {[=](double d) { return a * d + b * d * d * d; }, [=](double d) { return a + 3.0 * b * d * d; }};
  }
  // The one real root of k3 d^3 + k d - F = 0 (Cardano; k, k3 > 0).
  double elongation(double F) const {
    const double p = k / k3, q = -F / k3;
    const double r = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
    return std::cbrt(-q / 2.0 + r) + std::cbrt(-q / 2.0 - r);
  }
};

// node 1 fixed -A- node 2 -B- node 3 -C- node 4, load P at node 4: every
// spring carries P, so each elongation is a closed form.
const Cubic springA{1.0, 10.0}, springB{2.0, 0.0}, springC{3.0, 5.0};
const double loadP = 10.0;

void buildChain(Model& m) {
  for (int i = 1; i <= 4; ++i) m.addNode(i, i - 1.0);
  m.fixX(1);
  m.addSpring(1, 1, 2, springA.law());
  m.addSpring(2, 2, 3, springB.law());
  m.addSpring(3, 3, 4, springC.law());
  m.addLoad(4, loadP);
}

// Applies the load in `steps` equal LoadControl steps; returns the total
// number of iterations, or -1 if a step failed.
int solve(const std::string& algorithm, Args args, Model& m, int steps) {
  buildChain(m);
  m.analyzeWith(algorithm, std::move(args), "LoadControl", {1.0 / steps}, 1e-10, 100);
  int total = 0;
  for (int step = 0; step < steps; ++step) {
    if (m.analyze(1) != 0) return -1;
    total += m.components.test->numIterations();
  }
  return total;
}
int solveInOneStep(const std::string& algorithm, Args args, Model& m) { return solve(algorithm, std::move(args), m, 1); }

void expectExactSolution(const Model& m, const std::string& label) {
  const double dA = springA.elongation(loadP), dB = loadP / springB.k, dC = springC.elongation(loadP);
  // NormUnbalance 1e-10 and spring stiffness >= 1: displacements within 1e-9.
  EXPECT_NEAR(m.disp(2), dA, 1e-9) << label;
  EXPECT_NEAR(m.disp(3), dA + dB, 1e-9) << label;
  EXPECT_NEAR(m.disp(4), dA + dB + dC, 1e-9) << label;
}

void report(const std::string& label, int iterations, int extra = -1) {
  ::testing::Test::RecordProperty(label, iterations);
  std::cout << "[ iterations ] " << label << ": " << iterations;
  if (extra >= 0) std::cout << " (+" << extra << " line-search residuals)";
  std::cout << "\n";
}

}  // namespace

TEST(AnalysisAlgorithms, ClosedFormIsSelfConsistent) {
  for (const Cubic& s : {springA, springC}) {
    const double d = s.elongation(loadP);
    EXPECT_NEAR(s.law().force(d), loadP, 1e-12);
  }
}

TEST(AnalysisAlgorithms, NewtonLineSearchConvergesLikeNewtonOnStiffeningChain) {
  Model newton;
  const int newtonIterations = solveInOneStep("Newton", {}, newton);
  ASSERT_GT(newtonIterations, 0);
  expectExactSolution(newton, "Newton");
  report("Newton", newtonIterations);
  for (const char* type : {"InitialInterpolated", "Secant", "RegulaFalsi", "Bisection"}) {
    Model m;
    const int iterations = solveInOneStep("NewtonLineSearch", {std::string("-type"), std::string(type)}, m);
    ASSERT_GT(iterations, 0) << type;
    expectExactSolution(m, type);
    const auto* ls = dynamic_cast<const NewtonLineSearch*>(m.components.algorithm.get());
    ASSERT_NE(ls, nullptr);
    report(std::string("NewtonLineSearch_") + type, iterations, ls->lineSearchEvaluations());
    // From u = 0 the first Newton step overshoots far into the stiff range;
    // the search pulls it back, so fewer Newton iterations are needed.
    EXPECT_GT(ls->lineSearchEvaluations(), 0) << type;
    EXPECT_LT(iterations, newtonIterations) << type;
  }
}

// Total iterations and factorizations of KrylovNewton over `steps` load steps (-1: failed).
std::pair<int, int> solveKrylov(Args args, Model& m, int steps) {
  buildChain(m);
  m.analyzeWith("KrylovNewton", std::move(args), "LoadControl", {1.0 / steps}, 1e-10, 100);
  const auto& kn = dynamic_cast<const KrylovNewton&>(*m.components.algorithm);
  int iterations = 0, factorizations = 0;
  for (int step = 0; step < steps; ++step) {
    if (m.analyze(1) != 0) return {-1, -1};
    iterations += m.components.test->numIterations();
    factorizations += kn.numFactorizations();
  }
  return {iterations, factorizations};
}

// Ten load steps (the Krylov subspace models the response near the current
// state, so it needs steps that are not wildly nonlinear).
TEST(AnalysisAlgorithms, KrylovNewtonConvergesWhereModifiedNewtonDoesNot) {
  const int steps = 10;
  Model newton;
  const int newtonIterations = solve("Newton", {}, newton, steps);
  ASSERT_GT(newtonIterations, 0);
  expectExactSolution(newton, "Newton");
  report("Newton_10steps", newtonIterations);

  Model krylov;
  const auto [iterations, factorizations] = solveKrylov({}, krylov, steps);
  ASSERT_GT(iterations, 0);
  expectExactSolution(krylov, "KrylovNewton");
  report("KrylovNewton_10steps", iterations);
  report("KrylovNewton_10steps_factorizations", factorizations);
  // Newton factors once per iteration; the accelerated modified Newton less often.
  EXPECT_LT(factorizations, newtonIterations);

  // With the initial tangent only, modified Newton diverges on this
  // stiffening chain (|1 - f'(d)/k0| > 1 near the solution); the Krylov
  // acceleration converges on that same single factorization.
  Model modified;
  EXPECT_EQ(solve("ModifiedNewton", {std::string("-initial")}, modified, steps), -1);
  Model krylovInitial;
  const auto [initialIterations, initialFactorizations] = solveKrylov(
      {std::string("-iterate"), std::string("initial"), std::string("-increment"), std::string("initial")},
      krylovInitial, steps);
  ASSERT_GT(initialIterations, 0);
  expectExactSolution(krylovInitial, "KrylovNewton initial");
  report("KrylovNewton_initial_10steps", initialIterations);
  EXPECT_EQ(initialFactorizations, 1);

  for (int maxDim : {1, 2, 6}) {
    Model m;
    const auto [dimIterations, dimFactorizations] =
        solveKrylov({std::string("-maxDim"), static_cast<long long>(maxDim)}, m, steps);
    ASSERT_GT(dimIterations, 0) << "maxDim " << maxDim;
    expectExactSolution(m, "KrylovNewton maxDim " + std::to_string(maxDim));
    report("KrylovNewton_maxDim" + std::to_string(maxDim) + "_10steps", dimIterations);
  }
}

TEST(AnalysisAlgorithms, OptionErrorsNameTheOption) {
  Domain domain;
  auto expectError = [&](const std::string& type, Args args, const std::string& fragment) {
    try {
      build<Algorithm>(Registry::global().algorithms, domain, type, std::move(args));
      ADD_FAILURE() << "expected OpenSeesError containing '" << fragment << "'";
    } catch (const OpenSeesError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError("NewtonLineSearch", {std::string("-type"), std::string("Golden")}, "-type 'Golden' is unknown");
  expectError("NewtonLineSearch", {std::string("-speed"), 2.0}, "unknown option '-speed'");
  expectError("NewtonLineSearch", {std::string("-minEta"), 2.0, std::string("-maxEta"), 1.0}, "minEta <= maxEta");
  expectError("KrylovNewton", {std::string("-iterate"), std::string("secant")}, "-iterate 'secant' is unknown");
  expectError("KrylovNewton", {std::string("-maxDim"), 0LL}, "-maxDim must be at least 1");
  // The documented defaults.
  auto ls = build<Algorithm>(Registry::global().algorithms, domain, "NewtonLineSearch");
  const auto& o = dynamic_cast<NewtonLineSearch&>(*ls).options();
  EXPECT_EQ(o.search, NewtonLineSearch::Search::InitialInterpolated);
  EXPECT_EQ(o.tolerance, 0.8);
  EXPECT_EQ(o.maxIterations, 10);
  EXPECT_EQ(o.minEta, 0.1);
  EXPECT_EQ(o.maxEta, 10.0);
}
