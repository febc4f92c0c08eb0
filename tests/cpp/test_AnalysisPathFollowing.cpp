// DisplacementControl and ArcLength on springs with limit points, against
// the exact equilibrium curves; failed steps revert exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "AnalysisTestSupport.h"
#include "analysis/ArcLength.h"

using namespace beamsolid;
using namespace beamsolid::analysistest;

namespace {

// Softening spring with a limit point: f = k d / (1 + (d/d0)^2), peak k d0 / 2 at d = d0.
SpringLaw softening(double k, double d0) {
  return {[=](double d) { return k * d / (1.0 + d * d / (d0 * d0)); },
          [=](double d) {
            const double r = d * d / (d0 * d0);
            return k * (1.0 - r) / ((1.0 + r) * (1.0 + r));
          }};
}

// Snap-through spring (a shallow-arch-like cubic): f = k d (d - c)(d - 2c) / c^2,
// up to a limit point at d = c (1 - 1/sqrt 3), down through zero at c, a
// minimum at c (1 + 1/sqrt 3), and up again beyond 2c.
SpringLaw snapThrough(double k, double c) {
  return {[=](double d) { return k * d * (d - c) * (d - 2.0 * c) / (c * c); },
          [=](double d) { return k * (3.0 * d * d - 6.0 * c * d + 2.0 * c * c) / (c * c); }};
}

// node 1 fixed -- spring 1 -- node 2, load P at node 2.
void buildSingleSpring(Model& m, SpringLaw law, double P) {
  m.addNode(1, 0.0);
  m.fixX(1);
  m.addNode(2, 1.0);
  m.addSpring(1, 1, 2, std::move(law));
  m.addLoad(2, P);
}

// node 1 fixed -- nonlinear spring -- node 2 -- linear spring k2 -- node 3, load P at node 3.
void buildSeries(Model& m, SpringLaw law, double k2, double P) {
  m.addNode(1, 0.0);
  m.fixX(1);
  m.addNode(2, 1.0);
  m.addNode(3, 2.0);
  m.addSpring(1, 1, 2, std::move(law));
  m.addSpring(2, 2, 3, linearLaw(k2));
  m.addLoad(3, P);
}

struct State {
  std::vector<double> disp;
  double time;
};
State snapshot(const Model& m) {
  State s{{}, m.domain.currentTime()};
  for (const auto& [tag, n] : m.domain.nodes()) s.disp.insert(s.disp.end(), n->trialDisp().begin(), n->trialDisp().end());
  return s;
}

}  // namespace

// Single spring: the load factor at displacement u is f(u) / P in closed
// form, before and after the limit point at u = d0 (which LoadControl
// cannot pass, see below). Tolerances: the controlled displacement exact to
// 1e-14; lambda to 1e-10 (NormUnbalance 1e-11 with P = 2).
TEST(AnalysisPathFollowing, DisplacementControlPassesLimitPointOfSofteningSpring) {
  const double k = 100.0, d0 = 0.05, P = 2.0, incr = 0.007;
  const SpringLaw law = softening(k, d0);
  Model m;
  buildSingleSpring(m, law, P);
  m.analyzeWith("Newton", {}, "DisplacementControl", {2LL, 1LL, incr}, 1e-11);
  for (int step = 1; step <= 15; ++step) {
    ASSERT_EQ(m.analyze(1), 0) << "step " << step;
    const double u = m.disp(2);
    EXPECT_NEAR(u, step * incr, 1e-14);
    EXPECT_NEAR(m.domain.currentTime(), law.force(u) / P, 1e-10) << "step " << step;
  }
  EXPECT_GT(m.disp(2), 2.0 * d0);  // well past the peak, on the descending branch
  EXPECT_LT(m.domain.currentTime(), 0.5 * k * d0 / P);
}

// Two springs in series, control at the free end: the end reaches its
// target exactly and both springs carry lambda P (1e-9).
TEST(AnalysisPathFollowing, DisplacementControlSeriesSpringsEquilibrium) {
  const double k2 = 50.0, P = 1.0;
  const SpringLaw law = softening(100.0, 0.05);
  for (const char* algorithm : {"Newton", "NewtonLineSearch", "KrylovNewton"}) {
    Model m;
    buildSeries(m, law, k2, P);
    m.analyzeWith(algorithm, {}, "DisplacementControl", {3LL, 1LL, 0.01}, 1e-11);
    for (int step = 1; step <= 20; ++step) {
      ASSERT_EQ(m.analyze(1), 0) << algorithm << " step " << step;
      const double lambda = m.domain.currentTime();
      EXPECT_NEAR(m.disp(3), 0.01 * step, 1e-13) << algorithm;
      EXPECT_NEAR(lambda * P, law.force(m.disp(2)), 1e-9) << algorithm << " step " << step;
      EXPECT_NEAR(lambda * P, k2 * (m.disp(3) - m.disp(2)), 1e-9) << algorithm << " step " << step;
    }
  }
}

TEST(AnalysisPathFollowing, DisplacementControlChecksNodeAndDof) {
  auto expectError = [](Args integratorArgs, const std::string& fragment) {
    Model m;
    buildSingleSpring(m, linearLaw(1.0), 1.0);
    m.analyzeWith("Newton", {}, "DisplacementControl", std::move(integratorArgs));
    // Found when the analysis is set up for the model: -1, never a throw.
    EXPECT_EQ(m.analyze(1), -1) << fragment;
    EXPECT_NE(m.analysis->lastError().find(fragment), std::string::npos) << m.analysis->lastError();
    EXPECT_EQ(m.domain.currentTime(), 0.0);
    EXPECT_EQ(m.disp(2), 0.0);
  };
  expectError({99LL, 1LL, 0.1}, "integrator DisplacementControl: node 99 does not exist");
  expectError({2LL, 4LL, 0.1}, "dof 4 is out of range for node 2 (ndf 3)");
  expectError({1LL, 1LL, 0.1}, "node 1 dof 1 is fixed");
  expectError({2LL, 2LL, 0.1}, "node 2 dof 2 is fixed");
  Model m;
  EXPECT_THROW(build<Integrator>(Registry::global().integrators, m.domain, "DisplacementControl", {2LL, 0LL, 0.1}),
               OpenSeesError);
  EXPECT_THROW(build<Integrator>(Registry::global().integrators, m.domain, "DisplacementControl", {2LL, 1LL}),
               OpenSeesError);
}

// LoadControl cannot go past the peak load k d0 / 2 = 2.5: the step to 3.0
// fails and leaves displacements and time exactly (bitwise) at the last commit.
TEST(AnalysisPathFollowing, LoadControlFailsAtLimitPointAndRevertsExactly) {
  Model m;
  buildSingleSpring(m, softening(100.0, 0.05), 1.0);
  m.analyzeWith("Newton", {}, "LoadControl", {0.6}, 1e-10, 30);
  ASSERT_EQ(m.analyze(4), 0);
  const State before = snapshot(m);
  EXPECT_NEAR(before.time, 2.4, 1e-15);
  EXPECT_LT(m.analyze(1), 0);
  const State after = snapshot(m);
  EXPECT_EQ(after.time, before.time);
  EXPECT_EQ(m.domain.committedTime(), before.time);
  EXPECT_EQ(after.disp, before.disp);
  EXPECT_EQ(m.domain.node(2, "test").committedDisp()[0], before.disp[3]);
}

// A failed step (forced with a one-iteration test) leaves the model exactly
// at the last commit, and the analysis then continues as if it had never
// happened: same path as an uninterrupted run (1e-12).
TEST(AnalysisPathFollowing, FailedStepRevertsCleanlyForEveryIntegrator) {
  struct Case {
    const char* integrator;
    Args args;
  };
  const std::vector<Case> cases = {{"LoadControl", {0.3}},
                                   {"DisplacementControl", {3LL, 1LL, 0.01}},
                                   {"ArcLength", {0.02, 1.0}}};
  const SpringLaw law = softening(100.0, 0.05);
  for (const auto& c : cases) {
    Model reference, interrupted;
    for (Model* m : {&reference, &interrupted}) {
      buildSeries(*m, law, 50.0, 1.0);
      m->analyzeWith("Newton", {}, c.integrator, c.args, 1e-11);
    }
    ASSERT_EQ(reference.analyze(6), 0) << c.integrator;
    ASSERT_EQ(interrupted.analyze(3), 0) << c.integrator;
    const State committed = snapshot(interrupted);
    interrupted.setTest(1e-300, 1);  // cannot converge in one iteration
    EXPECT_EQ(interrupted.analyze(1), -3) << c.integrator;
    const State reverted = snapshot(interrupted);
    EXPECT_EQ(reverted.time, committed.time) << c.integrator;
    EXPECT_EQ(reverted.disp, committed.disp) << c.integrator;
    interrupted.setTest(1e-11, 50);
    ASSERT_EQ(interrupted.analyze(3), 0) << c.integrator;
    const State a = snapshot(reference), b = snapshot(interrupted);
    EXPECT_NEAR(a.time, b.time, 1e-12) << c.integrator;
    for (std::size_t i = 0; i < a.disp.size(); ++i) EXPECT_NEAR(a.disp[i], b.disp[i], 1e-12) << c.integrator;
  }
}

// Snap-through: lambda rises to 0.3849 k c / P, falls to -0.3849, rises
// again. ArcLength follows the whole curve, each converged point on it
// (NormUnbalance 1e-11: |lambda P - f| <= 1e-10) and at arc length s from
// the previous one (1e-10); LoadControl never produces a point on the
// descending branch.
TEST(AnalysisPathFollowing, ArcLengthFollowsSnapThroughThatLoadControlCannot) {
  const double k = 1.0, c = 1.0, k2 = 10.0, P = 1.0, s = 0.05, alpha = 1.0;
  const SpringLaw law = snapThrough(k, c);
  const double peak = k * c * 2.0 / (3.0 * std::sqrt(3.0));  // f at c (1 - 1/sqrt 3)
  for (const char* algorithm : {"Newton", "NewtonLineSearch", "KrylovNewton"}) {
    Model m;
    buildSeries(m, law, k2, P);
    m.analyzeWith(algorithm, {}, "ArcLength", {s, alpha}, 1e-11);
    double maxLambda = -1e9, minLambda = 1e9;
    int descending = 0, steps = 0;
    double u2 = 0.0, u3 = 0.0, lambda = 0.0;
    while (m.disp(2) < 2.3 * c && steps < 400) {
      ASSERT_EQ(m.analyze(1), 0) << algorithm << " step " << steps + 1;
      ++steps;
      const double l = m.domain.currentTime();
      EXPECT_NEAR(l * P, law.force(m.disp(2)), 1e-10) << algorithm << " step " << steps;
      EXPECT_NEAR(l * P, k2 * (m.disp(3) - m.disp(2)), 1e-10) << algorithm << " step " << steps;
      const double du2 = m.disp(2) - u2, du3 = m.disp(3) - u3, dl = l - lambda;
      EXPECT_NEAR(std::sqrt(du2 * du2 + du3 * du3 + alpha * alpha * dl * dl), s, 1e-10) << algorithm;
      EXPECT_GT(du2, 0.0) << algorithm << ": the path must keep going forward";
      if (law.stiffness(m.disp(2)) < 0.0) ++descending;
      u2 = m.disp(2);
      u3 = m.disp(3);
      lambda = l;
      if (u2 < 2.0 * c) maxLambda = std::max(maxLambda, l);  // the first hump
      minLambda = std::min(minLambda, l);
    }
    EXPECT_GT(m.disp(2), 2.3 * c) << algorithm;
    EXPECT_GT(maxLambda, 0.99 * peak) << algorithm;
    EXPECT_LE(maxLambda, peak + 1e-10) << algorithm;
    EXPECT_LT(minLambda, -0.99 * peak) << algorithm;
    EXPECT_GT(descending, 10) << algorithm;
    EXPECT_GT(lambda, 0.0) << algorithm;  // back on the rising branch
    const auto* arc = dynamic_cast<const ArcLength*>(m.components.integrator.get());
    ASSERT_NE(arc, nullptr);
    EXPECT_EQ(arc->complexRootIterations(), 0) << algorithm;
  }

  // LoadControl: lambda only grows, so past the peak it must jump (or fail).
  Model m;
  buildSeries(m, law, k2, P);
  m.analyzeWith("Newton", {}, "LoadControl", {0.05}, 1e-11, 100);
  int code = 0;
  for (int step = 0; step < 10 && code == 0; ++step) {
    code = m.analyze(1);
    if (code == 0) {
      EXPECT_GE(law.stiffness(m.disp(2)), 0.0) << "LoadControl found a point on the descending branch";
      EXPECT_NEAR(m.domain.currentTime() * P, law.force(m.disp(2)), 1e-10);
    }
  }
  EXPECT_TRUE(code < 0 || m.disp(2) > 2.0 * c) << "LoadControl should snap or fail past lambda = " << peak;
}

TEST(AnalysisPathFollowing, ArcLengthArgumentsAndZeroReferenceLoad) {
  Model m;
  EXPECT_THROW(build<Integrator>(Registry::global().integrators, m.domain, "ArcLength", {-1.0, 1.0}), OpenSeesError);
  EXPECT_THROW(build<Integrator>(Registry::global().integrators, m.domain, "ArcLength", {1.0}), OpenSeesError);
  // No load pattern: there is no path to follow.
  m.addNode(1, 0.0);
  m.fixX(1);
  m.addNode(2, 1.0);
  m.addSpring(1, 1, 2, linearLaw(1.0));
  m.analyzeWith("Newton", {}, "ArcLength", {0.1, 1.0});
  EXPECT_LT(m.analyze(1), 0);
  EXPECT_NE(m.analysis->lastError().find("reference load is zero"), std::string::npos) << m.analysis->lastError();
}
