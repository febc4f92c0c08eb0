// ContactMaterial3D (beam_contact_formulation.md C13-C16): stick T = G m s,
// slip onset at exactly mu N + c, plateau, elastic unloading with slope G,
// reversed loading, dissipation, consistent tangent against finite
// differences, tension cut-off, frictionless stage, revert exactness and the
// command's checks. A non-diagonal metric is used throughout so that the
// covariant/contravariant bookkeeping is exercised.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "materials/nd/ContactMaterial3D.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using Vector2 = Eigen::Vector2d;
using Matrix2 = Eigen::Matrix2d;

// A surface metric like the pile's: |g_xi|^2 ~ L^2, |g_psi|^2 ~ R^2, slightly skew.
Matrix2 testMetric() {
  Matrix2 m;
  m << 4.0, 0.3, 0.3, 0.09;
  return m;
}

double normIn(const Matrix2& m, const Vector2& s) { return std::sqrt(s.dot(m * s)); }
// |T| of a covariant traction: sqrt(T . m^-1 T).
double tractionNorm(const Matrix2& m, const Vector2& T) { return std::sqrt(T.dot(m.inverse() * T)); }

using beamsolid::testsupport::errorOf;

constexpr double mu = 0.4, G = 1500.0, c = 3.0, t = 2.0;

}  // namespace

TEST(ContactMaterial3D, StickingTractionIsGTimesMetricTimesSlip) {
  ContactMaterial3D mat(1, mu, G, c, t);
  const Matrix2 m = testMetric();
  const double N = 100.0;
  const Vector2 s(0.002, -0.01);  // |s|_m well below (mu N + c)/G
  ASSERT_LT(G * normIn(m, s), mu * N + c);
  mat.setTrialState(0.0, s, N, m);
  EXPECT_FALSE(mat.sliding());
  const Vector2 expected = G * m * s;
  EXPECT_LE((mat.traction() - expected).norm(), 1e-13 * expected.norm());
  EXPECT_LE((mat.tangentSlip() - G * m).norm(), 1e-13 * G);
  EXPECT_EQ(mat.tangentNormal(), Vector2::Zero());
  EXPECT_EQ(mat.dissipation(), 0.0);
  EXPECT_NEAR(mat.tractionNorm(), G * normIn(m, s), 1e-12 * G * normIn(m, s));
}

TEST(ContactMaterial3D, SlidingStartsAtExactlyMuNPlusC) {
  ContactMaterial3D mat(1, mu, G, c, t);
  const Matrix2 m = testMetric();
  const double N = 50.0;
  const double capacity = mu * N + c;
  const Vector2 direction = Vector2(1.0, 2.0) / normIn(m, Vector2(1.0, 2.0));  // unit in the metric
  const double onset = capacity / G;                                          // |s|_m at first slip
  mat.setTrialState(0.0, (1.0 - 1e-9) * onset * direction, N, m);
  EXPECT_FALSE(mat.sliding());
  EXPECT_NEAR(tractionNorm(m, mat.traction()), (1.0 - 1e-9) * capacity, 1e-12 * capacity);
  mat.setTrialState(0.0, (1.0 + 1e-9) * onset * direction, N, m);
  EXPECT_TRUE(mat.sliding());
  EXPECT_NEAR(tractionNorm(m, mat.traction()), capacity, 1e-12 * capacity);
  // The traction stays along the (covariant) trial direction m s.
  const Vector2 along = m * direction;
  EXPECT_LE((mat.traction() - capacity * along).norm(), 1e-12 * capacity * along.norm());
}

TEST(ContactMaterial3D, PlateauElasticUnloadingAndReversedLoading) {
  ContactMaterial3D mat(1, mu, G, c, t);
  const Matrix2 m = testMetric();
  const double N = 20.0;
  const double capacity = mu * N + c;
  const Vector2 e = Vector2(1.0, -0.5) / normIn(m, Vector2(1.0, -0.5));
  const double ds = 0.25 * capacity / G;  // four steps to the onset

  // Monotonic loading in committed steps: linear then a plateau at mu N + c.
  double slipTotal = 0.0;
  for (int step = 1; step <= 12; ++step) {
    mat.setTrialState(0.0, ds * e, N, m);
    slipTotal += ds;
    const double expected = std::min(G * slipTotal, capacity);
    EXPECT_NEAR(tractionNorm(m, mat.traction()), expected, 1e-11 * capacity) << "step " << step;
    EXPECT_EQ(mat.sliding(), G * slipTotal > capacity * (1 + 1e-12)) << "step " << step;
    mat.commitState();
  }
  // The elastic slip sits on the cone: |s_e|_m = capacity / G.
  EXPECT_NEAR(normIn(m, mat.committedElasticSlip()), capacity / G, 1e-12 * capacity / G);

  // Elastic unloading: the traction drops with slope G in the metric.
  const Vector2 back = -0.3 * ds * e;
  mat.setTrialState(0.0, back, N, m);
  EXPECT_FALSE(mat.sliding());
  EXPECT_LE((mat.traction() - (capacity * m * e + G * m * back)).norm(), 1e-11 * capacity);
  EXPECT_LE((mat.tangentSlip() - G * m).norm(), 1e-12 * G);

  // Reversed loading: sliding the other way starts after a reversal of
  // 2 capacity / G and the traction then equals -capacity along e.
  const double reversal = 2.0 * capacity / G;
  mat.setTrialState(0.0, -(1.0 - 1e-9) * reversal * e, N, m);
  EXPECT_FALSE(mat.sliding());
  mat.setTrialState(0.0, -(1.0 + 1e-6) * reversal * e, N, m);
  EXPECT_TRUE(mat.sliding());
  EXPECT_LE((mat.traction() + capacity * m * e).norm(), 1e-11 * capacity);
  mat.setTrialState(0.0, -3.0 * reversal * e, N, m);
  EXPECT_LE((mat.traction() + capacity * m * e).norm(), 1e-11 * capacity);
}

TEST(ContactMaterial3D, DissipationIsNeverNegativeAndMatchesClosedForm) {
  // A closed slip cycle along one direction: after the first half the loop
  // dissipates capacity times the plastic slip of each sweep.
  ContactMaterial3D mat(1, mu, G, c, t);
  const Matrix2 m = testMetric();
  const double N = 30.0, capacity = mu * N + c;
  const Vector2 e = Vector2(0.3, 1.0) / normIn(m, Vector2(0.3, 1.0));
  const double amplitude = 5.0 * capacity / G;
  const int stepsPerSweep = 40;
  double total = 0.0, position = 0.0;
  auto sweep = [&](double target) {
    const double ds = (target - position) / stepsPerSweep;
    for (int k = 0; k < stepsPerSweep; ++k) {
      mat.setTrialState(0.0, ds * e, N, m);
      EXPECT_GE(mat.dissipation(), -1e-14 * capacity * std::abs(ds));
      total += mat.dissipation();
      mat.commitState();
      position += ds;
    }
  };
  sweep(amplitude);   // plastic slip amplitude - capacity/G
  sweep(-amplitude);  // plastic slip 2 amplitude - 2 capacity/G
  sweep(amplitude);
  const double expected = capacity * ((amplitude - capacity / G) + 2.0 * (2.0 * amplitude - 2.0 * capacity / G));
  EXPECT_NEAR(total, expected, 1e-10 * expected);

  // A random two-dimensional path, with varying normal force.
  ContactMaterial3D path(2, mu, G, c, t);
  std::srand(7);
  for (int k = 0; k < 300; ++k) {
    const Vector2 ds = Vector2::Random() * 0.6 * capacity / G;
    const double n = 5.0 + 40.0 * (0.5 + 0.5 * Vector2::Random()(0));
    path.setTrialState(0.0, ds, n, m);
    EXPECT_GE(path.dissipation(), -1e-13 * capacity * normIn(m, ds)) << "step " << k;
    path.commitState();
  }
}

namespace {

// Central differences of the traction with respect to the slip and t_n.
void expectConsistentTangent(ContactMaterial3D& mat, const Vector2& s, double N, const Matrix2& m) {
  const double h = 1e-7 * std::max(s.norm(), 1e-3);
  Matrix2 dTds;
  for (int j = 0; j < 2; ++j) {
    Vector2 sp = s, sm = s;
    sp(j) += h;
    sm(j) -= h;
    mat.setTrialState(0.0, sp, N, m);
    const Vector2 Tp = mat.traction();
    mat.setTrialState(0.0, sm, N, m);
    dTds.col(j) = (Tp - mat.traction()) / (2.0 * h);
  }
  const double hN = 1e-6 * N;
  mat.setTrialState(0.0, s, N + hN, m);
  const Vector2 Tp = mat.traction();
  mat.setTrialState(0.0, s, N - hN, m);
  const Vector2 dTdN = (Tp - mat.traction()) / (2.0 * hN);
  mat.setTrialState(0.0, s, N, m);
  const double scale = G * m.norm();
  EXPECT_LE((mat.tangentSlip() - dTds).norm(), 1e-6 * scale) << "dT/ds\n" << mat.tangentSlip() << "\nfd\n" << dTds;
  EXPECT_LE((mat.tangentNormal() - dTdN).norm(), 1e-6 * (mu * m.norm() + 1e-12))
      << "dT/dtn " << mat.tangentNormal().transpose() << " fd " << dTdN.transpose();
}

}  // namespace

TEST(ContactMaterial3D, ConsistentTangentMatchesFiniteDifferences) {
  const Matrix2 m = testMetric();
  const double N = 40.0, capacity = mu * N + c;
  {
    SCOPED_TRACE("sticking");
    ContactMaterial3D mat(1, mu, G, c, t);
    const Vector2 s = Vector2(0.2, -0.7) * 0.5 * capacity / G / normIn(m, Vector2(0.2, -0.7));
    mat.setTrialState(0.0, s, N, m);
    ASSERT_FALSE(mat.sliding());
    expectConsistentTangent(mat, s, N, m);
  }
  {
    SCOPED_TRACE("sliding from a virgin state");
    ContactMaterial3D mat(1, mu, G, c, t);
    const Vector2 s = Vector2(0.2, -0.7) * 3.0 * capacity / G / normIn(m, Vector2(0.2, -0.7));
    mat.setTrialState(0.0, s, N, m);
    ASSERT_TRUE(mat.sliding());
    expectConsistentTangent(mat, s, N, m);
  }
  {
    SCOPED_TRACE("sliding sideways from a committed elastic slip");
    ContactMaterial3D mat(1, mu, G, c, t);
    mat.setTrialState(0.0, Vector2(0.6, 0.0) * capacity / G, N, m);
    mat.commitState();
    const Vector2 s = Vector2(-0.1, 2.5) * capacity / G;
    mat.setTrialState(0.0, s, N, m);
    ASSERT_TRUE(mat.sliding());
    expectConsistentTangent(mat, s, N, m);
  }
}

TEST(ContactMaterial3D, TensionBeyondTheStrengthReleasesAndResetsTheElasticSlip) {
  // t = 10 exceeds the cone apex c/mu = 7.5: the strength in use is 7.5.
  ContactMaterial3D mat(1, mu, G, c, 10.0);
  EXPECT_DOUBLE_EQ(mat.tensileStrength(), c / mu);
  const Matrix2 m = testMetric();
  mat.setTrialState(0.0, Vector2(1e-4, 0.0), 10.0, m);
  mat.commitState();
  ASSERT_GT(mat.committedElasticSlip().norm(), 0.0);
  // In tension inside the strength: friction capacity mu t_n + c > 0 remains.
  mat.setTrialState(0.0, Vector2::Zero(), -5.0, m);
  EXPECT_NEAR(mat.slipResistance(), c - mu * 5.0, 1e-14);
  EXPECT_GT(mat.traction().norm(), 0.0);
  // At the strength: no traction, no stiffness, elastic slip reset.
  mat.setTrialState(0.0, Vector2(2e-4, 1e-4), -7.5, m);
  EXPECT_EQ(mat.traction(), Vector2::Zero());
  EXPECT_EQ(mat.tangentSlip(), Matrix2::Zero());
  EXPECT_EQ(mat.elasticSlip(), Vector2::Zero());
  EXPECT_EQ(mat.dissipation(), 0.0);
  mat.commitState();
  // Back in compression the friction starts from zero elastic slip.
  const Vector2 s(1e-4, -2e-4);
  mat.setTrialState(0.0, s, 10.0, m);
  EXPECT_LE((mat.traction() - G * m * s).norm(), 1e-13 * G);
}

TEST(ContactMaterial3D, FrictionlessStageGivesNoTractionAndIsPerCopy) {
  ContactMaterial3D prototype(1, mu, G, c, t);
  auto copy = prototype.clone("ContactMaterial3D");
  ASSERT_TRUE(copy);
  auto& mat = dynamic_cast<ContactMaterial3D&>(*copy);
  const Matrix2 m = testMetric();
  mat.updateStage(0);
  EXPECT_FALSE(mat.frictional());
  EXPECT_TRUE(prototype.frictional());
  mat.setTrialState(0.0, Vector2(1e-3, 1e-3), 100.0, m);
  EXPECT_EQ(mat.traction(), Vector2::Zero());
  EXPECT_EQ(mat.tangentSlip(), Matrix2::Zero());
  EXPECT_EQ(mat.tangentNormal(), Vector2::Zero());
  EXPECT_EQ(mat.dissipation(), 0.0);
  mat.commitState();
  // Friction switched on through setParameter: sticking from zero elastic slip.
  EXPECT_TRUE(mat.setParameter({"friction"}, 1.0));
  EXPECT_TRUE(mat.frictional());
  const Vector2 s(1e-4, 0.0);
  mat.setTrialState(0.0, s, 100.0, m);
  EXPECT_LE((mat.traction() - G * m * s).norm(), 1e-13 * G);
  EXPECT_TRUE(mat.setParameter({"friction"}, 0.0));
  EXPECT_FALSE(mat.frictional());
  EXPECT_NE(errorOf([&] { mat.updateStage(2); }).find("must be 0 (frictionless) or 1"), std::string::npos);
  EXPECT_NE(errorOf([&] { mat.setParameter({"friction"}, 0.5); }).find("nDMaterial ContactMaterial3D 1"),
            std::string::npos);
  EXPECT_FALSE(mat.setParameter({"E"}, 1.0));
}

TEST(ContactMaterial3D, RevertToLastCommitReproducesTheTrialStateExactly) {
  ContactMaterial3D mat(1, mu, G, c, t);
  const Matrix2 m = testMetric();
  mat.setTrialState(0.0, Vector2(0.004, -0.001), 25.0, m);
  mat.commitState();
  const Vector2 s(0.01, 0.02);
  mat.setTrialState(0.0, s, 25.0, m);
  const Vector2 T = mat.traction();
  const Matrix2 K = mat.tangentSlip();
  const Vector2 Kn = mat.tangentNormal();
  const bool sliding = mat.sliding();
  // Wander off, revert, and repeat the same trial: bit-for-bit the same.
  mat.setTrialState(0.0, Vector2(-0.3, 0.5), 2.0, m);
  mat.revertToLastCommit();
  EXPECT_EQ(mat.elasticSlip(), mat.committedElasticSlip());
  mat.setTrialState(0.0, s, 25.0, m);
  EXPECT_EQ(mat.traction(), T);
  EXPECT_EQ(mat.tangentSlip(), K);
  EXPECT_EQ(mat.tangentNormal(), Kn);
  EXPECT_EQ(mat.sliding(), sliding);
  // Back to the start: no memory left.
  mat.revertToStart();
  mat.setTrialState(0.0, Vector2(1e-5, 0.0), 25.0, m);
  EXPECT_LE((mat.traction() - G * m * Vector2(1e-5, 0.0)).norm(), 1e-14 * G);
}

namespace {

// Newton's method on a friction node held by a spring of stiffness k (per
// unit slip, in the metric): k m s + T(s) = f (covariant). `guarded` uses
// setIterate (the contact elements' call), otherwise the plain return map
// setTrialState. Returns the residual norms |r| after each correction.
std::vector<double> springNewton(ContactMaterial3D& mat, bool guarded, double k, const Vector2& f, double N,
                                 const Matrix2& m, Vector2 s, int iterations) {
  std::vector<double> norms;
  auto evaluate = [&](const Vector2& slip) {
    if (guarded) mat.setIterate(0.0, slip, N, m);
    else mat.setTrialState(0.0, slip, N, m);
    return Vector2(k * m * slip + mat.traction() - f);
  };
  Vector2 r = evaluate(s);
  for (int i = 0; i < iterations; ++i) {
    const Matrix2 K = k * m + mat.tangentSlip();
    s -= K.fullPivLu().solve(r);
    r = evaluate(s);
    norms.push_back(tractionNorm(m, r));
  }
  return norms;
}

}  // namespace

// The lateral pile's failure in one node: a stiff stick (band |s_e| <
// mu N / G far narrower than the spring's own slip under the friction force,
// mu N / k) and a load inside the friction capacity, so that the node truly
// sticks. Newton started on the sliding side: the plain return map gives a
// zero tangent along the slip, each correction overshoots the band to the
// other side and the iteration cycles for ever between sliding up and down
// (closed form: s alternates between (f - R)/k and (f + R)/k, the residual is 2 R). setIterate
// holds the reversing node sticking once; the stick system is linear, so
// the next iterate is the exact solution s = f / ((k + G) m).
TEST(ContactMaterial3D, IterateHoldsAReversingNodeStickingInsteadOfCycling) {
  const Matrix2 m = testMetric();
  const double stiffG = 1e6, k = 1e4, N = 2.0, capacity = mu * N;  // no cohesion: c = t = 0
  const Vector2 e = Vector2(1.0, -0.5) / normIn(m, Vector2(1.0, -0.5));
  const Vector2 f = 0.3 * capacity * m * e;
  const Vector2 start = 5.0 * capacity / k * e;  // sliding along +e
  const Vector2 exact = 0.3 * capacity / (k + stiffG) * e;
  ASSERT_LT(stiffG * normIn(m, exact), capacity);  // the solution sticks
  {
    SCOPED_TRACE("plain return map: cycles");
    ContactMaterial3D mat(1, mu, stiffG, 0.0, 0.0);
    const std::vector<double> norms = springNewton(mat, false, k, f, N, m, start, 20);
    // Both states of the cycle are off balance by the jump of the friction force, 2 R.
    EXPECT_NEAR(norms[18], 2.0 * capacity, 1e-9 * capacity);
    EXPECT_NEAR(norms[19], 2.0 * capacity, 1e-9 * capacity);
    EXPECT_TRUE(mat.sliding());
  }
  {
    SCOPED_TRACE("setIterate: converges");
    ContactMaterial3D mat(1, mu, stiffG, 0.0, 0.0);
    const std::vector<double> norms = springNewton(mat, true, k, f, N, m, start, 3);
    EXPECT_GT(norms[0], capacity);  // held sticking after the reversal: far from balanced
    EXPECT_LE(norms[1], 1e-12 * capacity);
    EXPECT_LE(norms[2], 1e-12 * capacity);
    EXPECT_FALSE(mat.sliding());
    EXPECT_FALSE(mat.heldSticking());
    EXPECT_LE(normIn(m, mat.elasticSlip() - exact), 1e-10 * normIn(m, exact));
  }
  {
    SCOPED_TRACE("setIterate: a truly sliding node slides at once");
    ContactMaterial3D mat(1, mu, stiffG, 0.0, 0.0);
    const Vector2 load = 3.0 * capacity * m * e;
    const std::vector<double> norms = springNewton(mat, true, k, load, N, m, Vector2::Zero(), 3);
    EXPECT_LE(norms[1], 1e-12 * capacity);
    EXPECT_TRUE(mat.sliding());
    EXPECT_NEAR(tractionNorm(m, mat.traction()), capacity, 1e-12 * capacity);
  }
}

// A smooth interface (mu = 0, c = 0) under compression: no strength, so a
// sliding node carries no traction and has no direction.
// The guard must leave it to the return map; it used to hold every other
// iterate sticking (direction zero, 0 <= 0), and a confined smooth pile's
// Newton cycled between two states (the lateral capacity slice).
TEST(ContactMaterial3D, IterateWithNoStrengthNeverHoldsANode) {
  const Matrix2 m = testMetric();
  const double stiffG = 1e6, k = 1e4;
  const Vector2 e = Vector2(1.0, -0.5) / normIn(m, Vector2(1.0, -0.5));
  const Vector2 f = 5.0 * m * e;
  for (const double N : {10.0, 1e-3}) {
    SCOPED_TRACE(N);
    ContactMaterial3D mat(1, 0.0, stiffG, 0.0, 0.0);
    for (double sign : {1.0, -1.0, 1.0, -2.0}) {
      mat.setIterate(0.0, sign * 1e-3 * e, N, m);
      EXPECT_FALSE(mat.heldSticking());
      EXPECT_TRUE(mat.sliding());
      EXPECT_EQ(mat.traction().norm(), 0.0);
      EXPECT_EQ(mat.tangentSlip().norm(), 0.0);
    }
    // Newton on a spring: converged after the first correction (the interface adds nothing).
    ContactMaterial3D fresh(1, 0.0, stiffG, 0.0, 0.0);
    const std::vector<double> norms = springNewton(fresh, true, k, f, N, m, -1e-3 * e, 3);
    EXPECT_LE(norms[0], 1e-12 * f.norm());
    EXPECT_LE(norms[2], 1e-12 * f.norm());
  }
}

TEST(ContactMaterial3D, IterateIsRepeatableAndForgetsAtCommitAndRevert) {
  const Matrix2 m = testMetric();
  const double N = 10.0, capacity = mu * N + c;
  const Vector2 e = Vector2(0.4, 1.0) / normIn(m, Vector2(0.4, 1.0));
  ContactMaterial3D mat(1, mu, G, c, t);
  mat.setIterate(0.0, 4.0 * capacity / G * e, N, m);  // slides along +e
  ASSERT_TRUE(mat.sliding());
  const Vector2 back = -3.0 * capacity / G * e;       // the return map slides along -e
  mat.setIterate(0.0, back, N, m);
  EXPECT_TRUE(mat.heldSticking());
  const Vector2 held = mat.traction();
  EXPECT_LE((held - G * m * back).norm(), 1e-12 * G * m.norm() * normIn(m, back));
  EXPECT_LE((mat.tangentSlip() - G * m).norm(), 1e-12 * G);
  // The same input again: the same answer (an integrator may update twice).
  mat.setIterate(0.0, back, N, m);
  EXPECT_TRUE(mat.heldSticking());
  EXPECT_EQ(mat.traction(), held);
  // The next different input starts from the held (sticking) iterate: the return map.
  mat.setIterate(0.0, 1.01 * back, N, m);
  EXPECT_FALSE(mat.heldSticking());
  EXPECT_TRUE(mat.sliding());
  // After a revert, or a commit, there is no previous iterate: the return map.
  for (int k = 0; k < 2; ++k) {
    mat.setIterate(0.0, 4.0 * capacity / G * e, N, m);
    if (k == 0) mat.revertToLastCommit();
    else mat.commitState();
    mat.setIterate(0.0, back, N, m);
    EXPECT_FALSE(mat.heldSticking());
    mat.setTrialState(0.0, back, N, m);
    const Vector2 plain = mat.traction();
    mat.setIterate(0.0, back, N, m);
    EXPECT_EQ(mat.traction(), plain);
    mat.revertToStart();
  }
}

// A node that slid at the last commit starts the next step on the slip surface with the sliding
// tangent, also when the new projection's metric puts its elastic slip a hair inside the surface:
// the tangent of the converged state. Only while it has not moved: any motion, or any later iterate,
// gets the return map's answer (a reversal sticks).
TEST(ContactMaterial3D, SlidingNodeStartsTheNextStepSliding) {
  const Matrix2 m = testMetric();
  const double N = 10.0, capacity = mu * N + c;
  const Vector2 e = Vector2(0.4, 1.0) / normIn(m, Vector2(0.4, 1.0));
  ContactMaterial3D mat(1, mu, G, c, t);
  mat.setIterate(0.0, 4.0 * capacity / G * e, N, m);
  ASSERT_TRUE(mat.sliding());
  mat.commitState();
  const Vector2 se = mat.committedElasticSlip();
  const Vector2 mr = m * se / normIn(m, se);
  const Matrix2 slidingTangent = G * (m - mr * mr.transpose());
  // The re-projected metric shrinks |s_e|_m by 1e-7: the return map alone would stick.
  const Matrix2 drifted = (1.0 - 2e-7) * m;
  mat.setTrialState(0.0, Vector2::Zero(), N, drifted);
  ASSERT_FALSE(mat.sliding());
  mat.setIterate(0.0, Vector2::Zero(), N, drifted);
  EXPECT_TRUE(mat.sliding());
  EXPECT_NEAR(mat.tractionNorm(), capacity, 1e-12 * capacity);  // on the surface
  EXPECT_LE((mat.tangentSlip() - (1.0 - 2e-7) * slidingTangent).norm(), 1e-6 * G * m.norm());
  EXPECT_LE((mat.tangentNormal() - mu * mr).norm(), 1e-6 * mu * mr.norm());
  // The same state asked again (an integrator may update twice): the same answer.
  const Vector2 first = mat.traction();
  mat.setIterate(0.0, Vector2::Zero(), N, drifted);
  EXPECT_EQ(mat.traction(), first);
  // The next iterate moves on along the slide: the return map slides at mu N + c.
  mat.setIterate(0.0, 1e-3 * e, N, drifted);
  EXPECT_TRUE(mat.sliding());
  EXPECT_NEAR(mat.tractionNorm(), capacity, 1e-12 * capacity);
  // A first iterate that has moved back (a reversal) is the return map's: it sticks.
  mat.revertToLastCommit();
  mat.setIterate(0.0, -0.1 * capacity / G * e, N, m);
  EXPECT_FALSE(mat.sliding());
  EXPECT_LE((mat.tangentSlip() - G * m).norm(), 1e-12 * G * m.norm());
  // A node that stuck at the last commit starts sticking.
  mat.revertToStart();
  mat.setIterate(0.0, 0.5 * capacity / G * e, N, m);
  mat.commitState();
  mat.setIterate(0.0, Vector2::Zero(), N, m);
  EXPECT_FALSE(mat.sliding());
}

TEST(ContactMaterial3D, CloneServesOnlyContactElements) {
  ContactMaterial3D mat(3, mu, G, c, t);
  EXPECT_TRUE(dynamic_cast<ContactMaterial3D*>(mat.clone("ContactMaterial3D").get()));
  EXPECT_EQ(mat.clone("ThreeDimensional"), nullptr);
  EXPECT_EQ(mat.clone("PlaneStrain"), nullptr);
}

TEST(ContactMaterial3D, GenericInterfaceCarriesGapSlipAndNormalForce) {
  ContactMaterial3D mat(1, mu, G, c, t);
  const Matrix2 m = testMetric();
  mat.setMetric(m);
  Vector strain(4);
  strain << -1e-3, 1e-5, 2e-5, 60.0;
  mat.setTrialStrain(strain);
  EXPECT_EQ(Vector(mat.strain()), strain);
  const Vector stress = mat.stress();
  ASSERT_EQ(stress.size(), 3);
  EXPECT_EQ(stress(0), 60.0);
  EXPECT_LE((stress.tail<2>() - G * m * Vector2(1e-5, 2e-5)).norm(), 1e-13 * G);
  EXPECT_EQ(mat.tangent().rows(), 2);
  EXPECT_EQ(mat.tangent().cols(), 3);
  EXPECT_NE(errorOf([&] { mat.setTrialStrain(Vector::Zero(6)); }).find("size 4"), std::string::npos);
}

TEST(ContactMaterial3D, CommandChecksItsArguments) {
  Domain d;
  addNDMaterial(d, "ContactMaterial3D", 1, 0.3, 1000.0, 0.0, 0.0);
  EXPECT_EQ(d.ndMaterials.get(1, "test").className(), "ContactMaterial3D");
  EXPECT_NE(errorOf([&] { addNDMaterial(d, "ContactMaterial3D", 2, 0.3, -5.0, 0.0, 0.0); })
                .find("nDMaterial ContactMaterial3D 2: G must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { addNDMaterial(d, "ContactMaterial3D", 3, -0.1, 5.0, 0.0, 0.0); }).find("mu must be"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { addNDMaterial(d, "ContactMaterial3D", 4, 0.1, 5.0, 0.0); }).find("t"),
            std::string::npos);
}
