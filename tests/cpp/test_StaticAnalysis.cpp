// End-to-end static analysis through the Interpreter on spring models with
// closed-form answers: handlers, numberers and systems must agree; failed
// steps must leave the model at its last converged state.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "core/OpenSeesError.h"
#include "support/Script.h"
#include "support/TestSpring.h"
#include "analysis/StaticAnalysis.h"
#include "core/Registry.h"

using namespace beamsolid;
using namespace beamsolid::testing;

namespace {

// Three springs in series along x (k1, k2, k3), fixed at node 1, force P at
// node 4; node 5 tied to node 4 by equalDOF in x; a skew spring from node 4
// to a fixed node 6 carries transverse load. Every node needs all dofs held.
void buildChain(Script& s, const std::string& handler, const std::string& numberer, const std::string& system) {
  registerTestTypes();
  s("wipe");
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  for (int i = 1; i <= 4; ++i) s("node", i, double(i - 1), 0.0, 0.0);
  s("node", 5, 3.0, 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  for (int i = 2; i <= 4; ++i) s("fix", i, 0, 1, 1);
  s("fix", 5, 0, 1, 1);
  s("element", "testSpring", 1, 1, 2, 100.0);
  s("element", "testSpring", 2, 2, 3, 200.0);
  s("element", "testSpring", 3, 3, 4, 400.0);
  s("equalDOF", 4, 5, 1);
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 5, 8.0, 0.0, 0.0);
  if (handler == "Penalty") s("constraints", "Penalty", 1e12, 1e12);
  else s("constraints", handler);
  s("numberer", numberer);
  s("system", system);
  s("test", "NormDispIncr", 1e-12, 10);
  s("algorithm", "Newton");
  s("integrator", "LoadControl", 1.0);
  s("analysis", "Static");
}

}  // namespace

// u4 = P (1/k1 + 1/k2 + 1/k3) = 8 (0.01 + 0.005 + 0.0025) = 0.14.
class ChainEquivalence : public ::testing::TestWithParam<std::tuple<std::string, std::string, std::string>> {};

TEST_P(ChainEquivalence, MatchesClosedForm) {
  auto [handler, numberer, system] = GetParam();
  Script s;
  buildChain(s, handler, numberer, system);
  ASSERT_EQ(s.integer("analyze", 1), 0);
  const double tol = handler == "Penalty" ? 1e-9 : 1e-13;
  EXPECT_NEAR(s.number("nodeDisp", 4, 1), 0.14, tol);
  EXPECT_NEAR(s.number("nodeDisp", 5, 1), 0.14, tol);
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), 0.08, tol);
  s("reactions");
  EXPECT_NEAR(s.number("nodeReaction", 1, 1), -8.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(AllHandlersNumberersSystems, ChainEquivalence,
                         ::testing::Combine(::testing::Values("Plain", "Transformation", "Penalty"),
                                            ::testing::Values("Plain", "RCM", "AMD"),
                                            ::testing::Values("UmfPack", "Cholmod", "BandGeneral", "ProfileSPD")));

TEST(StaticAnalysis, ImposedDisplacementScalesWithTheSeries) {
  registerTestTypes();
  Script s;
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 1.0, 0.0, 0.0);
  s("node", 3, 2.0, 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  s("fix", 2, 0, 1, 1);
  s("fix", 3, 0, 1, 1);
  s("element", "testSpring", 1, 1, 2, 100.0);
  s("element", "testSpring", 2, 2, 3, 300.0);
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("sp", 3, 1, 0.4);
  s("integrator", "LoadControl", 0.5);
  s("analysis", "Static");
  ASSERT_EQ(s.integer("analyze", 2), 0);
  // Series: 1/u2 stiffness split: u2 = 0.4 * k2 / (k1 + k2) = 0.3.
  EXPECT_NEAR(s.number("nodeDisp", 3, 1), 0.4, 1e-14);
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), 0.3, 1e-14);
  EXPECT_NEAR(s.number("getTime"), 1.0, 1e-15);
}

TEST(StaticAnalysis, NewtonConvergesQuadraticallyOnAStiffeningSpring) {
  registerTestTypes();
  Script s;
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 1.0, 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  s("fix", 2, 0, 1, 1);
  s("element", "testSpring", 1, 1, 2, 10.0, 100.0);  // N = 10 e + 100 e^3
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 2, 120.0, 0.0, 0.0);  // e = 1: 10 + 100 = 110 ... solve 10e + 100e^3 = 120
  s("test", "NormUnbalance", 1e-10, 30);
  s("algorithm", "Newton");
  s("integrator", "LoadControl", 1.0);
  s("analysis", "Static");
  ASSERT_EQ(s.integer("analyze", 1), 0);
  const double e = s.number("nodeDisp", 2, 1);
  EXPECT_NEAR(10 * e + 100 * e * e * e, 120.0, 1e-9);
  // testNorm has maxIter values (as in OpenSees): the norms, then zeros.
  const auto norms = s.list("testNorm");
  ASSERT_EQ(norms.size(), 30u);
  const std::size_t n = static_cast<std::size_t>(s.integer("testIter"));
  ASSERT_GE(n, 4u);
  for (std::size_t k = n; k < 30; ++k) EXPECT_EQ(norms[k], 0.0) << k;
  for (std::size_t k = 0; k + 1 < n; ++k) EXPECT_GT(norms[k], 0.0) << k;
  // Observed order log(r_{k+1}/r_k) / log(r_k/r_{k-1}) near 2 in the last iterations.
  const double p = std::log(norms[n - 1] / norms[n - 2]) / std::log(norms[n - 2] / norms[n - 3]);
  EXPECT_GT(p, 1.8);
}

TEST(StaticAnalysis, FailedStepLeavesTheLastConvergedState) {
  registerTestTypes();
  Script s;
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 1.0, 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  s("fix", 2, 0, 1, 1);
  // Softening spring N = 10 e - 10 e^3: its peak is 20/(3 sqrt 3) = 3.849 at e = 0.577.
  s("element", "testSpring", 1, 1, 2, 10.0, -10.0);
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 2, 1.0, 0.0, 0.0);
  s("test", "NormUnbalance", 1e-10, 15);
  s("algorithm", "Newton");
  s("integrator", "LoadControl", 1.0);
  s("analysis", "Static");
  ASSERT_EQ(s.integer("analyze", 3), 0);
  const double u3 = s.number("nodeDisp", 2, 1);
  EXPECT_NEAR(10 * u3 - 10 * u3 * u3 * u3, 3.0, 1e-9);
  // Load factor 4 exceeds the peak: no equilibrium exists.
  EXPECT_LT(s.integer("analyze", 1), 0);
  EXPECT_EQ(s.number("nodeDisp", 2, 1), u3);
  EXPECT_EQ(s.number("getTime"), 3.0);
  EXPECT_EQ(std::get<std::vector<double>>(s("eleResponse", 1, "axialForce"))[0], 10 * u3 - 10 * u3 * u3 * u3);
  // Cut the step and go on: the usual retry loop works.
  s("integrator", "LoadControl", 0.5);
  EXPECT_EQ(s.integer("analyze", 1), 0);
  const double u35 = s.number("nodeDisp", 2, 1);
  EXPECT_NEAR(10 * u35 - 10 * u35 * u35 * u35, 3.5, 1e-9);
}

// analyze never throws (OpenSees' contract): a singular model is a failed
// step, -3, with a reason that names the dofs without stiffness.
TEST(StaticAnalysis, SingularModelIsAClearError) {
  registerTestTypes();
  Script s;
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 1.0, 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  s("element", "testSpring", 1, 1, 2, 10.0);  // node 2 free in y and z: a mechanism
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 2, 1.0, 0.0, 0.0);
  s("system", "UmfPack");
  s("analysis", "Static");
  EXPECT_EQ(s.integer("analyze", 1), -3);
  const std::string msg = s.interp.lastError();
  EXPECT_NE(msg.find("singular before any step converged"), std::string::npos) << msg;
  EXPECT_NE(msg.find("node 2 dof 2"), std::string::npos) << msg;
  EXPECT_EQ(s.number("nodeDisp", 2, 1), 0.0);
}

TEST(StaticAnalysis, CholmodRejectsIndefiniteMatrixAndSaysWhy) {
  registerTestTypes();
  Script s;
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 1.0, 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  s("fix", 2, 0, 1, 1);
  s("element", "testSpring", 1, 1, 2, -10.0);
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 2, 1.0, 0.0, 0.0);
  s("system", "Cholmod");
  s("analysis", "Static");
  EXPECT_EQ(s.integer("analyze", 1), -3);
  EXPECT_NE(s.interp.lastError().find("not positive definite"), std::string::npos) << s.interp.lastError();
  // UMFPACK solves the same (indefinite but regular) system.
  s("system", "UmfPack");
  EXPECT_EQ(s.integer("analyze", 1), 0);
  EXPECT_NEAR(s.number("nodeDisp", 2, 1), -0.1, 1e-14);
}

// A lever: node 1 rotates about z only; node 2 hangs on it by a rigid beam
// link at arm (0, 1, 0), so u2x = -theta_z. Node 3 (ndf 3) follows node 2 by
// equalDOF (a chain of MPs); spring 1 joins node 3 to node 4, spring 2 node 4
// to the fixed node 5. Load P at node 4: spring 2 carries it, spring 1 none,
// so u4x = P / k2 and theta_z = -u3x = -u4x.
TEST(StaticAnalysis, RigidBeamLinkTransformationMatchesPenalty) {
  registerTestTypes();
  double results[2][2];
  int k = 0;
  for (const char* handler : {"Transformation", "Penalty"}) {
    Script s;
    s("model", "basic", "-ndm", 3, "-ndf", 6);
    s("node", 1, 0.0, 0.0, 0.0);
    s("node", 2, 0.0, 1.0, 0.0);
    s("node", 3, 0.0, 1.0, 0.0, "-ndf", 3);
    s("node", 4, 1.0, 1.0, 0.0, "-ndf", 3);
    s("node", 5, 2.0, 1.0, 0.0, "-ndf", 3);
    s("fix", 1, 1, 1, 1, 1, 1, 0);
    s("fix", 4, 0, 1, 1);
    s("fix", 5, 1, 1, 1);
    s("rigidLink", "beam", 1, 2);
    s("equalDOF", 2, 3, 1, 2, 3);
    s("element", "testSpring", 1, 3, 4, 1000.0);
    s("element", "testSpring", 2, 4, 5, 500.0);
    s("timeSeries", "testLinear", 1);
    s("pattern", "Plain", 1, 1);
    s("load", 4, 3.0, 0.0, 0.0);
    if (std::string(handler) == "Penalty") s("constraints", "Penalty", 1e12, 1e12);
    else s("constraints", handler);
    s("system", "UmfPack");
    s("test", "NormDispIncr", 1e-12, 10);
    s("analysis", "Static");
    ASSERT_EQ(s.integer("analyze", 1), 0) << handler;
    results[k][0] = s.number("nodeDisp", 4, 1);
    results[k][1] = s.number("nodeDisp", 1, 6);
    ++k;
  }
  EXPECT_NEAR(results[0][0], 3.0 / 500.0, 1e-12);
  EXPECT_NEAR(results[0][1], -3.0 / 500.0, 1e-12);
  EXPECT_NEAR(results[1][0], results[0][0], 1e-8);
  EXPECT_NEAR(results[1][1], results[0][1], 1e-8);
}

namespace {
template <class T, class Table>
std::unique_ptr<T> buildFrom(const Table& table, Domain& d, std::vector<CommandArgs::Value> args) {
  CommandArgs a("test", std::move(args));
  return table.build(a, d);
}
}  // namespace

// The pattern is built once per model change and the solver's symbolic
// analysis reused while it holds; numeric factorization happens per iteration.
TEST(StaticAnalysis, SymbolicAnalysisIsReusedUntilTheModelChanges) {
  registerTestTypes();
  Script s;  // only to build the model through commands
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  for (int i = 1; i <= 4; ++i) s("node", i, double(i - 1), 0.0, 0.0);
  s("fix", 1, 1, 1, 1);
  for (int i = 2; i <= 4; ++i) s("fix", i, 0, 1, 1);
  s("element", "testSpring", 1, 1, 2, 10.0, 50.0);
  s("element", "testSpring", 2, 2, 3, 10.0, 50.0);
  s("element", "testSpring", 3, 3, 4, 10.0, 50.0);
  s("timeSeries", "testLinear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 4, 2.0, 0.0, 0.0);
  Domain& domain = s.interp.domain();
  Registry& r = Registry::global();
  for (const char* system : {"UmfPack", "Cholmod"}) {
    AnalysisComponents c;
    c.handler = buildFrom<ConstraintHandler>(r.constraintHandlers, domain, {std::string("Transformation")});
    c.numberer = buildFrom<Numberer>(r.numberers, domain, {std::string("RCM")});
    c.solver = buildFrom<LinearSolver>(r.systems, domain, {std::string(system)});
    c.test = buildFrom<ConvergenceTest>(r.tests, domain, {std::string("NormDispIncr"), 1e-12, 20LL});
    c.algorithm = buildFrom<Algorithm>(r.algorithms, domain, {std::string("Newton")});
    c.integrator = buildFrom<Integrator>(r.integrators, domain, {std::string("LoadControl"), 0.1});
    StaticAnalysis analysis(domain, c);
    int iterations = 0;
    for (int step = 0; step < 5; ++step) {
      ASSERT_EQ(analysis.analyze(1), 0);
      iterations += c.test->numIterations();
    }
    EXPECT_EQ(c.solver->numAnalyze(), 1) << system;
    EXPECT_EQ(c.solver->numFactorize(), iterations) << system;
    // A new element changes the pattern: one more symbolic analysis.
    s("node", 5, 4.0, 0.0, 0.0);
    s("fix", 5, 0, 1, 1);
    s("element", "testSpring", 10, 4, 5, 10.0);
    ASSERT_EQ(analysis.analyze(1), 0);
    EXPECT_EQ(c.solver->numAnalyze(), 2) << system;
    s("remove", "element", 10);
    s("remove", "node", 5);
    domain.revertToStart();
  }
}
