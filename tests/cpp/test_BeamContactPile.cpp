// Chained beam contact ('-pile'): a soil node handed over from segment to
// segment keeps its friction state, lambda and status exactly; the nodal
// frames a handed-over element uses are the ones the paper's element tracks
// on that segment; the tangent stays consistent after a hand-over; a node
// level with a beam node is held; an analysis renumbers after a hand-over
// (forces go to the new segment's nodes). Also Element::reconnect and the
// Domain's cached node usage.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/contact/BeamContact3D.h"
#include "elements/contact/BeamContact3Dp.h"
#include "support/Script.h"
#include "support/TestSpring.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

constexpr double kRadius = 0.3;
constexpr double kMu = 0.3, kG = 1000.0, kC = 0.5;

using beamsolid::testsupport::errorOf;

void addLinearTransf(Domain& d, int tag, const Vector3& vecxz) {
  CommandArgs a = args("geomTransf", tag, vecxz.x(), vecxz.y(), vecxz.z());
  d.geomTransfs.add(tag, std::shared_ptr<CrdTransf>(Registry::global().geomTransfs.get("Linear")(a, d)), "test");
}

// Pile nodes 1, 2, ... (ndf 6) at `points`, geomTransf 1 (Linear, vecxz),
// ContactMaterial3D 1.
void buildPile(Domain& d, const std::vector<Vector3>& points, const Vector3& vecxz = Vector3(1.0, 0.0, 0.0)) {
  for (std::size_t k = 0; k < points.size(); ++k)
    addNode(d, int(k) + 1, 6, points[k].x(), points[k].y(), points[k].z());
  addLinearTransf(d, 1, vecxz);
  addNDMaterial(d, "ContactMaterial3D", 1, kMu, kG, kC, 0.0);
}

std::vector<int> pileTags(const Domain& d) {
  std::vector<int> tags;
  for (const auto& [tag, n] : d.nodes())
    if (n->ndf() == 6) tags.push_back(tag);
  return tags;
}

// Soil node s (and multiplier node l) at x, and a chained (or unchained)
// BeamContact3D `tag` on pile segment i-j.
BeamContact3D& addContact(Domain& d, int tag, int i, int j, int s, int l, const Vector3& x, bool chained = true) {
  addNode(d, s, 3, x.x(), x.y(), x.z());
  addNode(d, l, 3, x.x(), x.y(), x.z());
  if (chained)
    return dynamic_cast<BeamContact3D&>(
        addElement(d, "BeamContact3D", tag, i, j, s, l, kRadius, 1, 1, 1e-8, 1e-8, 0, "-pile", pileTags(d)));
  return dynamic_cast<BeamContact3D&>(addElement(d, "BeamContact3D", tag, i, j, s, l, kRadius, 1, 1, 1e-8, 1e-8));
}

BeamContact3Dp& addPenaltyContact(Domain& d, int tag, int i, int j, int s, const Vector3& x) {
  addNode(d, s, 3, x.x(), x.y(), x.z());
  return dynamic_cast<BeamContact3Dp&>(
      addElement(d, "BeamContact3Dp", tag, i, j, s, kRadius, 1, 1, 1e5, 0, "-pile", pileTags(d)));
}

void setLambda(Domain& d, int l, double lambda) {
  Vector v = Vector::Zero(3);
  v(0) = lambda;
  d.node(l, "test").setTrialDisp(v);
}

void setDisp(Domain& d, int tag, const Vector& u) { d.node(tag, "test").setTrialDisp(u); }

// Physical elastic slip s_e^alpha g_alpha of an element's material (trial).
Vector3 physicalElasticSlip(const BeamContactElement& e) {
  const Eigen::Vector2d& s = e.material().elasticSlip();
  return s(0) * e.geometry().covariantBase(0) + s(1) * e.geometry().covariantBase(1);
}

}  // namespace

TEST(BeamContactPile, HandOverKeepsFrictionStateLambdaAndStatusExactly) {
  // Segments of different lengths (2 and 1), so that the surface coordinate
  // s^xi of the friction state changes scale at the hand-over.
  Domain d;
  buildPile(d, {Vector3(0, 0, 0), Vector3(0, 0, 2), Vector3(0, 0, 3)});
  const double z0 = 2.0 - 4e-4;  // xi = 0.9998 on segment 1-2
  BeamContact3D& e = addContact(d, 1, 1, 2, 10, 11, Vector3(kRadius, 0.0, z0));
  ASSERT_EQ(e.segment(), 0);
  ASSERT_TRUE(e.inContact());
  const long stamp0 = d.modelStamp();

  // Sticking across the beam node: the elastic slip of 1e-3 moves the
  // projection to xi = 1.0003.
  const double lambda = 50.0, delta = 1e-3;
  setLambda(d, 11, lambda);
  setDisp(d, 10, Vector(Vector3(0.0, 0.0, delta)));
  d.update();
  ASSERT_EQ(e.status(), BeamContactElement::Status::Sticking);
  const Vector3 frictionBefore = e.frictionForce();
  EXPECT_LE((frictionBefore - Vector3(0.0, 0.0, -kG * delta)).norm(), 1e-12);
  EXPECT_NEAR(e.material().elasticSlip()(0), delta / 2.0, 1e-16);
  const Vector3 elasticBefore = physicalElasticSlip(e);
  d.commit();

  EXPECT_EQ(e.segment(), 1);
  EXPECT_EQ(e.handOverCount(), 1);
  EXPECT_EQ(e.nodeTags(), (std::vector<int>{2, 3, 10, 11}));
  EXPECT_EQ(e.nodes()[0]->tag(), 2);
  EXPECT_EQ(e.numDOF(), 18);
  EXPECT_GT(d.modelStamp(), stamp0);
  EXPECT_EQ(d.nodeUsage(1).elements, 0);
  EXPECT_EQ(d.nodeUsage(3).elements, 1);
  EXPECT_TRUE(e.inContact());
  EXPECT_EQ(e.lambda(), lambda);
  EXPECT_NEAR(e.geometry().xi(), (z0 + delta - 2.0) / 1.0, 1e-12);
  // The friction state in the new coordinates: s^xi = delta / L2, the same
  // physical elastic slip and friction force.
  EXPECT_NEAR(e.material().committedElasticSlip()(0), delta / 1.0, 1e-15);
  EXPECT_NEAR(e.material().committedElasticSlip()(1), 0.0, 1e-18);
  EXPECT_LE((physicalElasticSlip(e) - elasticBefore).norm(), 1e-16);
  EXPECT_LE((e.frictionForce() - frictionBefore).norm(), 1e-12);
  EXPECT_EQ(e.status(), BeamContactElement::Status::Sticking);
  EXPECT_EQ(e.normalForce(), lambda);

  // Back by delta: the stick spring carried over unloads to zero friction,
  // and the node goes back to segment 1-2.
  setDisp(d, 10, Vector(Vector3::Zero()));
  d.update();
  EXPECT_LE(e.frictionForce().norm(), 1e-12);
  d.commit();
  EXPECT_EQ(e.segment(), 0);
  EXPECT_EQ(e.handOverCount(), 2);
  EXPECT_EQ(e.nodeTags(), (std::vector<int>{1, 2, 10, 11}));

  // Sliding 0.9 up in one step: friction mu lambda + c against the motion on
  // both sides of the hand-over; the accumulated slip is the distance moved.
  setDisp(d, 10, Vector(Vector3(0.0, 0.0, 0.9)));
  d.update();
  ASSERT_EQ(e.status(), BeamContactElement::Status::Sliding);
  const double capacity = kMu * lambda + kC;
  EXPECT_LE((e.frictionForce() - Vector3(0.0, 0.0, -capacity)).norm(), 1e-10 * capacity);
  d.commit();
  EXPECT_EQ(e.segment(), 1);
  EXPECT_EQ(e.handOverCount(), 3);
  EXPECT_LE((e.frictionForce() - Vector3(0.0, 0.0, -capacity)).norm(), 1e-10 * capacity);
  EXPECT_NEAR(e.totalSlip()(0), 0.9, 1e-12);
  EXPECT_EQ(e.lambda(), lambda);
  EXPECT_TRUE(e.inContact());

  // Just beyond the pile's top (xi = 1.1996, within the end allowance of a
  // quarter segment) the node is still held: it stands for the soil below it.
  setDisp(d, 10, Vector(Vector3(0.0, 0.0, 1.2)));
  d.update();
  d.commit();
  EXPECT_EQ(e.segment(), 1);
  EXPECT_NEAR(e.geometry().xi(), z0 + 1.2 - 2.0, 1e-12);
  EXPECT_TRUE(e.ownsNode());
  EXPECT_TRUE(e.inContact());

  // Further (xi = 1.2996 > 1 + kEndAllowance) it is released; the element
  // stays on the last segment.
  setDisp(d, 10, Vector(Vector3(0.0, 0.0, 1.3)));
  d.update();
  d.commit();
  EXPECT_EQ(e.segment(), 1);
  EXPECT_GT(e.geometry().xi(), 1.0 + BeamContactElement::kEndAllowance);
  EXPECT_FALSE(e.ownsNode());
  EXPECT_FALSE(e.inContact());

  // revertToStart: back on the first segment and its nodes.
  for (const auto& [tag, n] : d.nodes()) n->revertToStart();
  e.revertToStart();
  EXPECT_EQ(e.segment(), 0);
  EXPECT_EQ(e.handOverCount(), 0);
  EXPECT_EQ(e.nodeTags(), (std::vector<int>{1, 2, 10, 11}));
  EXPECT_TRUE(e.inContact());
  EXPECT_NEAR(e.geometry().xi(), z0 / 2.0, 1e-14);
}

TEST(BeamContactPile, NodeLevelWithABeamNodeIsHeldByItsSegment) {
  Domain d;
  buildPile(d, {Vector3(0, 0, 0), Vector3(0, 0, 1), Vector3(0, 0, 2)});
  // The same level (z = 1) held from the segment below (xi = 1) and from the
  // one above (xi = 0); neither hands it over.
  BeamContact3D& below = addContact(d, 1, 1, 2, 10, 11, Vector3(kRadius, 0.0, 1.0));
  BeamContact3D& above = addContact(d, 2, 2, 3, 12, 13, Vector3(0.0, kRadius, 1.0));
  // At the pile's ends the closed interval holds too; beyond them it does not.
  BeamContact3D& tip = addContact(d, 3, 1, 2, 14, 15, Vector3(-kRadius, 0.0, 0.0));
  BeamContact3D& beyond = addContact(d, 4, 1, 2, 16, 17, Vector3(0.0, -kRadius, -0.01));
  // The paper's element (no chain) never holds a node level with a beam node.
  BeamContact3D& single =
      addContact(d, 5, 2, 3, 18, 19, Vector3(kRadius / std::sqrt(2.0), kRadius / std::sqrt(2.0), 1.0), false);
  EXPECT_NEAR(below.geometry().xi(), 1.0, 1e-15);
  EXPECT_NEAR(above.geometry().xi(), 0.0, 1e-15);
  EXPECT_NEAR(tip.geometry().xi(), 0.0, 1e-15);
  for (BeamContact3D* e : {&below, &above, &tip}) EXPECT_TRUE(e->inContact()) << e->tag();
  EXPECT_EQ(below.segment(), 0);
  EXPECT_EQ(above.segment(), 1);
  EXPECT_FALSE(beyond.inContact());
  EXPECT_FALSE(single.inContact());

  // Pressed and dragged around the pile (sliding): the nodes carry
  // mu lambda + c, steps go by without a hand-over.
  const double lambda = 30.0;
  for (int step = 1; step <= 3; ++step) {
    setLambda(d, 11, lambda);
    setLambda(d, 13, lambda);
    setLambda(d, 15, lambda);
    // Along the circle (the held tangent plane is left inwards: in contact).
    const double phi = 0.05 * step;
    setDisp(d, 10, Vector(Vector3(kRadius * (std::cos(phi) - 1.0), kRadius * std::sin(phi), 0.0)));
    setDisp(d, 14, Vector(Vector3(-kRadius * (std::cos(phi) - 1.0), -kRadius * std::sin(phi), 0.0)));
    d.update();
    for (BeamContact3D* e : {&below, &tip}) {
      ASSERT_EQ(e->status(), BeamContactElement::Status::Sliding) << e->tag();
      EXPECT_NEAR(e->forceScalars()(0), lambda, 0.0);
    }
    EXPECT_NEAR(below.frictionForce().norm(), kMu * lambda + kC, 1e-9);
    EXPECT_EQ(above.status(), BeamContactElement::Status::Sticking);
    d.commit();
    for (BeamContact3D* e : {&below, &above, &tip}) {
      EXPECT_TRUE(e->inContact()) << e->tag() << " step " << step;
      EXPECT_EQ(e->handOverCount(), 0) << e->tag();
    }
  }
  // The tangent at xi = 1 and xi = 0 is consistent.
  setDisp(d, 10, Vector(Vector3(0.0, 0.04, 0.002)));
  setDisp(d, 14, Vector(Vector3(0.0, 1e-4, 0.0)));
  for (BeamContact3D* e : {&below, &tip}) {
    const TangentCheck check = checkTangent(*e, 1e-7);
    EXPECT_LE(check.relativeError(), 1e-6) << e->tag() << ": " << check.maxError << " of " << check.maxEntry;
  }
}

namespace {

// A kinked, inclined three-segment pile bent and twisted over three commits,
// with chained elements 1 (soil node 10 near the end of segment 1-2) and 3
// (soil node 30 on segment 2-3) and an unchained element 2 (soil node 20 on
// segment 2-3); penalty elements when `penalty`. After each commit the soil
// nodes are put back on the surface at their projections (and committed).
struct BentPile {
  Domain d;
  BeamContactElement* moving = nullptr;
  BeamContactElement* chainedReference = nullptr;
  BeamContactElement* unchainedReference = nullptr;
};

Vector3 perpendicularTo(const Vector3& axis) { return axis.cross(Vector3::UnitX()).normalized(); }

void toSurface(Domain& d, BeamContactElement& e, int soilNode) {
  const BeamContactGeometry& g = e.geometry();
  const Node& s = d.node(soilNode, "test");
  setDisp(d, soilNode, Vector(g.centerlinePoint() + kRadius * g.normal() - s.crd()));
}

std::unique_ptr<BentPile> bentPile(bool penalty) {
  auto m = std::make_unique<BentPile>();
  Domain& d = m->d;
  const std::vector<Vector3> points{Vector3(0.1, -0.2, 0.0), Vector3(0.3, 0.1, 1.5), Vector3(0.35, 0.15, 3.0),
                                    Vector3(0.3, 0.25, 4.5)};
  buildPile(d, points, Vector3(0.3, -1.0, 0.2));
  auto on = [&](int k, double xi) {
    const Vector3 a = points[k], b = points[k + 1];
    return Vector3(a + xi * (b - a) + kRadius * perpendicularTo(b - a));
  };
  if (penalty) {
    m->moving = &addPenaltyContact(d, 1, 1, 2, 10, on(0, 0.97));
    m->chainedReference = &addPenaltyContact(d, 3, 2, 3, 30, on(1, 0.5));
    addNode(d, 20, 3, on(1, 0.4).x(), on(1, 0.4).y(), on(1, 0.4).z());
    m->unchainedReference = &dynamic_cast<BeamContactElement&>(
        addElement(d, "BeamContact3Dp", 2, 2, 3, 20, kRadius, 1, 1, 1e5));
  } else {
    m->moving = &addContact(d, 1, 1, 2, 10, 11, on(0, 0.97));
    m->chainedReference = &addContact(d, 3, 2, 3, 30, 31, on(1, 0.5));
    m->unchainedReference = &addContact(d, 2, 2, 3, 20, 21, on(1, 0.4), false);
  }
  const int soil[3] = {10, 20, 30};
  BeamContactElement* elements[3] = {m->moving, m->unchainedReference, m->chainedReference};
  for (int step = 1; step <= 3; ++step) {
    for (int k = 1; k <= 4; ++k) {
      Vector6 u;
      const double f = 0.01 * step * k;
      u << 0.2 * f, -0.3 * f, 0.05 * f, 0.6 * f * std::cos(k), -0.5 * f * std::sin(k + step), 0.8 * f;
      setDisp(d, k, Vector(u));
    }
    d.update();
    d.commit();
    for (int i = 0; i < 3; ++i) toSurface(d, *elements[i], soil[i]);
    d.update();
    d.commit();
  }
  return m;
}

}  // namespace

TEST(BeamContactPile, HandedOverElementUsesTheFramesTheSegmentsElementsTrackAndAConsistentTangent) {
  for (bool penalty : {false, true}) {
    SCOPED_TRACE(penalty ? "BeamContact3Dp" : "BeamContact3D");
    auto m = bentPile(penalty);
    Domain& d = m->d;
    BeamContactElement& e = *m->moving;
    ASSERT_EQ(e.segment(), 0);
    ASSERT_TRUE(e.inContact());
    // Slide the soil node along the pile past node 2 (along c1: no change of
    // the held gap), then commit: hand-over to segment 2-3.
    const Vector3 c1 = e.geometry().frame().col(0);
    setDisp(d, 10, Vector(d.node(10, "test").trialDisp() + 0.1 * 1.5 * c1));
    if (!penalty) setLambda(d, 11, 20.0);
    d.update();
    d.commit();
    ASSERT_EQ(e.segment(), 1);
    ASSERT_EQ(e.handOverCount(), 1);
    ASSERT_TRUE(e.inContact());
    EXPECT_GT(e.geometry().xi(), 0.0);
    EXPECT_LT(e.geometry().xi(), 0.2);
    // The nodal frames of segment 2-3: exactly those of the chained element
    // that was there all along, and those the paper's element tracks itself
    // (same exponential maps, other rounding order).
    const BeamContactGeometry& g = e.geometry();
    EXPECT_EQ((g.frameA() - m->chainedReference->geometry().frameA()).norm(), 0.0);
    EXPECT_EQ((g.frameB() - m->chainedReference->geometry().frameB()).norm(), 0.0);
    EXPECT_LE((g.frameA() - m->unchainedReference->geometry().frameA()).norm(), 1e-14);
    EXPECT_LE((g.frameB() - m->unchainedReference->geometry().frameB()).norm(), 1e-14);
    EXPECT_NEAR(g.twist(), m->unchainedReference->geometry().twist(), 1e-14);
    EXPECT_GT(std::abs(g.twist()), 0.01);

    // Tangent on the new segment's dofs, sticking and sliding, from a
    // committed state on the surface without friction memory (t_n = 0).
    toSurface(d, e, 10);
    if (!penalty) setLambda(d, 11, 0.0);
    d.update();
    d.commit();
    ASSERT_EQ(e.material().committedElasticSlip().norm(), 0.0);
    for (double slip : {2e-5, 0.02}) {
      for (const auto& [tag, n] : d.nodes()) n->revertToLastCommit();
      const BeamContactGeometry& h = e.geometry();
      Vector6 da, db;
      da << 2e-4, -1e-4, 3e-4, 1e-3, -2e-3, 1.5e-3;
      db << -1e-4, 2e-4, 1e-4, -1.5e-3, 1e-3, 2e-3;
      setDisp(d, 2, Vector(d.node(2, "test").trialDisp() + da));
      setDisp(d, 3, Vector(d.node(3, "test").trialDisp() + db));
      const Vector3 motion = slip * (0.8 * h.frame().col(0) + 0.6 * h.normal().cross(h.frame().col(0)));
      setDisp(d, 10, Vector(d.node(10, "test").trialDisp() + motion));
      e.update();
      if (penalty) setDisp(d, 10, Vector(d.node(10, "test").trialDisp() - (h.gap() + 2e-4) * h.normal()));
      else setLambda(d, 11, 20.0);
      e.update();
      ASSERT_EQ(e.status(), slip > 1e-3 ? BeamContactElement::Status::Sliding : BeamContactElement::Status::Sticking);
      const TangentCheck check = checkTangent(e, penalty ? 1e-9 : 1e-7);
      EXPECT_LE(check.relativeError(), 1e-6) << "slip " << slip << ": " << check.maxError << " of " << check.maxEntry;
    }
  }
}

TEST(BeamContactPile, NodeOutsideAKinkStaysWithItsSegment) {
  // A pile bent by 90 degrees at node 2: a node outside the corner lies
  // beyond both segments (its closest pile point is node 2). It is kept by
  // its segment instead of flipping between the two at every commit.
  Domain d;
  buildPile(d, {Vector3(0, 0, 0), Vector3(0, 0, 1), Vector3(1, 0, 1)}, Vector3(0.0, 1.0, 0.3));
  BeamContact3D& e = addContact(d, 1, 1, 2, 10, 11, Vector3(-0.2, 0.0, 1.2));
  EXPECT_EQ(e.segment(), 0);
  EXPECT_GT(e.geometry().xi(), 1.0);
  EXPECT_TRUE(e.ownsNode());
  for (int step = 0; step < 3; ++step) {
    d.update();
    d.commit();
    EXPECT_EQ(e.segment(), 0);
    EXPECT_EQ(e.handOverCount(), 0);
  }
}

TEST(BeamContactPile, AnalysisRenumbersAfterAHandOverAndTheForceMovesToTheNewSegment) {
  // The stick-slip drag of test_BeamContactAnalysis along a two-segment pile
  // (nodes 1, 2, 3 at z = 0, 2, 4, fixed): the soil node 4, pressed by P and
  // dragged through a spring k from the driver node 6, slides from z = 1.5
  // past node 2. Closed form while sliding: friction mu P + c, u4 = u6 -
  // (mu P + c) / k. The contact force on the pile goes to nodes 1, 2 before
  // the hand-over and to nodes 2, 3 after it: the analysis must have rebuilt
  // its dof map for the reactions to follow.
  beamsolid::testing::registerTestTypes();
  beamsolid::testing::Script s;
  const double P = 100.0, k = 2e5;
  s("model", "basic", "-ndm", 3, "-ndf", 6);
  for (int n = 1; n <= 3; ++n) {
    s("node", n, 0.0, 0.0, 2.0 * (n - 1));
    s("fix", n, 1, 1, 1, 1, 1, 1);
  }
  s("geomTransf", "Linear", 1, 1.0, 0.0, 0.0);
  s("element", "elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1);
  s("element", "elasticBeamColumn", 11, 2, 3, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1);
  s("model", "basic", "-ndm", 3, "-ndf", 3);
  s("node", 4, kRadius, 0.0, 1.5);
  s("node", 5, kRadius, 0.0, 1.5);
  s("node", 6, kRadius, 0.0, 3.5);
  s("nDMaterial", "ContactMaterial3D", 1, kMu, 1e5, kC, 0.0);
  s("element", "BeamContact3D", 1, 1, 2, 4, 5, kRadius, 1, 1, 1e-8, 1e-8, "-pile", 1, 2, 3);
  s("element", "testSpring", 2, 4, 6, k);
  s("fix", 4, 0, 1, 0);
  s("fix", 6, 1, 1, 1);
  auto analysis = [&](double dt) {
    s("constraints", "Transformation");
    s("numberer", "RCM");
    s("system", "UmfPack");
    s("test", "NormDispIncr", 1e-12, 25);
    s("algorithm", "Newton");
    s("integrator", "LoadControl", dt);
    s("analysis", "Static");
  };
  s("timeSeries", "Linear", 1);
  s("pattern", "Plain", 1, 1);
  s("load", 4, -P, 0.0, 0.0);
  analysis(1.0);
  ASSERT_EQ(s.integer("analyze", 1), 0);
  s("loadConst", "-time", 0.0);
  s("wipeAnalysis");
  s("remove", "sp", 6, 3);
  const double uMax = 1.0;
  s("timeSeries", "Linear", 2);
  s("pattern", "Plain", 2, 2);
  s("sp", 6, 3, uMax);
  const int steps = 20;
  analysis(1.0 / steps);
  const double capacity = kMu * P + kC;
  int handOverStep = 0;
  for (int step = 1; step <= steps; ++step) {
    const long stamp = s.interp.domain().modelStamp();
    ASSERT_EQ(s.integer("analyze", 1), 0) << "step " << step;
    const double u6 = uMax * step / steps;
    const double u4 = s.number("nodeDisp", 4, 3);
    const auto scalars = s.list("eleResponse", 1, "physicalForceScalar");
    EXPECT_NEAR(scalars[0], P, 1e-9 * P) << "step " << step;
    const auto nodes = std::get<std::vector<int>>(s("eleNodes", 1));
    if (handOverStep == 0 && nodes[0] == 2) {
      handOverStep = step;
      EXPECT_GT(s.interp.domain().modelStamp(), stamp);
      EXPECT_GT(1.5 + u4, 2.0);
    }
    if (u6 * k > 2.0 * capacity) {  // well into sliding
      EXPECT_NEAR(u4, u6 - capacity / k, 1e-10) << "step " << step;
      EXPECT_NEAR(scalars[1], -capacity, 1e-8 * capacity) << "step " << step;
    }
    s("reactions");
    const double r1 = s.number("nodeReaction", 1, 3), r2 = s.number("nodeReaction", 2, 3),
                 r3 = s.number("nodeReaction", 3, 3);
    // The beams carry nothing axially apart from the contact force: the
    // pile's reactions balance the friction pulling it up.
    EXPECT_NEAR(r1 + r2 + r3, scalars[1], 1e-7 * capacity) << "step " << step;
    if (nodes[0] == 2) {
      EXPECT_NEAR(r1, 0.0, 1e-7 * capacity) << "step " << step;
      EXPECT_GT(std::abs(r3), 0.0) << "step " << step;
    } else {
      EXPECT_NEAR(r3, 0.0, 1e-7 * capacity) << "step " << step;
    }
  }
  EXPECT_GT(handOverStep, 1);
  EXPECT_EQ(s.list("eleResponse", 1, "handovers")[0], 1.0);
  EXPECT_EQ(s.list("eleResponse", 1, "segment"), (std::vector<double>{2.0, 3.0}));
}

TEST(BeamContactPile, BadInputGivesClearErrors) {
  auto error = [](const std::function<void(Domain&)>& build) {
    return errorOf([&] {
      Domain d;
      buildPile(d, {Vector3(0, 0, 0), Vector3(0, 0, 1), Vector3(0, 0, 2)});
      addNode(d, 10, 3, kRadius, 0.0, 0.5);
      addNode(d, 11, 3, kRadius, 0.0, 0.5);
      addNode(d, 12, 3, 0.0, 0.0, 3.0);
      build(d);
    });
  };
  auto contact = [](Domain& d, int i, int j, std::vector<int> pile, int s = 10) {
    addElement(d, "BeamContact3D", 1, i, j, s, 11, kRadius, 1, 1, 1e-8, 1e-8, "-pile", pile);
  };
  EXPECT_EQ(error([&](Domain& d) { contact(d, 1, 2, {1, 2, 3}); }), "(no error)");
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 3, {1, 2, 3}); })
                .find("element BeamContact3D 1: iNode 1 and jNode 3 must be consecutive nodes of the -pile list"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 2, 1, {1, 2, 3}); }).find("must be consecutive"), std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 2, {1, 2, 2}); }).find("-pile lists node 2 twice"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 2, {1, 2, 7}); }).find("pile node 7 does not exist"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 2, {1, 2, 12}); }).find("pile node 12 has 3 dofs, expected 6"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) { contact(d, 1, 2, {1}); }).find("argument 13 (pile beam node tags)"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              addElement(d, "BeamContact3D", 1, 1, 2, 10, 11, kRadius, 1, 1, 1e-8, 1e-8, 0, "-chain", 1, 2);
            }).find("element BeamContact3D 1"),
            std::string::npos);
  EXPECT_NE(error([&](Domain& d) {
              addElement(d, "BeamContact3Dp", 1, 1, 2, 10, kRadius, 1, 1, 1e5, "-pile", 1, 2, 3, 10);
            }).find("pile node 10 has 3 dofs"),
            std::string::npos);
  // A soil node on the pile axis (beyond the segment's end, on the next one).
  EXPECT_NE(error([&](Domain& d) {
              d.node(10, "test").setTrialDisp(Vector(Vector3(-kRadius, 0.0, 1.0)));
              contact(d, 1, 2, {1, 2, 3});
            }).find("lies on the beam centerline"),
            std::string::npos);
}

namespace {

// A minimal element whose nodes can be changed from outside, for reconnect().
class ReconnectProbe : public Element {
 public:
  ReconnectProbe(int tag, std::vector<int> nodes) : Element(tag, std::move(nodes)) {}
  std::string className() const override { return "reconnectProbe"; }
  void update() override {}
  MatrixView tangentStiff() override { return viewOf(k_); }
  MatrixView initialStiff() override { return viewOf(k_); }
  VectorView resistingForce() override { return viewOf(f_); }
  void moveTo(std::vector<int> tags) { reconnect(std::move(tags)); }

 private:
  Matrix k_;
  Vector f_;
};

}  // namespace

TEST(ElementReconnect, ResolvesTheNewNodesAndTouchesTheDomain) {
  Domain d;
  addNode(d, 1, 3, 0, 0, 0);
  addNode(d, 2, 6, 1, 0, 0);
  addNode(d, 3, 3, 2, 0, 0);
  ReconnectProbe detached(9, {1, 2});
  EXPECT_NE(errorOf([&] { detached.moveTo({1, 3}); }).find("reconnectProbe 9: cannot change the nodes"),
            std::string::npos);
  d.addElement(std::make_unique<ReconnectProbe>(1, std::vector<int>{1, 2}), "test");
  auto& e = dynamic_cast<ReconnectProbe&>(d.element(1, "test"));
  EXPECT_EQ(e.numDOF(), 9);
  EXPECT_EQ(d.nodeUsage(2).elements, 1);
  const long stamp = d.modelStamp();
  e.moveTo({1, 3});
  EXPECT_GT(d.modelStamp(), stamp);
  EXPECT_EQ(e.nodeTags(), (std::vector<int>{1, 3}));
  EXPECT_EQ(e.nodes()[1]->tag(), 3);
  EXPECT_EQ(e.numDOF(), 6);
  EXPECT_EQ(d.nodeUsage(2).elements, 0);
  EXPECT_EQ(d.nodeUsage(3).elements, 1);
  // A missing node: clear error, the old nodes stay.
  EXPECT_NE(errorOf([&] { e.moveTo({1, 42}); }).find("element reconnectProbe 1: node 42 does not exist"),
            std::string::npos);
  EXPECT_EQ(e.nodeTags(), (std::vector<int>{1, 3}));
  // Node removal follows the new connectivity.
  EXPECT_NE(errorOf([&] { d.removeNode(3, "remove node"); }).find("node 3 is used by element 1"), std::string::npos);
  d.removeNode(2, "remove node");
}

TEST(DomainNodeUsage, CountsElementsAndConstraintsAndStaysCurrent) {
  Domain d;
  for (int n = 1; n <= 5; ++n) addNode(d, n, 3, n, 0, 0);
  d.addElement(std::make_unique<ReconnectProbe>(1, std::vector<int>{1, 2}), "test");
  EXPECT_EQ(d.nodeUsage(1).elements, 1);  // builds the cache
  // Kept current through additions (no rebuild needed, but the same answer).
  d.addElement(std::make_unique<ReconnectProbe>(2, std::vector<int>{2, 3}), "test");
  addNode(d, 6, 3, 6, 0, 0);
  EXPECT_EQ(d.nodeUsage(2).elements, 2);
  EXPECT_EQ(d.nodeUsage(6).elements, 0);
  d.addSP(SPConstraint{4, 0, 0.0}, "test");
  MPConstraint mp;
  mp.kind = "equalDOF";
  mp.retainedNode = 5;
  mp.constrainedNode = 6;
  mp.retainedDofs = {0};
  mp.constrainedDofs = {0};
  mp.C = Matrix::Identity(1, 1);
  d.addMP(mp, "test");
  EXPECT_EQ(d.nodeUsage(4).constraints, 1);
  EXPECT_EQ(d.nodeUsage(5).constraints, 1);
  EXPECT_EQ(d.nodeUsage(6).constraints, 1);
  EXPECT_EQ(d.nodeUsage(1).constraints, 0);
  d.removeElement(1, "test");
  EXPECT_EQ(d.nodeUsage(1).elements, 0);
  EXPECT_EQ(d.nodeUsage(2).elements, 1);
  EXPECT_EQ(d.nodeUsage(99).elements, 0);
}

TEST(BeamContactPile, ElementTakesTheSegmentThatHoldsItsNodeAtCreationAndSharesThePile) {
  Domain d;
  buildPile(d, {Vector3(0, 0, 0), Vector3(0, 0, 1), Vector3(0, 0, 2), Vector3(0, 0, 3)});
  // Soil node at z = 2.5, given segment 1-2: the element starts on 3-4.
  BeamContact3D& e = addContact(d, 1, 1, 2, 10, 11, Vector3(kRadius, 0.0, 2.5));
  EXPECT_EQ(e.segment(), 2);
  EXPECT_EQ(e.nodeTags(), (std::vector<int>{3, 4, 10, 11}));
  EXPECT_EQ(e.handOverCount(), 0);
  EXPECT_NEAR(e.geometry().xi(), 0.5, 1e-14);
  EXPECT_TRUE(e.inContact());
  // The usage counts follow the final nodes.
  EXPECT_EQ(d.nodeUsage(1).elements, 0);
  EXPECT_EQ(d.nodeUsage(4).elements, 1);
  EXPECT_EQ(d.nodeUsage(11).elements, 1);
  // revertToStart keeps that segment.
  d.revertToStart();
  EXPECT_EQ(e.segment(), 2);
  // Elements of one pile and geomTransf share the pile; another geomTransf has its own.
  BeamContact3D& f = addContact(d, 2, 2, 3, 12, 13, Vector3(0.0, kRadius, 1.5));
  EXPECT_EQ(e.pile(), f.pile());
  addLinearTransf(d, 2, Vector3(0.0, 1.0, 0.0));
  addNode(d, 14, 3, -kRadius, 0.0, 1.5);
  addNode(d, 15, 3, -kRadius, 0.0, 1.5);
  auto& g = dynamic_cast<BeamContact3D&>(
      addElement(d, "BeamContact3D", 3, 2, 3, 14, 15, kRadius, 2, 1, 1e-8, 1e-8, "-pile", std::vector<int>{1, 2, 3, 4}));
  EXPECT_NE(g.pile(), e.pile());
  EXPECT_EQ(e.pile()->numSegments(), 3);
  EXPECT_EQ(e.pile()->segmentLength(1), 1.0);
}

TEST(DomainSharedObject, LivesAsLongAsAnElementHoldsIt) {
  Domain d;
  int made = 0;
  auto make = [&] {
    ++made;
    return std::make_shared<int>(made);
  };
  std::shared_ptr<int> a = d.sharedObject<int>("test/a", make);
  std::shared_ptr<int> b = d.sharedObject<int>("test/a", make);
  EXPECT_EQ(a, b);
  EXPECT_EQ(made, 1);
  EXPECT_NE(d.sharedObject<int>("test/b", make), a);
  a.reset();
  b.reset();
  EXPECT_EQ(*d.sharedObject<int>("test/a", make), 3);  // a fresh one
}

TEST(BeamContactPile, SlidingFrictionIsKeptExactlyAcrossAHandOverFromAStretchedSegment) {
  // Segment 1-2 stretched by 1 % (committed): its |g_xi| varies along xi, so
  // the friction state must be mapped from the base it was computed in (the
  // step's held projection), not from the re-projected one.
  Domain d;
  buildPile(d, {Vector3(0, 0, 0), Vector3(0, 0, 2), Vector3(0, 0, 3)});
  BeamContact3D& e = addContact(d, 1, 1, 2, 10, 11, Vector3(kRadius, 0.0, 1.5));
  Vector u2 = Vector::Zero(6);
  u2(2) = 0.02;
  setDisp(d, 2, u2);
  setDisp(d, 3, u2);
  d.update();
  d.commit();
  const double lambda = 40.0, capacity = kMu * lambda + kC;
  setLambda(d, 11, lambda);
  // Slide up over node 2 in two steps; the second ends past it.
  for (double dz : {0.3, 0.62}) {
    setDisp(d, 10, Vector(Vector3(0.0, 0.0, dz)));
    d.update();
    ASSERT_EQ(e.status(), BeamContactElement::Status::Sliding);
    EXPECT_NEAR(e.frictionForce().norm(), capacity, 1e-12 * capacity);
    d.commit();
  }
  ASSERT_EQ(e.handOverCount(), 1);
  EXPECT_EQ(e.status(), BeamContactElement::Status::Sliding);
  EXPECT_NEAR(e.frictionForce().norm(), capacity, 1e-12 * capacity);
  EXPECT_LE((e.frictionForce().normalized() - Vector3(0.0, 0.0, -1.0)).norm(), 1e-12);
  // The re-projected base on the old segment differs from the held one here.
  const BeamContactGeometry& g = e.geometry();
  EXPECT_NEAR(g.covariantBase(0).norm(), 1.0, 1e-12);  // segment 2-3 is not stretched
}
