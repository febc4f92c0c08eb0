// BeamContact3D / BeamContact3Dp element level (beam_contact_formulation.md):
// gap of a node at radius + g0, projection against a brute-force search on a
// deflected beam, the transported frame and its derivative, finite-difference
// checks of the gap and slip gradients (C12) and of the full tangent against
// the resisting force (C17-C19) for straight, bent and twisted beams, sticking
// and sliding; rigid-motion invariance and element equilibrium; the contact
// status decided at commit (C20); the penalty force; responses; errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/contact/BeamContact3D.h"
#include "elements/contact/BeamContact3Dp.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using Vector2 = Eigen::Vector2d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Vector15 = BeamContactGeometry::Vector15;

using beamsolid::testsupport::errorOf;

void addLinearTransf(Domain& d, int tag, const Vector3& vecxz) {
  CommandArgs a = args("geomTransf", tag, vecxz.x(), vecxz.y(), vecxz.z());
  d.geomTransfs.add(tag, std::shared_ptr<CrdTransf>(Registry::global().geomTransfs.get("Linear")(a, d)), "test");
}

// Unit vector perpendicular to `axis` (any).
Vector3 perpendicular(const Vector3& axis) {
  Vector3 p = axis.cross(Vector3::UnitX());
  if (p.norm() < 0.1) p = axis.cross(Vector3::UnitY());
  return p.normalized();
}

constexpr double kRadius = 0.3;
constexpr double kMu = 0.3, kG = 1000.0, kC = 0.5, kT = 0.0;

// A pile segment a (node 1) - b (node 2), a soil node s (node 3) and, for
// the Lagrange element, the multiplier node 4. Material 1 is the contact
// material, geomTransf 1 Linear.
struct ContactModel {
  Domain d;
  BeamContactElement* element = nullptr;

  Node& node(int tag) { return d.node(tag, "test"); }
  const BeamContactGeometry& geometry() const { return element->geometry(); }
  // Every node commits, then the element (as Domain::commit does).
  void commit() {
    for (const auto& [tag, n] : d.nodes()) n->commitState();
    element->commitState();
  }
  void setDisp(int tag, const Vector& u) { node(tag).setTrialDisp(u); }
  Vector3 position(int tag) { return node(tag).crd() + node(tag).trialDisp().head<3>(); }
};

std::unique_ptr<ContactModel> makeModel(const Vector3& xa, const Vector3& xb, const Vector3& xs, bool penalty,
                                        int cSwitch = 0, const Vector3& vecxz = Vector3(0.3, -1.0, 0.2)) {
  auto m = std::make_unique<ContactModel>();
  addNode(m->d, 1, 6, xa.x(), xa.y(), xa.z());
  addNode(m->d, 2, 6, xb.x(), xb.y(), xb.z());
  addNode(m->d, 3, 3, xs.x(), xs.y(), xs.z());
  addNDMaterial(m->d, "ContactMaterial3D", 1, kMu, kG, kC, kT);
  addLinearTransf(m->d, 1, vecxz);
  if (penalty) {
    m->element = &dynamic_cast<BeamContactElement&>(
        addElement(m->d, "BeamContact3Dp", 1, 1, 2, 3, kRadius, 1, 1, 1e5, cSwitch));
  } else {
    addNode(m->d, 4, 3, xs.x(), xs.y(), xs.z());
    m->element = &dynamic_cast<BeamContactElement&>(
        addElement(m->d, "BeamContact3D", 1, 1, 2, 3, 4, kRadius, 1, 1, 1e-8, 1e-8, cSwitch));
  }
  return m;
}

// The three reference shapes of the beam at the committed state.
enum class Shape { Straight, Bent, Twisted };

const char* name(Shape s) { return s == Shape::Straight ? "straight" : s == Shape::Bent ? "bent" : "twisted"; }

// An inclined segment, deformed and committed into `shape`, with the soil
// node put back on the pile surface at xi = 0.4 (then committed again, so
// that the held projection data sit on the surface).
std::unique_ptr<ContactModel> committedModel(Shape shape, bool penalty) {
  const Vector3 xa(0.1, -0.2, 0.0), xb(0.35, 0.15, 2.0);
  const Vector3 axis = (xb - xa).normalized();
  const Vector3 xs = xa + 0.4 * (xb - xa) + kRadius * perpendicular(axis);
  auto m = makeModel(xa, xb, xs, penalty);
  Vector6 ua = Vector6::Zero(), ub = Vector6::Zero();
  if (shape == Shape::Bent) {
    ua << 0.01, -0.02, 0.003, 0.06, -0.09, 0.02;
    ub << 0.05, 0.04, -0.002, -0.05, 0.07, -0.01;
  } else if (shape == Shape::Twisted) {
    ua << 0.0, 0.01, 0.0, 0.04, -0.03, 0.0;
    ub.tail<3>() = 0.35 * axis + Vector3(-0.02, 0.05, 0.0);  // a third of a radian of twist
  }
  m->setDisp(1, ua);
  m->setDisp(2, ub);
  m->element->update();
  m->commit();
  // Soil node onto the surface of the committed pile at its projection.
  const BeamContactGeometry& g = m->geometry();
  const Vector3 onSurface = g.centerlinePoint() + kRadius * g.normal();
  m->setDisp(3, Vector(onSurface - m->node(3).crd()));
  m->element->update();
  m->commit();
  return m;
}

// Trial state: small beam motion, soil node slipping by `slip` (physical)
// along the pile axis plus a bit around it, pressing with normal force
// `lambda` (Lagrange) or penetrating the moved pile by `penetration` (penalty).
void setTrial(ContactModel& m, double slip, double lambda, double penetration) {
  const BeamContactGeometry& g = m.geometry();
  Vector6 da, db;
  da << 2e-4, -1e-4, 3e-4, 1e-3, -2e-3, 1.5e-3;
  db << -1e-4, 2e-4, 1e-4, -1.5e-3, 1e-3, 2e-3;
  m.setDisp(1, Vector(m.node(1).trialDisp() + da));
  m.setDisp(2, Vector(m.node(2).trialDisp() + db));
  const Vector3 c1 = g.frame().col(0);
  const Vector3 around = g.normal().cross(c1);
  const Vector3 motion = slip * (0.8 * c1 + 0.6 * around);
  m.setDisp(3, Vector(m.node(3).trialDisp() + motion));
  m.element->update();
  if (!m.d.findNode(4)) {
    // Penalty: move the soil node along n until it penetrates the moved pile by `penetration`.
    m.setDisp(3, Vector(m.node(3).trialDisp() - (g.gap() + penetration) * g.normal()));
  } else {
    Vector l(3);
    l << lambda, 0.0, 0.0;
    m.setDisp(4, l);
  }
  m.element->update();
}

}  // namespace

TEST(BeamContact3D, GapOfANodeAtRadiusPlusOffsetIsTheOffset) {
  const Vector3 xa(1.0, 2.0, 3.0), xb(1.5, 2.5, 7.0);
  const Vector3 axis = (xb - xa).normalized();
  const Vector3 out = perpendicular(axis);
  for (double g0 : {0.0, 0.05, -0.02, 1.7}) {
    const Vector3 xs = xa + 0.3 * (xb - xa) + (kRadius + g0) * out;
    auto m = makeModel(xa, xb, xs, false);
    const BeamContactGeometry& g = m->geometry();
    EXPECT_NEAR(g.gap(), g0, 1e-14 * 10.0) << "g0 " << g0;
    EXPECT_NEAR(g.committedGap(), g0, 1e-14 * 10.0);
    EXPECT_NEAR(g.xi(), 0.3, 1e-13);
    EXPECT_LE((g.normal() - out).norm(), 1e-14);
    EXPECT_TRUE(g.inBounds());
    EXPECT_NEAR(m->element->setResponse({"gap"}).value()(0), g0, 1e-13);
    // Straight pile without twist: m = diag(L^2, R^2) (C9).
    const double L = (xb - xa).norm();
    EXPECT_NEAR(g.metric()(0, 0), L * L, 1e-12 * L * L);
    EXPECT_NEAR(g.metric()(1, 1), kRadius * kRadius, 1e-14);
    EXPECT_NEAR(g.metric()(0, 1), 0.0, 1e-13);
  }
}

TEST(BeamContact3D, ProjectionMatchesBruteForceOnADeflectedBeam) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 3.0);
  auto m = makeModel(xa, xb, Vector3(0.9, 0.4, 1.1), false, 1, Vector3(1.0, 0.0, 0.0));
  // A strongly curved committed centerline (large end rotations).
  Vector6 ua, ub;
  ua << 0.0, 0.0, 0.0, 0.25, 0.3, 0.1;
  ub << 0.4, -0.2, -0.1, -0.2, -0.35, 0.0;
  m->setDisp(1, ua);
  m->setDisp(2, ub);
  for (const Vector3& us : {Vector3(0.0, 0.0, 0.0), Vector3(-0.5, 0.1, 0.9), Vector3(0.3, -0.6, -0.7)}) {
    m->setDisp(3, Vector(us));
    m->element->update();
    m->commit();
    // Independent centerline: Hermite cubic with end tangents rotated by the
    // exponential map of the end rotations from the local x axis (0, 0, 1).
    const double L = 3.0;
    auto rotated = [](const Vector3& theta) {
      return Vector3(Eigen::AngleAxisd(theta.norm(), theta.normalized()) * Vector3::UnitZ());
    };
    const Vector3 pa = xa + ua.head<3>(), pb = xb + ub.head<3>();
    const Vector3 ta = rotated(ua.tail<3>()), tb = rotated(ub.tail<3>());
    auto phi = [&](double x) -> Vector3 {
      const double h1 = 1 - 3 * x * x + 2 * x * x * x, h2 = x - 2 * x * x + x * x * x;
      const double h3 = 3 * x * x - 2 * x * x * x, h4 = -x * x + x * x * x;
      return h1 * pa + h2 * L * ta + h3 * pb + h4 * L * tb;
    };
    const Vector3 xs = m->position(3);
    auto distance = [&](double x) { return (xs - phi(x)).norm(); };
    // Brute force over the segment, then golden-section refinement.
    const int n = 20000;
    int best = 0;
    for (int k = 1; k <= n; ++k)
      if (distance(double(k) / n) < distance(double(best) / n)) best = k;
    double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 100; ++it) {
      const double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
      if (distance(m1) < distance(m2)) hi = m2;
      else lo = m1;
    }
    const double xiBrute = 0.5 * (lo + hi);
    const BeamContactGeometry& g = m->geometry();
    EXPECT_NEAR(g.xi(), xiBrute, 1e-7) << "us " << us.transpose();
    // The brute-force xi is only good to ~sqrt(eps) (the distance is flat at
    // its minimum), hence the looser tolerances on xi and on the point.
    EXPECT_LE((g.centerlinePoint() - phi(xiBrute)).norm(), 3e-7);
    EXPECT_NEAR(g.committedGap(), distance(xiBrute) - kRadius, 1e-12);
    EXPECT_NEAR((xs - g.centerlinePoint()).dot(g.centerlineTangent(g.xi())), 0.0, 1e-12);
  }
}

TEST(BeamContact3D, ProjectionFallbackFindsTheSameClosestPointFromBadStarts) {
  // A segment bent by +-0.6 rad at its ends (a 70 degree arc). Newton from
  // far starts leaves the segment or meets R' >= 0; the sampled, bracketed
  // fallback must land on the same closest point as Newton from a good start.
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 3.0);
  auto m = makeModel(xa, xb, Vector3(1.0, 0.0, 1.5), false, 1, Vector3(1.0, 0.0, 0.0));
  Vector6 ua = Vector6::Zero(), ub = Vector6::Zero();
  ua(4) = 0.6;
  ub(4) = -0.6;
  m->setDisp(1, ua);
  m->setDisp(2, ub);
  m->element->update();
  m->commit();
  const BeamContactGeometry& g = m->geometry();
  int fallbacks = 0;
  for (double x : {0.2, 0.5, 1.0, -0.5}) {
    const Vector3 point(x, 0.0, 1.2);
    const double reference = g.project(point, 0.5);
    ASSERT_FALSE(g.projectionUsedFallback());
    // Brute force on the segment.
    double bestXi = 0.0, bestDistance = 1e300;
    for (int k = 0; k <= 100000; ++k) {
      const double xi = k / 100000.0;
      const double dist = (point - g.centerline(xi)).norm();
      if (dist < bestDistance) {
        bestDistance = dist;
        bestXi = xi;
      }
    }
    EXPECT_NEAR(reference, bestXi, 2e-5) << "x " << x;
    for (double start : {-0.9, 0.0, 1.0, 1.9}) {
      EXPECT_NEAR(g.project(point, start), reference, 1e-11) << "x " << x << " start " << start;
      fallbacks += g.projectionUsedFallback();
    }
  }
  EXPECT_GE(fallbacks, 2);
  // Beyond the centre of curvature no interior point is closest: out of bounds.
  const double beyond = g.project(Vector3(-3.0, 0.0, 1.2), 0.5);
  EXPECT_TRUE(beyond < 0.0 || beyond > 1.0) << beyond;
}

TEST(BeamContact3D, ProjectionOutsideTheSegmentIsOutOfBoundsAndReleases) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  auto above = makeModel(xa, xb, Vector3(0.3, 0.0, 2.4), false);
  EXPECT_GT(above->geometry().xi(), 1.0);
  EXPECT_FALSE(above->geometry().inBounds());
  EXPECT_FALSE(above->element->inContact());
  // A node exactly at a beam node's elevation is not in bounds (xi = 0).
  auto level = makeModel(xa, xb, Vector3(0.3, 0.0, 0.0), false);
  EXPECT_NEAR(level->geometry().xi(), 0.0, 1e-15);
  EXPECT_FALSE(level->element->inContact());
}

TEST(BeamContact3D, TransportedFrameHasTheRightEndsAndDerivative) {
  for (Shape shape : {Shape::Straight, Shape::Bent, Shape::Twisted}) {
    SCOPED_TRACE(name(shape));
    auto m = committedModel(shape, false);
    const BeamContactGeometry& g = m->geometry();
    Matrix3 q0, q1;
    g.frameAt(0.0, q0, nullptr);
    g.frameAt(1.0, q1, nullptr);
    EXPECT_LE((q0 - g.frameA()).norm(), 1e-13);
    EXPECT_LE((q1 - g.frameB()).norm(), 1e-12);
    for (double xi : {0.1, 0.4, 0.85}) {
      Matrix3 q, dq, qp, qm;
      g.frameAt(xi, q, &dq);
      EXPECT_LE((q.transpose() * q - Matrix3::Identity()).norm(), 1e-14);
      EXPECT_NEAR(q.determinant(), 1.0, 1e-14);
      const double h = 1e-6;
      g.frameAt(xi + h, qp, nullptr);
      g.frameAt(xi - h, qm, nullptr);
      EXPECT_LE((dq - (qp - qm) / (2 * h)).norm(), 1e-8) << "xi " << xi;
      // c1 follows the centerline tangent.
      EXPECT_LE((q.col(0) - g.centerlineTangent(xi).normalized()).norm(), 1e-14);
    }
    // The tangent plane base vectors are orthogonal to the normal.
    EXPECT_NEAR(g.covariantBase(0).dot(g.normal()), 0.0, 1e-13);
    EXPECT_NEAR(g.covariantBase(1).dot(g.normal()), 0.0, 1e-14);
    EXPECT_NEAR(g.covariantBase(1).norm(), kRadius, 1e-14);
  }
}

TEST(BeamContact3D, GapAndSlipGradientsMatchFiniteDifferences) {
  for (Shape shape : {Shape::Straight, Shape::Bent, Shape::Twisted}) {
    SCOPED_TRACE(name(shape));
    auto m = committedModel(shape, false);
    setTrial(*m, 0.01, 10.0, 0.0);
    const BeamContactGeometry& g = m->geometry();
    const Vector15 Bn = g.gapGradient();
    const BeamContactGeometry::Matrix15x2 Bs = g.slipGradient();
    const double h = 1e-5;
    int col = 0;
    for (int tag : {1, 2, 3}) {
      Node& n = m->node(tag);
      for (int dof = 0; dof < n.ndf(); ++dof, ++col) {
        const double u0 = n.trialDisp()(dof);
        n.setTrialDisp(dof, u0 + h);
        m->element->update();
        const double gp = g.gap();
        const Vector2 sp = g.slip();
        n.setTrialDisp(dof, u0 - h);
        m->element->update();
        const double gm = g.gap();
        const Vector2 sm = g.slip();
        n.setTrialDisp(dof, u0);
        // Gap and slip are linear in the dofs: central differences are exact
        // up to round-off.
        EXPECT_NEAR(-(gp - gm) / (2 * h), Bn(col), 1e-9) << "B_n dof " << col;
        EXPECT_NEAR((sp(0) - sm(0)) / (2 * h), Bs(col, 0), 1e-9) << "B_s^xi dof " << col;
        EXPECT_NEAR((sp(1) - sm(1)) / (2 * h), Bs(col, 1), 1e-8) << "B_s^psi dof " << col;
      }
    }
    m->element->update();
  }
}

TEST(BeamContact3D, TangentMatchesFiniteDifferencesStickingAndSliding) {
  for (Shape shape : {Shape::Straight, Shape::Bent, Shape::Twisted}) {
    for (bool sliding : {false, true}) {
      SCOPED_TRACE(std::string(name(shape)) + (sliding ? " sliding" : " sticking"));
      auto m = committedModel(shape, false);
      setTrial(*m, sliding ? 0.02 : 5e-4, 20.0, 0.0);
      ASSERT_TRUE(m->element->inContact());
      ASSERT_EQ(m->element->status(),
                sliding ? BeamContactElement::Status::Sliding : BeamContactElement::Status::Sticking);
      const TangentCheck check = checkTangent(*m->element, 1e-7);
      EXPECT_LE(check.relativeError(), 1e-6) << "max error " << check.maxError << " of " << check.maxEntry;
      // The multiplier row is B_n^T and the inert multiplier dofs have unit stiffness.
      const Matrix K = m->element->tangentStiff();
      EXPECT_LE((K.block(15, 0, 1, 15).transpose() - m->geometry().gapGradient()).norm(), 0.0);
      EXPECT_EQ(K(15, 15), 0.0);
      EXPECT_EQ(K(16, 16), 1.0);
      EXPECT_EQ(K(17, 17), 1.0);
      // ... coupled to nothing, as hasConstantUncoupledDof tells the solver (which condenses them).
      for (int i : {16, 17}) {
        EXPECT_EQ(K.row(i).norm(), 1.0);
        EXPECT_EQ(K.col(i).norm(), 1.0);
        EXPECT_TRUE(m->element->hasConstantUncoupledDof(i));
      }
      for (int i = 0; i < 16; ++i) EXPECT_FALSE(m->element->hasConstantUncoupledDof(i)) << i;
      EXPECT_EQ(m->element->resistingForce()(15), -m->geometry().gap());
    }
  }
}

TEST(BeamContact3D, OutOfContactTheMultiplierReturnsToZero) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  auto m = makeModel(xa, xb, Vector3(0.5, 0.0, 1.0), false, 1);
  EXPECT_FALSE(m->element->inContact());
  Vector l(3);
  l << 7.0, 2.0, -3.0;
  m->setDisp(4, l);
  m->setDisp(3, Vector(Vector3(-0.4, 0.1, 0.0)));  // penetration, ignored while released
  m->element->update();
  const Vector f = m->element->resistingForce();
  EXPECT_EQ(f.head<15>().norm(), 0.0);
  EXPECT_EQ(f(15), 7.0);
  EXPECT_EQ(f(16), 2.0);
  EXPECT_EQ(f(17), -3.0);
  const Matrix K = m->element->tangentStiff();
  Matrix expectedK = Matrix::Zero(18, 18);
  expectedK(15, 15) = expectedK(16, 16) = expectedK(17, 17) = 1.0;
  EXPECT_EQ((K - expectedK).norm(), 0.0);
  const TangentCheck check = checkTangent(*m->element, 1e-6);
  EXPECT_LE(check.maxError, 1e-9);
  EXPECT_EQ(m->element->setResponse({"status"}).value()(0), 0.0);
}

TEST(BeamContact3D, RigidMotionGivesNoGapChangeNoSlipAndForcesAreInEquilibrium) {
  for (Shape shape : {Shape::Straight, Shape::Bent, Shape::Twisted}) {
    SCOPED_TRACE(name(shape));
    auto m = committedModel(shape, false);
    const BeamContactGeometry& g = m->geometry();
    ASSERT_NEAR(g.committedGap(), 0.0, 1e-14);
    const double gap0 = g.gap();
    // Linearized rigid motion about x0: u = v + w x (x - x0), theta = w.
    const Vector3 v(0.01, -0.02, 0.015), w(0.002, 0.003, -0.004), x0(0.3, 0.2, 1.0);
    for (int tag : {1, 2, 3}) {
      Node& n = m->node(tag);
      Vector u = n.committedDisp();
      const Vector3 x = n.crd() + n.committedDisp().head<3>();
      u.head<3>() += v + w.cross(x - x0);
      if (n.ndf() == 6) u.tail<3>() += w;
      n.setTrialDisp(u);
    }
    m->element->update();
    EXPECT_NEAR(g.gap(), gap0, 1e-15);
    EXPECT_LE(g.slip().norm(), 1e-14);

    // Resisting forces of a sliding state carry no net force or moment
    // (about the committed positions, where the gradients are taken).
    for (int tag : {1, 2, 3}) m->node(tag).revertToLastCommit();
    setTrial(*m, 0.02, 20.0, 0.0);
    ASSERT_EQ(m->element->status(), BeamContactElement::Status::Sliding);
    const Vector f = m->element->resistingForce();
    Vector3 force = Vector3::Zero(), moment = Vector3::Zero();
    const int offset[3] = {0, 6, 12};
    int k = 0;
    for (int tag : {1, 2, 3}) {
      const Node& n = m->node(tag);
      const Vector3 x = n.crd() + n.committedDisp().head<3>();
      const Vector3 fk = f.segment<3>(offset[k]);
      force += fk;
      moment += x.cross(fk);
      if (n.ndf() == 6) moment += f.segment<3>(offset[k] + 3);
      ++k;
    }
    const double scale = f.head<15>().cwiseAbs().maxCoeff();
    EXPECT_LE(force.norm(), 1e-13 * scale);
    EXPECT_LE(moment.norm(), 1e-12 * scale);
    // The responses see the same balance: force on s plus the actions on the beam.
    const Vector onS = m->element->setResponse({"force"}).value();
    const Vector onBeam = m->element->setResponse({"masterforce"}).value();
    EXPECT_LE((onS + onBeam.head<3>() + onBeam.tail<3>()).norm(), 1e-13 * scale);
  }
}

TEST(BeamContact3D, SlipOfTheSoilNodeAlongAndAroundAStraightPile) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  auto m = makeModel(xa, xb, Vector3(kRadius, 0.0, 0.8), false);
  const BeamContactGeometry& g = m->geometry();
  const double delta = 1e-3;
  // Along the axis: s^xi = delta / L and the physical slip is delta.
  m->setDisp(3, Vector(Vector3(0.0, 0.0, delta)));
  m->element->update();
  EXPECT_NEAR(g.slip()(0), delta / 2.0, 1e-16);
  EXPECT_NEAR(g.slip()(1), 0.0, 1e-16);
  EXPECT_NEAR(m->element->totalSlip()(0), delta, 1e-15);
  // Around it: s^psi = delta / R (tangent-plane approximation).
  m->setDisp(3, Vector(Vector3(0.0, delta, 0.0)));
  m->element->update();
  EXPECT_NEAR(g.slip()(0), 0.0, 1e-16);
  EXPECT_NEAR(g.slip()(1), delta / kRadius, 1e-15);
  // A pile twist by phi moves its surface by R phi under the node: slip -R phi.
  m->setDisp(3, Vector(Vector3::Zero()));
  Vector6 twist = Vector6::Zero();
  twist(5) = 1e-3;
  m->setDisp(1, Vector(twist));
  m->setDisp(2, Vector(twist));
  m->element->update();
  EXPECT_NEAR(g.slip()(1) * kRadius, -kRadius * 1e-3, 1e-16);
  // Sticking friction force on the soil node opposes its slip: -G * slip.
  Vector l(3);
  l << 50.0, 0.0, 0.0;
  m->setDisp(4, l);
  m->setDisp(1, Vector(Vector6::Zero()));
  m->setDisp(2, Vector(Vector6::Zero()));
  m->setDisp(3, Vector(Vector3(0.0, 0.0, delta)));
  m->element->update();
  ASSERT_EQ(m->element->status(), BeamContactElement::Status::Sticking);
  const Vector friction = m->element->setResponse({"soilFrictionForce"}).value();
  EXPECT_LE((friction - Vector(Vector3(0.0, 0.0, -kG * delta))).norm(), 1e-12);
  // OpenSees' frictionforce is the reaction on the pile: the opposite.
  EXPECT_LE((m->element->setResponse({"frictionforce"}).value() + friction).norm(), 0.0);
  const Vector force = m->element->setResponse({"force"}).value();
  EXPECT_LE((force - Vector(Vector3(50.0, 0.0, -kG * delta))).norm(), 1e-12);
  const Vector scalars = m->element->setResponse({"physicalForceScalar"}).value();
  EXPECT_NEAR(scalars(0), 50.0, 0.0);
  EXPECT_NEAR(scalars(1), -kG * delta, 1e-12);
  EXPECT_NEAR(scalars(2), 0.0, 1e-12);
  // OpenSees' forcescalar: the tractions on the unnormalised surface base,
  // T_xi = -|g_xi| times the axial friction (|g_xi| = L = 2 on this straight
  // pile), T_psi = -R times the circumferential one.
  const Vector opensees = m->element->setResponse({"forcescalar"}).value();
  EXPECT_NEAR(opensees(0), 50.0, 0.0);
  EXPECT_NEAR(opensees(1), 2.0 * kG * delta, 1e-12);
  EXPECT_NEAR(opensees(2), 0.0, 1e-12);
  // OpenSees' slip: this step's slip in parametric coordinates (delta / L);
  // ours, totalSlip, in metres.
  const Vector slip = m->element->setResponse({"slip"}).value();
  EXPECT_NEAR(slip(0), delta / 2.0, 1e-16);
  EXPECT_NEAR(slip(1), 0.0, 1e-16);
  EXPECT_NEAR(m->element->setResponse({"totalSlip"}).value()(0), delta, 1e-15);
  // Resisting force on the soil node: minus the contact force on it.
  EXPECT_LE((m->element->resistingForce().segment<3>(12) + force).norm(), 1e-12);
}

TEST(BeamContact3D, StatusIsDecidedAtCommit) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  auto m = makeModel(xa, xb, Vector3(kRadius, 0.0, 1.0), false);
  auto& e = dynamic_cast<BeamContact3D&>(*m->element);
  ASSERT_TRUE(e.inContact());
  Vector l(3);
  // Sliding around the pile on the tangent plane (converged gap 0) leaves the
  // node slip^2 / 2R off the re-projected surface, far beyond gapTol; a node
  // in contact is judged by its converged gap and stays in contact.
  m->setDisp(3, Vector(Vector3(0.0, 0.01, 0.0)));
  e.update();
  ASSERT_NEAR(m->geometry().gap(), 0.0, 1e-15);
  m->commit();
  EXPECT_NEAR(m->geometry().committedGap(), 0.01 * 0.01 / (2 * kRadius), 1e-6);
  EXPECT_TRUE(e.inContact());
  // Tension beyond forceTol: the step keeps contact, the commit releases it.
  l << -1.0, 0.0, 0.0;
  m->setDisp(4, l);
  e.update();
  EXPECT_TRUE(e.shouldRelease());
  EXPECT_TRUE(e.inContact());
  EXPECT_EQ(e.resistingForce()(15), -m->geometry().gap());
  m->commit();
  EXPECT_FALSE(e.inContact());
  // Released and at a gap beyond gapTol: stays out.
  l << 0.0, 0.0, 0.0;
  m->setDisp(4, l);
  m->setDisp(3, Vector(Vector3(0.01, 0.0, 0.0)));
  e.update();
  m->commit();
  EXPECT_GT(m->geometry().committedGap(), 0.009);
  EXPECT_FALSE(e.inContact());
  // Back within gapTol: in contact again from the next step.
  m->setDisp(3, Vector(Vector3(-1e-3, 0.0, 0.0)));
  e.update();
  EXPECT_FALSE(e.inContact());
  m->commit();
  EXPECT_TRUE(e.inContact());
  // Sliding out of the segment: released at commit.
  m->setDisp(3, Vector(Vector3(0.0, 0.0, 1.5)));
  e.update();
  m->commit();
  EXPECT_FALSE(m->geometry().inBounds());
  EXPECT_FALSE(e.inContact());
  // revertToStart brings back the initial status.
  for (const auto& [tag, n] : m->d.nodes()) n->revertToStart();
  e.revertToStart();
  EXPECT_TRUE(e.inContact());
  EXPECT_NEAR(m->geometry().xi(), 0.5, 1e-15);
}

TEST(BeamContact3D, FrictionStageIsForwardedToTheElementsMaterialCopy) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  auto m = makeModel(xa, xb, Vector3(kRadius, 0.0, 0.8), false);
  Vector l(3);
  l << 100.0, 0.0, 0.0;
  m->setDisp(4, l);
  m->setDisp(3, Vector(Vector3(0.0, 0.0, 1e-3)));
  EXPECT_TRUE(m->element->setParameter({"friction"}, 0.0));
  m->element->update();
  EXPECT_EQ(m->element->frictionForce().norm(), 0.0);
  EXPECT_TRUE(m->d.ndMaterials.get(1, "test").clone("ContactMaterial3D") != nullptr);
  EXPECT_TRUE(dynamic_cast<ContactMaterial3D&>(m->d.ndMaterials.get(1, "test")).frictional());
  m->element->updateMaterialStage(1, 1);
  m->element->update();
  EXPECT_NEAR(m->element->frictionForce().z(), -kG * 1e-3, 1e-12);
  m->element->updateMaterialStage(2, 0);  // another material: ignored
  m->element->update();
  EXPECT_TRUE(m->element->material().frictional());
  EXPECT_FALSE(m->element->setParameter({"unknown"}, 1.0));
  EXPECT_NE(errorOf([&] { m->element->setParameter({"friction"}, 3.0); }).find("element BeamContact3D 1:"),
            std::string::npos);
}

TEST(BeamContact3D, ResponsesHaveOpenSeesNamesAndSizes) {
  auto m = committedModel(Shape::Bent, false);
  setTrial(*m, 0.02, 20.0, 0.0);
  const std::pair<const char*, std::size_t> expected[] = {
      {"force", 3},        {"frictionforce", 3},  {"forcescalar", 3},   {"masterforce", 6},   {"primaryforce", 6},
      {"mastermoment", 6}, {"primarymoment", 6},  {"masterreaction", 12}, {"primaryreaction", 12},
      {"slip", 2},         {"totalSlip", 2},      {"physicalForceScalar", 3}, {"gap", 1},            {"status", 1},        {"xi", 1},            {"frictionForce", 3},  {"soilFrictionForce", 3}};
  for (const auto& [what, size] : expected) {
    const Response r = m->element->setResponse({what});
    ASSERT_TRUE(r) << what;
    EXPECT_EQ(r.size(), size) << what;
    EXPECT_EQ(static_cast<std::size_t>(r.value().size()), size) << what;
  }
  EXPECT_FALSE(m->element->setResponse({"stresses"}));
  const Vector reaction = m->element->setResponse({"masterreaction"}).value();
  EXPECT_LE((reaction + m->element->resistingForce().head(12)).norm(), 0.0);
  EXPECT_EQ(m->element->setResponse({"status"}).value()(0), 2.0);
  EXPECT_EQ(m->element->setResponse({"xi"}).value()(0), m->geometry().xi());
}

TEST(BeamContact3Dp, ContactForceIsPenaltyTimesPenetration) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  const Vector3 out = Vector3(1.0, 1.0, 0.0).normalized();
  const double penetration = 2e-4;
  auto m = makeModel(xa, xb, 0.9 * xb + kRadius * out, true);
  ASSERT_EQ(m->element->numDOF(), 15);
  m->setDisp(3, Vector(-penetration * out));
  m->element->update();
  const double kappa = dynamic_cast<BeamContact3Dp&>(*m->element).penalty();
  EXPECT_NEAR(m->element->normalForce(), kappa * penetration, 1e-12 * kappa * penetration);
  const Vector force = m->element->setResponse({"force"}).value();
  EXPECT_LE((force - Vector(kappa * penetration * out)).norm(), 1e-11 * kappa * penetration);
  EXPECT_LE((m->element->resistingForce().segment<3>(12) + Vector3(force)).norm(), 1e-11 * kappa * penetration);
  // Opening: no force at all.
  m->setDisp(3, Vector(penetration * out));
  m->element->update();
  EXPECT_EQ(m->element->resistingForce().norm(), 0.0);
  EXPECT_EQ(m->element->status(), BeamContactElement::Status::Separated);
}

TEST(BeamContact3Dp, TangentMatchesFiniteDifferencesStickingAndSliding) {
  for (Shape shape : {Shape::Straight, Shape::Bent, Shape::Twisted}) {
    for (bool sliding : {false, true}) {
      SCOPED_TRACE(std::string(name(shape)) + (sliding ? " sliding" : " sticking"));
      auto m = committedModel(shape, true);
      // 2e-4 penetration: t_n = 20 with the penalty 1e5.
      setTrial(*m, sliding ? 0.02 : 5e-5, 0.0, 2e-4);
      ASSERT_LT(m->geometry().gap(), 0.0);
      ASSERT_EQ(m->element->status(),
                sliding ? BeamContactElement::Status::Sliding : BeamContactElement::Status::Sticking);
      const TangentCheck check = checkTangent(*m->element, 1e-9);
      EXPECT_LE(check.relativeError(), 1e-6) << "max error " << check.maxError << " of " << check.maxEntry;
    }
  }
}

TEST(BeamContact3Dp, NoContactInitiallyEngagesAfterTheFirstPenetratingStep) {
  const Vector3 xa(0.0, 0.0, 0.0), xb(0.0, 0.0, 2.0);
  auto m = makeModel(xa, xb, Vector3(kRadius, 0.0, 1.0), true, 1);
  auto& e = dynamic_cast<BeamContact3Dp&>(*m->element);
  EXPECT_FALSE(e.activated());
  m->setDisp(3, Vector(Vector3(-1e-4, 0.0, 0.0)));
  e.update();
  EXPECT_EQ(e.resistingForce().norm(), 0.0);
  m->commit();
  EXPECT_TRUE(e.activated());
  e.update();
  EXPECT_NEAR(e.normalForce(), 1e5 * 1e-4, 1e-9);
}

TEST(BeamContact3D, BadInputGivesClearErrors) {
  auto build = [](const std::function<void(Domain&)>& tweak, int sNdf = 3, int lNdf = 3, int aNdf = 6) {
    Domain d;
    addNode(d, 1, aNdf, 0, 0, 0);
    addNode(d, 2, 6, 0, 0, 2);
    addNode(d, 3, sNdf, 0.3, 0, 1);
    addNode(d, 4, lNdf, 0.3, 0, 1);
    addNDMaterial(d, "ContactMaterial3D", 1, 0.3, 1000.0, 0.0, 0.0);
    addNDMaterial(d, "ElasticIsotropic", 2, 1000.0, 0.3);
    addLinearTransf(d, 1, Vector3(1, 0, 0));
    tweak(d);
  };
  auto contact = [](Domain& d, int tag, int mat = 1, double radius = 0.3, int l = 4) {
    addElement(d, "BeamContact3D", tag, 1, 2, 3, l, radius, 1, mat, 1e-6, 1e-6);
  };
  auto error = [&](const std::function<void(Domain&)>& tweak, int sNdf = 3, int lNdf = 3, int aNdf = 6) {
    return errorOf([&] { build(tweak, sNdf, lNdf, aNdf); });
  };
  EXPECT_EQ(error([&](Domain& d) { contact(d, 1); }), "(no error)");
  EXPECT_NE(error([&](Domain& d) { contact(d, 1); }, 3, 3, 3)
                .find("element BeamContact3D 1: primary (beam) node 1 has 3 dofs, expected 6"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1); }, 6).find("secondary (solid) node 3 has 6 dofs, expected 3"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1); }, 3, 6).find("multiplier node 4 has 6 dofs, expected 3"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 2); })
                .find("element BeamContact3D 1: nDMaterial 2 (ElasticIsotropic3D) is not a ContactMaterial3D; beam "
                      "contact elements need a ContactMaterial3D"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 1, 0.0); }).find("argument 6 (radius): expected a positive number"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 1, 0.3, 3); }).find("node 3 appears twice"), std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              contact(d, 1);
              contact(d, 2);
            }).find("element BeamContact3D 2: multiplier node 4 is also used by element 1"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              d.addSP(SPConstraint{4, 0, 0.0}, "test");
              contact(d, 1);
            }).find("multiplier node 4 is fixed (dof 1)"),
            std::string::npos);
  // A fix added after the element is caught at the next update.
  EXPECT_NE(error([&](Domain& d) {
              contact(d, 1);
              d.addSP(SPConstraint{4, 2, 0.0}, "test");
              d.update();
            }).find("multiplier node 4 is fixed (dof 3)"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              addElement(d, "BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-6, 1e-6, 2);
            }).find("cSwitch"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              addElement(d, "BeamContact3D", 1, 1, 2, 3, 4, 0.3, 7, 1, 1e-6, 1e-6);
            }).find("geomTransf 7 does not exist"),
            std::string::npos);
  // A soil node on the centerline has no contact normal.
  EXPECT_NE(error([&](Domain& d) {
              d.node(3, "test").setTrialDisp(Vector(Vector3(-0.3, 0.0, 0.0)));
              contact(d, 1);
            }).find("lies on the beam centerline"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              addElement(d, "BeamContact3Dp", 1, 1, 2, 3, 0.3, 1, 1, -1.0);
            }).find("argument 8 (penalty): expected a positive number"),
            std::string::npos);
}
