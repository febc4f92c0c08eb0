// BeamEndContact3D / BeamEndContact3Dp (docs/beam_contact.md, "End bearing",
// E1-E7). Element level: the gap of a node ahead of a straight or turned
// tip face, the face-radius rule, finite-difference checks of the gap
// gradient and Hessian and of the full tangent against the resisting force,
// the balance of the contact actions, the status decided at commit, the
// penalty force, responses and errors. Analyses: a pile (elasticBeamColumn)
// standing on a block of stdBrick soil: the tip carries the head load, the
// multiplier closes the gap, pulling releases and pushing re-closes one step
// late, and the penalty answer converges to the Lagrange answer.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/contact/BeamEndContact3D.h"
#include "elements/contact/BeamEndContact3Dp.h"
#include "support/Script.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Vector15 = BeamEndContactElement::Vector15;
using Matrix15 = BeamEndContactElement::Matrix15;

using beamsolid::testsupport::errorOf;

Vector3 perpendicular(const Vector3& axis) {
  Vector3 p = axis.cross(Vector3::UnitX());
  if (p.norm() < 0.1) p = axis.cross(Vector3::UnitY());
  return p.normalized();
}

// exp(skew(w)) v, written with Rodrigues' formula (independent of the element).
Vector3 rotate(const Vector3& w, const Vector3& v) {
  const double a = w.norm();
  if (a == 0.0) return v;
  const Vector3 k = w / a;
  return std::cos(a) * v + std::sin(a) * k.cross(v) + (1.0 - std::cos(a)) * k.dot(v) * k;
}

constexpr double kRadius = 0.4;
constexpr double kPenalty = 1e5;

// An inclined end element j (node 2) -> i (node 1, the tip), soil node 3 and,
// for the Lagrange element, multiplier node 4.
struct EndModel {
  Domain d;
  BeamEndContactElement* element = nullptr;

  Node& node(int tag) { return d.node(tag, "test"); }
  void commit() {
    for (const auto& [tag, n] : d.nodes()) n->commitState();
    element->commitState();
  }
  void setDisp(int tag, const Vector& u) { node(tag).setTrialDisp(u); }
  void addDisp(int tag, const Vector& du) { node(tag).setTrialDisp(Vector(node(tag).trialDisp() + du)); }
  Vector3 position(int tag) { return node(tag).crd() + node(tag).trialDisp().head<3>(); }
  void setLambda(double lambda) {
    Vector l = Vector::Zero(3);
    l(0) = lambda;
    setDisp(4, l);
  }
};

const Vector3 kTip(1.3, 1.8, 2.0), kOther(1.0, 2.0, 5.0);

std::unique_ptr<EndModel> makeModel(const Vector3& xs, bool penalty, int cFlag = 0) {
  auto m = std::make_unique<EndModel>();
  addNode(m->d, 1, 6, kTip.x(), kTip.y(), kTip.z());
  addNode(m->d, 2, 6, kOther.x(), kOther.y(), kOther.z());
  addNode(m->d, 3, 3, xs.x(), xs.y(), xs.z());
  if (penalty) {
    m->element = &dynamic_cast<BeamEndContactElement&>(
        addElement(m->d, "BeamEndContact3Dp", 1, 1, 2, 3, kRadius, kPenalty, cFlag));
  } else {
    addNode(m->d, 4, 3, 0.0, 0.0, 0.0);
    m->element = &dynamic_cast<BeamEndContactElement&>(
        addElement(m->d, "BeamEndContact3D", 1, 1, 2, 3, 4, kRadius, 1e-8, 1e-8, cFlag));
  }
  return m;
}

// The tip turned by two committed steps of rotation (and moved), the soil
// node then put at `ahead` along the committed normal and `offset` (a
// fraction of the radius) sideways, and committed again. Returns the model
// and the independently computed normal.
std::unique_ptr<EndModel> turnedTipModel(bool turned, bool penalty, double ahead, double offset,
                                         Vector3* expectedNormal = nullptr) {
  const Vector3 axis = (kTip - kOther).normalized();
  auto m = makeModel(kTip + 0.5 * kRadius * perpendicular(axis), penalty);
  Vector3 normal = axis;
  if (turned) {
    const Vector3 step1(0.2, -0.15, 0.1), step2(-0.05, 0.25, 0.3);
    Vector6 u;
    u << 0.01, -0.02, 0.005, step1;
    m->setDisp(1, u);
    m->element->update();
    m->commit();
    u << 0.03, 0.01, -0.01, step1 + step2;
    m->setDisp(1, u);
    m->element->update();
    m->commit();
    normal = rotate(step2, rotate(step1, axis));
  }
  const Vector3 xs = m->position(1) + ahead * normal + offset * kRadius * perpendicular(normal);
  m->setDisp(3, Vector(xs - m->node(3).crd()));
  m->element->update();
  m->commit();
  m->element->update();
  if (expectedNormal) *expectedNormal = normal;
  return m;
}

// A trial state inside a step: the tip turns and moves a little, the soil
// node moves, and the normal force is `lambda` (Lagrange) or the node
// penetrates the moved face by `penetration` (penalty).
void setTrial(EndModel& m, double lambda, double penetration) {
  Vector6 di, dj;
  di << 2e-3, -1e-3, 3e-3, 0.02, -0.03, 0.015;
  dj << -1e-3, 2e-3, 1e-3, -0.01, 0.01, 0.02;
  m.addDisp(1, di);
  m.addDisp(2, dj);
  m.addDisp(3, Vector(Vector3(1e-3, 2e-3, -1.5e-3)));
  m.element->update();
  if (m.d.findNode(4)) {
    m.setLambda(lambda);
  } else {
    // Along the trial normal n, |n| = 1 + O(dth^2): move by -(g + p) n / |n|^2.
    const Vector3 n = m.element->normal();
    m.addDisp(3, Vector(-(m.element->gap() + penetration) * n / n.squaredNorm()));
  }
  m.element->update();
}

}  // namespace

TEST(BeamEndContact3D, GapOfANodeAheadOfTheFaceIsItsDistance) {
  for (bool turned : {false, true}) {
    for (double g0 : {0.0, 0.05, -0.02, 1.7}) {
      for (double offset : {0.0, 0.6}) {
        SCOPED_TRACE(std::string(turned ? "turned" : "straight") + " g0 " + std::to_string(g0) + " offset " +
                     std::to_string(offset));
        Vector3 normal;
        auto m = turnedTipModel(turned, false, g0, offset, &normal);
        const BeamEndContactElement& e = *m->element;
        EXPECT_NEAR(e.gap(), g0, 1e-14 * 10.0);
        EXPECT_NEAR(e.committedGap(), g0, 1e-14 * 10.0);
        EXPECT_LE((e.normal() - normal).norm(), 1e-14);
        EXPECT_LE((e.committedNormal() - normal).norm(), 1e-14);
        EXPECT_NEAR(e.lateralOffset(), offset * kRadius, 1e-13);
        EXPECT_TRUE(e.withinFace());
        // Committed at this gap: still in contact only if within gapTol.
        EXPECT_EQ(e.inContact(), g0 < 1e-8);
        EXPECT_NEAR(m->element->setResponse({"gap"}).value()(0), g0, 1e-13);
      }
    }
  }
}

TEST(BeamEndContact3D, OnlyANodeWithinTheFaceRadiusCanBeInContact) {
  const Vector3 axis = (kTip - kOther).normalized();
  const Vector3 side = perpendicular(axis);
  auto inside = makeModel(kTip + 0.01 * axis + 0.99 * kRadius * side, false);
  EXPECT_TRUE(inside->element->withinFace());
  EXPECT_TRUE(inside->element->inContact());
  auto outside = makeModel(kTip + 0.01 * axis + 1.01 * kRadius * side, false);
  EXPECT_FALSE(outside->element->withinFace());
  EXPECT_FALSE(outside->element->inContact());
  // A node in contact that slides sideways off the face is released at commit.
  inside->setLambda(10.0);
  inside->setDisp(3, Vector(0.05 * kRadius * side));
  inside->element->update();
  EXPECT_TRUE(inside->element->inContact());
  EXPECT_EQ(inside->element->status(), 1);
  inside->commit();
  EXPECT_FALSE(inside->element->withinFace());
  EXPECT_FALSE(inside->element->inContact());
  // The same for the penalty element.
  auto penalty = makeModel(kTip - 0.001 * axis + 1.01 * kRadius * side, true);
  EXPECT_FALSE(penalty->element->inContact());
  EXPECT_EQ(penalty->element->resistingForce().norm(), 0.0);
}

TEST(BeamEndContact3D, GapGradientAndHessianMatchFiniteDifferences) {
  for (bool turned : {false, true}) {
    SCOPED_TRACE(turned ? "turned tip" : "straight tip");
    auto m = turnedTipModel(turned, false, 0.0, 0.7);
    setTrial(*m, 10.0, 0.0);
    const Vector15 B = m->element->gapGradient();
    const Matrix15 H = m->element->gapHessian();
    ASSERT_GT(H.norm(), 1.0);
    // g is quadratic in the dofs (E1, E2): central differences are exact up
    // to round-off.
    const double h = 1e-4;
    int col = 0;
    for (int tag : {1, 2, 3}) {
      Node& n = m->node(tag);
      for (int dof = 0; dof < n.ndf(); ++dof, ++col) {
        const double u0 = n.trialDisp()(dof);
        n.setTrialDisp(dof, u0 + h);
        m->element->update();
        const double gp = m->element->gap();
        const Vector15 Bp = m->element->gapGradient();
        n.setTrialDisp(dof, u0 - h);
        m->element->update();
        const double gm = m->element->gap();
        const Vector15 Bm = m->element->gapGradient();
        n.setTrialDisp(dof, u0);
        EXPECT_NEAR(-(gp - gm) / (2 * h), B(col), 1e-11) << "B dof " << col;
        EXPECT_LE((-(Bp - Bm) / (2 * h) - H.col(col)).norm(), 1e-10) << "H column " << col;
      }
    }
    EXPECT_LE((H - H.transpose()).norm(), 0.0);
    m->element->update();
  }
}

TEST(BeamEndContact3D, TangentMatchesFiniteDifferencesStraightAndTurnedTip) {
  for (bool turned : {false, true}) {
    for (double offset : {0.0, 0.7}) {
      SCOPED_TRACE(std::string(turned ? "turned" : "straight") + " offset " + std::to_string(offset));
      auto m = turnedTipModel(turned, false, 0.0, offset);
      setTrial(*m, 20.0, 0.0);
      ASSERT_TRUE(m->element->inContact());
      // The residual is quadratic in the dofs: central differences are exact
      // up to round-off for any step.
      const TangentCheck check = checkTangent(*m->element, 1e-3);
      EXPECT_LE(check.relativeError(), 1e-10) << "max error " << check.maxError << " of " << check.maxEntry;
      // The rotation coupling -lambda H is there: the check is not only B.
      const Matrix K = m->element->tangentStiff();
      EXPECT_GT(K.block(0, 0, 15, 15).norm(), 1.0);
      EXPECT_EQ(K(15, 15), 0.0);
      EXPECT_EQ(K(16, 16), 1.0);
      EXPECT_EQ(K(17, 17), 1.0);
      for (int i : {16, 17}) {  // inert: coupled to nothing, condensed by the solver
        EXPECT_EQ(K.row(i).norm(), 1.0);
        EXPECT_EQ(K.col(i).norm(), 1.0);
        EXPECT_TRUE(m->element->hasConstantUncoupledDof(i));
      }
      EXPECT_FALSE(m->element->hasConstantUncoupledDof(15));
      EXPECT_EQ(m->element->resistingForce()(15), -m->element->gap());
      // Node j carries nothing.
      EXPECT_EQ(K.block(6, 0, 6, 18).norm(), 0.0);
      EXPECT_EQ(K.block(0, 6, 18, 6).norm(), 0.0);
    }
  }
}

TEST(BeamEndContact3Dp, TangentMatchesFiniteDifferencesStraightAndTurnedTip) {
  for (bool turned : {false, true}) {
    for (double offset : {0.0, 0.7}) {
      SCOPED_TRACE(std::string(turned ? "turned" : "straight") + " offset " + std::to_string(offset));
      auto m = turnedTipModel(turned, true, 0.0, offset);
      // 2e-4 penetration: t_n = 20 with the penalty 1e5.
      setTrial(*m, 0.0, 2e-4);
      ASSERT_NEAR(m->element->gap(), -2e-4, 1e-12);
      ASSERT_EQ(m->element->status(), 1);
      ASSERT_EQ(m->element->numDOF(), 15);
      // Steps well below the penetration keep the Macaulay bracket closed.
      const TangentCheck check = checkTangent(*m->element, 1e-7);
      EXPECT_LE(check.relativeError(), 1e-8) << "max error " << check.maxError << " of " << check.maxEntry;
    }
  }
}

TEST(BeamEndContact3D, OutOfContactTheMultiplierReturnsToZero) {
  const Vector3 axis = (kTip - kOther).normalized();
  auto m = makeModel(kTip + 0.5 * axis, false, 1);
  EXPECT_FALSE(m->element->inContact());
  Vector l(3);
  l << 7.0, 2.0, -3.0;
  m->setDisp(4, l);
  m->setDisp(3, Vector(-0.6 * axis));  // penetration, ignored while released
  m->element->update();
  const Vector f = m->element->resistingForce();
  EXPECT_EQ(f.head<15>().norm(), 0.0);
  EXPECT_EQ(f(15), 7.0);
  EXPECT_EQ(f(16), 2.0);
  EXPECT_EQ(f(17), -3.0);
  Matrix expectedK = Matrix::Zero(18, 18);
  expectedK(15, 15) = expectedK(16, 16) = expectedK(17, 17) = 1.0;
  EXPECT_EQ((Matrix(m->element->tangentStiff()) - expectedK).norm(), 0.0);
  EXPECT_EQ(m->element->setResponse({"status"}).value()(0), 0.0);
  EXPECT_EQ(m->element->setResponse({"force"}).value().norm(), 0.0);
}

TEST(BeamEndContact3D, ContactActionsBalance) {
  auto m = turnedTipModel(true, false, 0.0, 0.7);
  const BeamEndContactElement& e = *m->element;
  const double lambda = 30.0;
  // Translations only (no rotation increment): exact balance of force and
  // moment about the tip between the soil node and the end node.
  m->addDisp(3, Vector(Vector3(1e-3, -2e-3, 5e-4)));
  m->addDisp(1, Vector(Vector6((Vector6() << 2e-3, 1e-3, -1e-3, 0, 0, 0).finished())));
  m->setLambda(lambda);
  m->element->update();
  auto imbalance = [&](Vector3& force, Vector3& moment) {
    const Vector onSoil = m->element->setResponse({"force"}).value();
    const Vector onTip = m->element->setResponse({"masterforce"}).value();
    const Vector3 d = m->position(3) - m->position(1);
    force = Vector3(onSoil.head<3>()) + Vector3(onTip.head<3>());
    moment = Vector3(onTip.tail<3>()) + d.cross(Vector3(onSoil.head<3>()));
  };
  Vector3 force, moment;
  imbalance(force, moment);
  EXPECT_LE((Vector3(m->element->setResponse({"force"}).value()) - lambda * e.normal()).norm(), 1e-13 * lambda);
  EXPECT_LE(force.norm(), 1e-13 * lambda);
  EXPECT_LE(moment.norm(), 1e-13 * lambda);
  EXPECT_EQ(m->element->setResponse({"forcescalar"}).value()(0), lambda);
  // With a rotation increment dth the moment misses lambda d x (dth x n_n)
  // (the linearized normal E1), second order in the step's motion.
  const Vector3 dTheta(0.01, -0.02, 0.015);
  m->addDisp(1, Vector(Vector6((Vector6() << 0, 0, 0, dTheta).finished())));
  m->element->update();
  imbalance(force, moment);
  const Vector3 d = m->position(3) - m->position(1);
  EXPECT_LE(force.norm(), 1e-13 * lambda);
  EXPECT_LE((moment - lambda * d.cross(dTheta.cross(e.committedNormal()))).norm(), 1e-13 * lambda);
}

TEST(BeamEndContact3D, StatusIsDecidedAtCommit) {
  const Vector3 axis = (kTip - kOther).normalized();
  auto m = makeModel(kTip, false);
  auto& e = dynamic_cast<BeamEndContact3D&>(*m->element);
  ASSERT_TRUE(e.inContact());
  // Pressing: stays in contact.
  m->setLambda(50.0);
  e.update();
  m->commit();
  EXPECT_TRUE(e.inContact());
  // Tension beyond forceTol: the step keeps contact (the multiplier holds the
  // node on the face), the commit releases it.
  m->setLambda(-1.0);
  e.update();
  EXPECT_TRUE(e.shouldRelease());
  EXPECT_EQ(e.status(), 1);
  EXPECT_EQ(e.resistingForce()(15), -e.gap());
  m->commit();
  EXPECT_FALSE(e.inContact());
  // Released and ahead of the face beyond gapTol: stays out.
  m->setLambda(0.0);
  m->setDisp(3, Vector(0.01 * axis));
  e.update();
  EXPECT_EQ(e.status(), 0);
  m->commit();
  EXPECT_NEAR(e.committedGap(), 0.01, 1e-15);
  EXPECT_FALSE(e.inContact());
  // Behind the face (penetrating) at a commit: in contact from the next step.
  m->setDisp(3, Vector(-1e-3 * axis));
  e.update();
  EXPECT_FALSE(e.inContact());
  m->commit();
  EXPECT_TRUE(e.inContact());
  // Tension smaller than forceTol does not release.
  m->setLambda(-0.5e-8);
  e.update();
  m->commit();
  EXPECT_TRUE(e.inContact());
  // revertToStart brings back the initial status and normal.
  for (const auto& [tag, n] : m->d.nodes()) n->revertToStart();
  m->setLambda(-1.0);
  e.update();
  m->commit();
  ASSERT_FALSE(e.inContact());
  for (const auto& [tag, n] : m->d.nodes()) n->revertToStart();
  e.revertToStart();
  EXPECT_TRUE(e.inContact());
  EXPECT_LE((e.committedNormal() - axis).norm(), 1e-15);
}

TEST(BeamEndContact3Dp, ContactForceIsPenaltyTimesPenetration) {
  const Vector3 axis = (kTip - kOther).normalized();
  const Vector3 side = perpendicular(axis);
  const double penetration = 3e-4;
  auto m = makeModel(kTip + 0.3 * kRadius * side - penetration * axis, true);
  auto& e = dynamic_cast<BeamEndContact3Dp&>(*m->element);
  EXPECT_NEAR(e.normalForce(), kPenalty * penetration, 1e-9 * kPenalty * penetration);
  const Vector force = e.setResponse({"force"}).value();
  EXPECT_LE((force - Vector(kPenalty * penetration * axis)).norm(), 1e-9 * kPenalty * penetration);
  EXPECT_LE((e.resistingForce().segment<3>(12) + Vector3(force)).norm(), 1e-12 * kPenalty * penetration);
  EXPECT_FALSE(e.needsGeneralSolver());
  // Opening: no force at all.
  m->setDisp(3, Vector(2.0 * penetration * axis));
  e.update();
  EXPECT_EQ(e.resistingForce().norm(), 0.0);
  EXPECT_EQ(e.status(), 0);
}

TEST(BeamEndContact3Dp, NoContactInitiallyEngagesAfterTheFirstPenetratingStep) {
  const Vector3 axis = (kTip - kOther).normalized();
  auto m = makeModel(kTip + 1e-3 * axis, true, 1);
  auto& e = dynamic_cast<BeamEndContact3Dp&>(*m->element);
  EXPECT_FALSE(e.activated());
  m->setDisp(3, Vector(-2e-3 * axis));
  e.update();
  EXPECT_EQ(e.resistingForce().norm(), 0.0);
  m->commit();
  EXPECT_TRUE(e.activated());
  e.update();
  EXPECT_NEAR(e.normalForce(), kPenalty * 1e-3, 1e-9);
  for (const auto& [tag, n] : m->d.nodes()) n->revertToStart();
  e.revertToStart();
  EXPECT_FALSE(e.activated());
}

TEST(BeamEndContact3D, ResponsesHaveTheirNamesAndSizes) {
  auto m = turnedTipModel(true, false, 0.0, 0.5);
  setTrial(*m, 20.0, 0.0);
  const std::pair<const char*, std::size_t> expected[] = {{"force", 3},        {"forcescalar", 1}, {"masterforce", 6},
                                                          {"primaryforce", 6}, {"gap", 1},         {"status", 1},
                                                          {"normal", 3},       {"Force", 3}};
  for (const auto& [what, size] : expected) {
    const Response r = m->element->setResponse({what});
    ASSERT_TRUE(r) << what;
    EXPECT_EQ(r.size(), size) << what;
    EXPECT_EQ(static_cast<std::size_t>(r.value().size()), size) << what;
  }
  EXPECT_FALSE(m->element->setResponse({"slip"}));
  const Vector master = m->element->setResponse({"masterforce"}).value();
  EXPECT_LE((master + m->element->resistingForce().head(6)).norm(), 0.0);
  EXPECT_EQ(m->element->setResponse({"status"}).value()(0), 1.0);
}

TEST(BeamEndContact3D, BadInputGivesClearErrors) {
  auto build = [](const std::function<void(Domain&)>& tweak, int sNdf = 3, int lNdf = 3, int iNdf = 6) {
    Domain d;
    addNode(d, 1, iNdf, 0, 0, 0);
    addNode(d, 2, 6, 0, 0, 2);
    addNode(d, 3, sNdf, 0, 0, 0);
    addNode(d, 4, lNdf, 0, 0, 0);
    addNode(d, 5, 6, 0, 0, 0);
    tweak(d);
  };
  auto contact = [](Domain& d, int tag, double radius = 0.3, int l = 4, int j = 2) {
    addElement(d, "BeamEndContact3D", tag, 1, j, 3, l, radius, 1e-6, 1e-6);
  };
  auto error = [&](const std::function<void(Domain&)>& tweak, int sNdf = 3, int lNdf = 3, int iNdf = 6) {
    return errorOf([&] { build(tweak, sNdf, lNdf, iNdf); });
  };
  auto has = [](const std::string& message, const std::string& fragment) {
    return message.find(fragment) != std::string::npos;
  };
  EXPECT_EQ(error([&](Domain& d) { contact(d, 1); }), "(no error)");
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1); }, 3, 3, 3),
                  "element BeamEndContact3D 1: beam end node 1 has 3 dofs, expected 6"));
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1); }, 6), "secondary (solid) node 3 has 6 dofs, expected 3"));
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1); }, 3, 6), "multiplier node 4 has 6 dofs, expected 3"));
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1, 0.0); }), "argument 6 (radius): expected a positive number"));
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1, -1.0); }), "argument 6 (radius): expected a positive number"));
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1, 0.3, 3); }), "node 3 appears twice"));
  EXPECT_TRUE(has(error([&](Domain& d) { contact(d, 1, 0.3, 4, 5); }),
                  "element BeamEndContact3D 1: the beam nodes 1 and 5 coincide"));
  EXPECT_TRUE(has(error([&](Domain& d) {
                    contact(d, 1);
                    contact(d, 2);
                  }),
                  "element BeamEndContact3D 2: multiplier node 4 is also used by element 1; every BeamEndContact3D "
                  "needs its own multiplier node"));
  EXPECT_TRUE(has(error([&](Domain& d) {
                    d.addSP(SPConstraint{4, 0, 0.0}, "test");
                    contact(d, 1);
                  }),
                  "multiplier node 4 is fixed (dof 1)"));
  // A fix added after the element is caught at the next update.
  EXPECT_TRUE(has(error([&](Domain& d) {
                    contact(d, 1);
                    d.addSP(SPConstraint{4, 1, 0.0}, "test");
                    d.update();
                  }),
                  "element BeamEndContact3D 1: multiplier node 4 is fixed (dof 2)"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3D", 1, 1, 2, 3, 4, 0.3, 1e-6, 1e-6, 2); }),
                  "argument 9 (cFlag): expected 0 (initially in contact) or 1 (initially not in contact)"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3D", 1, 1, 2, 3, 4, 0.3, -1e-6, 1e-6); }),
                  "argument 7 (gapTol): expected a number >= 0"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3D", 1, 1, 2, 3, 4, 0.3, 1e-6); }),
                  "argument 8 (forceTol)"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3D", 1, 1, 2, 9, 4, 0.3, 1e-6, 1e-6); }),
                  "node 9 does not exist"));
  // The penalty form.
  EXPECT_EQ(error([&](Domain& d) { addElement(d, "BeamEndContact3Dp", 1, 1, 2, 3, 0.3, 1e5); }), "(no error)");
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3Dp", 1, 1, 2, 3, 0.3, 0.0); }),
                  "element BeamEndContact3Dp 1: argument 6 (penalty): expected a positive number"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3Dp", 1, 1, 2, 3, 0.3, 1e5, 0, 7); }),
                  "element BeamEndContact3Dp 1"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3Dp", 1, 1, 2, 1, 0.3, 1e5); }),
                  "node 1 appears twice"));
  EXPECT_TRUE(has(error([&](Domain& d) { addElement(d, "BeamEndContact3Dp", 1, 3, 2, 1, 0.3, 1e5); }, 3, 3, 3),
                  "element BeamEndContact3Dp 1: beam end node 3 has 3 dofs, expected 6"));
}

// ----------------------------------------------------------------------------------
// A pile standing on a block of soil.

namespace {

using beamsolid::testing::Script;

constexpr double kPileRadius = 0.3;
constexpr double kPileE = 3e7, kPileLength = 5.0;
constexpr double kSoilE = 1e4, kSoilNu = 0.3;
constexpr double kHeadLoad = 100.0;
constexpr int kTipNode = 1, kHeadNode = 3, kMultiplierNode = 900, kContact = 50;

double pileArea() { return M_PI * kPileRadius * kPileRadius; }
// Axial flexibility of the pile between head and tip.
double pileFlexibility() { return kPileLength / (kPileE * pileArea()); }

// Soil block [-1, 1] x [-1, 1] x [-1, 0] of 4 x 4 x 2 stdBricks (material 1),
// base fixed, sides on rollers. Node tags 100 + i + 5 j + 25 k (k = 0 at the
// base); returns the tag of the top centre node (0, 0, 0).
int buildSoilBlock(Script& s) {
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("nDMaterial", "ElasticIsotropic", 1, kSoilE, kSoilNu);
  auto tag = [](int i, int j, int k) { return 100 + i + 5 * j + 25 * k; };
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 4; ++i) {
        s("node", tag(i, j, k), -1.0 + 0.5 * i, -1.0 + 0.5 * j, -1.0 + 0.5 * k);
        const int fx = k == 0 || i == 0 || i == 4, fy = k == 0 || j == 0 || j == 4, fz = k == 0;
        if (fx || fy || fz) s("fix", tag(i, j, k), fx, fy, fz);
      }
  int brick = 1000;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        s("element", "stdBrick", brick++, tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k),
          tag(i, j, k + 1), tag(i + 1, j, k + 1), tag(i + 1, j + 1, k + 1), tag(i, j + 1, k + 1), 1);
  return tag(2, 2, 2);
}

std::vector<int> soilBaseNodes() {
  std::vector<int> tags;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) tags.push_back(100 + i + 5 * j);
  return tags;
}

void staticAnalysis(Script& s, double dt) {
  s("constraints", "Transformation");
  s("numberer", "RCM");
  s("system", "UmfPack");
  s("test", "NormDispIncr", 1e-12, 25);
  s("algorithm", "Newton");
  s("integrator", "LoadControl", dt);
  s("analysis", "Static");
}

// Settlement flexibility of the soil block's top centre node under a point
// load, from the soil alone (the independent solution the pile sees).
double soilFlexibility() {
  Script s;
  const int centre = buildSoilBlock(s);
  s("timeSeries", "Linear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", centre, 0.0, 0.0, -kHeadLoad);
  staticAnalysis(s, 1.0);
  EXPECT_EQ(s.integer("analyze", 1), 0);
  return -s.number("nodeDisp", centre, 3) / kHeadLoad;
}

// Pile nodes 1 (tip, z = 0, on the soil's top centre node), 2, 3 (head,
// z = 5), two elasticBeamColumns; the head is held laterally and in rotation.
// The tip contact is BeamEndContact3D (multiplier node 900) or, with
// penalty > 0, BeamEndContact3Dp. Returns the soil node under the tip.
int buildPileOnSoil(Script& s, double penalty = 0.0) {
  s("wipe");
  s("model", "basic", "-ndm", 3, "-ndf", 6);
  for (int k = 0; k < 3; ++k) s("node", 1 + k, 0.0, 0.0, 0.5 * kPileLength * k);
  s("fix", kHeadNode, 1, 1, 0, 1, 1, 1);
  s("geomTransf", "Linear", 1, 1.0, 0.0, 0.0);
  const double I = M_PI * std::pow(kPileRadius, 4) / 4.0;
  for (int k = 0; k < 2; ++k)
    s("element", "elasticBeamColumn", 1 + k, 1 + k, 2 + k, pileArea(), kPileE, 1.2e7, 2 * I, I, I, 1);
  const int soil = buildSoilBlock(s);
  if (penalty > 0.0) {
    s("element", "BeamEndContact3Dp", kContact, kTipNode, 2, soil, kPileRadius, penalty);
  } else {
    s("node", kMultiplierNode, 0.0, 0.0, 0.0);
    s("element", "BeamEndContact3D", kContact, kTipNode, 2, soil, kMultiplierNode, kPileRadius, 1e-8, 1e-8);
  }
  return soil;
}

// Head displacement imposed (total, pattern 2), one step; the tip force.
double tipForceUnderHeadDisplacement(double headDisp, double penalty) {
  Script s;
  buildPileOnSoil(s, penalty);
  s("timeSeries", "Linear", 2);
  s("pattern", "Plain", 2, 2);
  s("sp", kHeadNode, 3, headDisp);
  staticAnalysis(s, 1.0);
  EXPECT_EQ(s.integer("analyze", 1), 0) << "penalty " << penalty;
  return s.list("eleResponse", kContact, "forcescalar")[0];
}

}  // namespace

TEST(BeamEndContactAnalysis, TheTipCarriesTheHeadLoadAndTheMultiplierClosesTheGap) {
  const double fs = soilFlexibility();
  ASSERT_GT(fs, 0.0);
  Script s;
  const int soil = buildPileOnSoil(s);
  s("timeSeries", "Linear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", kHeadNode, 0.0, 0.0, -kHeadLoad, 0.0, 0.0, 0.0);
  staticAnalysis(s, 0.25);
  ASSERT_EQ(s.integer("analyze", 4), 0);

  const double P = kHeadLoad;
  // The tip contact force equals the head load (the pile has no other
  // vertical support); lambda is the multiplier node's first dof.
  EXPECT_NEAR(s.list("eleResponse", kContact, "forcescalar")[0], P, 1e-10 * P);
  EXPECT_NEAR(s.number("nodeDisp", kMultiplierNode, 1), P, 1e-10 * P);
  const auto onSoil = s.list("eleResponse", kContact, "force");
  EXPECT_NEAR(onSoil[2], -P, 1e-10 * P);
  EXPECT_NEAR(std::hypot(onSoil[0], onSoil[1]), 0.0, 1e-10 * P);
  const auto onTip = s.list("eleResponse", kContact, "masterforce");
  EXPECT_NEAR(onTip[2], P, 1e-10 * P);
  for (int k : {0, 1, 3, 4, 5}) EXPECT_NEAR(onTip[k], 0.0, 1e-10 * P) << "component " << k;
  EXPECT_EQ(s.list("eleResponse", kContact, "status")[0], 1.0);
  // The soil carries it to its base.
  s("reactions");
  double baseReaction = 0.0;
  for (int n : soilBaseNodes()) baseReaction += s.number("nodeReaction", n, 3);
  EXPECT_NEAR(baseReaction, P, 1e-9 * P);
  // g = 0: the tip follows the soil node, which settles as under a point
  // load P on the soil alone; the head adds the pile's shortening.
  const double settlement = -fs * P;
  EXPECT_NEAR(s.list("eleResponse", kContact, "gap")[0], 0.0, 1e-12 * fs * P);
  EXPECT_NEAR(s.number("nodeDisp", soil, 3), settlement, 1e-9 * fs * P);
  EXPECT_NEAR(s.number("nodeDisp", kTipNode, 3), settlement, 1e-9 * fs * P);
  EXPECT_NEAR(s.number("nodeDisp", kHeadNode, 3), settlement - pileFlexibility() * P, 1e-9 * fs * P);
}

TEST(BeamEndContactAnalysis, PullingReleasesAndPushingClosesOneStepLate) {
  // After the head load, the head displacement is imposed: from its loaded
  // value u0 up to -u0/2 (the tip lifts off the soil) and back to u0. With
  // the soil's and the pile's flexibilities fs, fp:
  //   in contact  lambda = -w_h / (fs + fp), soil node at -fs lambda, g = 0;
  //   released    lambda = 0, soil node back at 0, tip at w_h, g = w_h.
  // Status by C20 at each commit: released at the commit of the first step
  // that ends with lambda <= -forceTol (that step holds the tip down with a
  // tension: the lag), closed at the commit of the first step that ends with
  // g < gapTol (that step ends with the tip inside the soil: the lag).
  const double fs = soilFlexibility(), fp = pileFlexibility();
  const double P = kHeadLoad;
  Script s;
  const int soil = buildPileOnSoil(s);
  s("timeSeries", "Linear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", kHeadNode, 0.0, 0.0, -P, 0.0, 0.0, 0.0);
  staticAnalysis(s, 0.5);
  ASSERT_EQ(s.integer("analyze", 2), 0);
  s("loadConst", "-time", 0.0);
  s("wipeAnalysis");
  const double u0 = s.number("nodeDisp", kHeadNode, 3);
  ASSERT_NEAR(u0, -(fs + fp) * P, 1e-9 * (fs + fp) * P);
  const double uUp = -0.5 * u0;
  s("timeSeries", "Path", 2, "-time", 0.0, 1.0, 2.0, "-values", u0, uUp, u0);
  s("pattern", "Plain", 2, 2);
  s("sp", kHeadNode, 3, 1.0);
  // w_h = 0 at t = 2/3 and 4/3: steps of 0.1 do not land on it.
  staticAnalysis(s, 0.1);
  bool inContact = true;
  int releases = 0, closings = 0;
  const double scale = (fs + fp) * P;
  for (int step = 1; step <= 20; ++step) {
    ASSERT_EQ(s.integer("analyze", 1), 0) << "step " << step;
    const double t = s.number("getTime");
    const double wh = t <= 1.0 ? u0 + (uUp - u0) * t : uUp + (u0 - uUp) * (t - 1.0);
    const double lambda = s.list("eleResponse", kContact, "forcescalar")[0];
    const double gap = s.list("eleResponse", kContact, "gap")[0];
    EXPECT_EQ(s.list("eleResponse", kContact, "status")[0], inContact ? 1.0 : 0.0) << "step " << step;
    if (inContact) {
      EXPECT_NEAR(lambda, -wh / (fs + fp), 1e-9 * P) << "step " << step;
      EXPECT_NEAR(gap, 0.0, 1e-12 * scale) << "step " << step;
      EXPECT_NEAR(s.number("nodeDisp", soil, 3), -fs * lambda, 1e-9 * scale) << "step " << step;
    } else {
      EXPECT_EQ(lambda, 0.0) << "step " << step;
      EXPECT_NEAR(gap, wh, 1e-9 * scale) << "step " << step;
      EXPECT_NEAR(s.number("nodeDisp", soil, 3), 0.0, 1e-9 * scale) << "step " << step;
      EXPECT_NEAR(s.number("nodeDisp", kTipNode, 3), wh, 1e-9 * scale) << "step " << step;
    }
    const bool next = gap < 1e-8 && !(inContact && lambda <= -1e-8);
    if (inContact && !next) {
      ++releases;
      EXPECT_LT(lambda, 0.0) << "the releasing step holds the tip with a tension";
      EXPECT_NEAR(t, 0.7, 1e-12);
    }
    if (!inContact && next) {
      ++closings;
      EXPECT_LT(gap, 0.0) << "the closing step ends with the tip inside the soil";
      EXPECT_NEAR(t, 1.4, 1e-12);
    }
    inContact = next;
  }
  EXPECT_EQ(releases, 1);
  EXPECT_EQ(closings, 1);
  // Back at u0: the tip carries P again.
  EXPECT_NEAR(s.list("eleResponse", kContact, "forcescalar")[0], P, 1e-9 * P);
}

TEST(BeamEndContactAnalysis, PenaltyConvergesToTheLagrangeAnswer) {
  // Head pushed down by w_h: the Lagrange tip force is -w_h / (fs + fp); the
  // penalty adds a spring 1/kappa in series, so its relative error is
  // (1/kappa) / (fs + fp + 1/kappa): first order in 1/kappa. (Beyond
  // kappa ~ 1e9 here, i.e. 1e5 times the pile-soil stiffness, round-off of
  // the ill-conditioned system, ~ eps kappa (fs + fp), hides the error.)
  const double fs = soilFlexibility(), fp = pileFlexibility();
  const double wh = -(fs + fp) * kHeadLoad;
  const double lagrange = tipForceUnderHeadDisplacement(wh, 0.0);
  EXPECT_NEAR(lagrange, kHeadLoad, 1e-9 * kHeadLoad);
  double previous = 1.0;
  for (double kappa = 1e3; kappa <= 1e9 * 1.0001; kappa *= 10.0) {
    const double penalty = tipForceUnderHeadDisplacement(wh, kappa);
    const double error = std::abs(penalty - lagrange) / lagrange;
    const double predicted = (1.0 / kappa) / (fs + fp + 1.0 / kappa);
    EXPECT_NEAR(error, predicted, 1e-4 * predicted) << "kappa " << kappa;
    EXPECT_LT(error, previous) << "kappa " << kappa;
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}
