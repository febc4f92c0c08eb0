// zeroLengthContact3D: finite-difference tangent (stick, slide, open; axial
// and radial normals), the closed-form stick-slip cycle of a penalty spring
// with Coulomb friction under a constant normal force, separation and
// re-contact, the radial normal at several angles, commit/revert and input
// errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/contact/ZeroLengthContact3D.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

constexpr double kKn = 1000.0, kKt = 100.0, kMu = 0.5, kC = 2.0;

using beamsolid::testsupport::errorOf;

// Constrained node 1 and retained node 2 at X (coincident), element 1.
ZeroLengthContact3D& makeContact(Domain& d, int dir, const Vector3& X = Vector3::Zero(), double ox = 0.0,
                                 double oy = 0.0) {
  addNode(d, 1, 3, X(0), X(1), X(2));
  addNode(d, 2, 3, X(0), X(1), X(2));
  Element& e = dir == 0 ? addElement(d, "zeroLengthContact3D", 1, 1, 2, kKn, kKt, kMu, kC, 0, ox, oy)
                        : addElement(d, "zeroLengthContact3D", 1, 1, 2, kKn, kKt, kMu, kC, dir);
  return dynamic_cast<ZeroLengthContact3D&>(e);
}

// Relative displacement u_c - u_r imposed on the constrained node.
void setRelative(Domain& d, Element& e, const Vector3& du) {
  d.node(1, "test").setTrialDisp(du);
  d.node(2, "test").setTrialDisp(Vector3::Zero());
  e.update();
}

}  // namespace

TEST(ZeroLengthContact3D, AxialNormalsFollowOpenSeesConventions) {
  // dir a: n = +axis a; tangents the next two axes cyclically; contact when
  // the constrained node moves along -n relative to the retained one.
  for (int dir = 1; dir <= 3; ++dir) {
    Domain d;
    ZeroLengthContact3D& e = makeContact(d, dir);
    const Vector3 n = Vector3::Unit(dir - 1);
    EXPECT_EQ(e.normal(), n);
    EXPECT_EQ(Vector3(e.tangents().row(0).transpose()), Vector3::Unit(dir % 3));
    EXPECT_EQ(Vector3(e.tangents().row(1).transpose()), Vector3::Unit((dir + 1) % 3));
    setRelative(d, e, -0.002 * n);
    EXPECT_DOUBLE_EQ(e.gap(), -0.002);
    EXPECT_DOUBLE_EQ(e.normalForce(), kKn * 0.002);
    const Vector f = e.resistingForce();
    EXPECT_LE((f.head<3>() + kKn * 0.002 * n).norm(), 1e-15);  // -N n at the constrained node
    EXPECT_LE((f.head<3>() + f.tail<3>()).norm(), 0.0);
    setRelative(d, e, 0.002 * n);
    EXPECT_EQ(e.status(), ZeroLengthContact3D::Status::Open);
    EXPECT_EQ(Vector(e.resistingForce()).norm(), 0.0);
  }
}

TEST(ZeroLengthContact3D, FiniteDifferenceTangentStickSlideOpen) {
  // Central differences, h = 1e-8: exact to round-off in stick and open (the
  // force is linear there) and O(h^2) in slide; tolerance 1e-6 of the largest
  // entry. States away from the kinks (g = 0, |F_t| = mu N + c).
  struct Case {
    int dir;
    Vector3 X;
    Vector3 committed;  // relative displacement committed first
    Vector3 trial;
    ZeroLengthContact3D::Status status;
  };
  const Vector3 X0(1.3, -0.4, 2.0);
  const std::vector<Case> cases = {
      {1, X0, Vector3(-0.001, 0.004, 0.0), Vector3(-0.003, 0.006, -0.002), ZeroLengthContact3D::Status::Stick},
      {2, X0, Vector3(0.0, -0.01, 0.02), Vector3(0.09, -0.012, 0.1), ZeroLengthContact3D::Status::Slide},
      {3, X0, Vector3(0.01, 0.0, -0.004), Vector3(-0.15, 0.07, -0.02), ZeroLengthContact3D::Status::Slide},
      {0, X0, Vector3(0.0, 0.0, 0.0), Vector3(0.01, 0.2, -0.5), ZeroLengthContact3D::Status::Slide},
      {0, X0, Vector3(0.0, 0.0, 0.0), Vector3(0.004, -0.002, 0.001), ZeroLengthContact3D::Status::Stick},
      {1, X0, Vector3(-0.01, 0.0, 0.0), Vector3(0.002, 0.05, 0.0), ZeroLengthContact3D::Status::Open},
  };
  for (const Case& c : cases) {
    Domain d;
    ZeroLengthContact3D& e = makeContact(d, c.dir, c.X, 0.2, -0.7);
    setRelative(d, e, c.committed);
    e.commitState();
    setRelative(d, e, c.trial);
    EXPECT_EQ(e.status(), c.status) << "dir " << c.dir;
    const TangentCheck check = checkTangent(e, 1e-8);
    if (c.status == ZeroLengthContact3D::Status::Open) {
      EXPECT_EQ(check.maxEntry, 0.0);
      EXPECT_EQ(check.maxError, 0.0);
      continue;
    }
    EXPECT_GT(check.maxEntry, 0.0);
    EXPECT_LE(check.relativeError(), 1e-6) << "dir " << c.dir << " error " << check.maxError;
    if (c.status == ZeroLengthContact3D::Status::Slide) {
      const Matrix K = e.tangentStiff();
      EXPECT_GT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-3 * check.maxEntry);  // unsymmetric
      EXPECT_TRUE(e.needsGeneralSolver());
    }
  }
}

TEST(ZeroLengthContact3D, StickSlipCycleUnderConstantNormalForce) {
  // Penetration 0.004 -> N = 4, slip resistance Fy = mu N + c = 4 with
  // Kt = 100: sticks up to s = 0.04. Tangential motion along t1 to s_max =
  // 0.1 and back to -0.1, one committed step each: the closed form of a
  // rigid-plastic slider on an elastic spring,
  //   loading    F = min(Kt s, Fy),
  //   unloading  F = max(Fy - Kt (s_max - s), -Fy).
  Domain d;
  ZeroLengthContact3D& e = makeContact(d, 2);  // n = y, t1 = z, t2 = x
  const double pen = 0.004, N = kKn * pen, Fy = kMu * N + kC, sMax = 0.1;
  // steps chosen so that no step lands on a kink (s = 0.04 loading, 0.02 unloading)
  const int steps = 47;
  for (int k = 0; k <= steps; ++k) {
    const double s = sMax * k / steps;
    setRelative(d, e, Vector3(0.0, -pen, s));
    const double expected = std::min(kKt * s, Fy);
    EXPECT_NEAR(e.frictionComponents()(0), expected, 1e-12 * Fy) << s;
    EXPECT_NEAR(Vector(e.resistingForce())(5), -expected, 1e-12 * Fy) << s;  // at r: N n - F_t t1
    EXPECT_EQ(e.status(), kKt * s > Fy ? ZeroLengthContact3D::Status::Slide : ZeroLengthContact3D::Status::Stick);
    EXPECT_DOUBLE_EQ(e.normalForce(), N);
    e.commitState();
  }
  for (int k = 1; k <= 2 * steps; ++k) {
    const double s = sMax - 2.0 * sMax * k / (2 * steps);
    setRelative(d, e, Vector3(0.0, -pen, s));
    const double expected = std::max(Fy - kKt * (sMax - s), -Fy);
    EXPECT_NEAR(e.frictionComponents()(0), expected, 1e-12 * Fy) << s;
    e.commitState();
  }
  // A diagonal push: the friction force lines up with the slip direction, |F| = Fy.
  Domain d2;
  ZeroLengthContact3D& e2 = makeContact(d2, 3);  // n = z, t1 = x, t2 = y
  setRelative(d2, e2, Vector3(0.0, 0.0, -pen));
  e2.commitState();
  setRelative(d2, e2, Vector3(0.3, 0.4, -pen));
  const Vector3 F = e2.setResponse({"frictionForce"}).value();
  EXPECT_NEAR(F.norm(), Fy, 1e-12 * Fy);
  EXPECT_LE((F / Fy - Vector3(0.6, 0.8, 0.0)).norm(), 1e-12);
}

TEST(ZeroLengthContact3D, SeparationCarriesNoForceAndResetsTheStickPoint) {
  Domain d;
  ZeroLengthContact3D& e = makeContact(d, 1);
  setRelative(d, e, Vector3(-0.01, 0.02, 0.0));  // N = 10, F = 2 < 7: stick
  EXPECT_EQ(e.status(), ZeroLengthContact3D::Status::Stick);
  e.commitState();
  setRelative(d, e, Vector3(0.003, 0.05, -0.01));  // open
  EXPECT_EQ(e.status(), ZeroLengthContact3D::Status::Open);
  EXPECT_EQ(Vector(e.resistingForce()).norm(), 0.0);
  EXPECT_EQ(Matrix(e.tangentStiff()).norm(), 0.0);
  EXPECT_EQ(e.setResponse({"forceScalar"}).value().norm(), 0.0);
  EXPECT_DOUBLE_EQ(e.setResponse({"gap"}).value()(0), 0.003);
  e.commitState();
  // Closing again: the tangential motion since the opening commit is the new elastic slip.
  setRelative(d, e, Vector3(-0.01, 0.06, -0.01));
  EXPECT_EQ(e.status(), ZeroLengthContact3D::Status::Stick);
  EXPECT_NEAR(e.frictionComponents()(0), kKt * 0.01, 1e-13);
  EXPECT_NEAR(e.frictionComponents()(1), 0.0, 1e-13);
}

TEST(ZeroLengthContact3D, RadialNormalAtSeveralAngles) {
  // dir 0 about the axis through (ox, oy): n = -e_r at the retained node;
  // pushing the constrained node outward by d closes the contact with
  // N = Kn d, its resisting force is N e_r; moving it inward opens it.
  const double ox = 1.0, oy = -0.5, R = 2.0, dr = 0.003;
  for (double deg : {0.0, 30.0, 135.0, 250.0, 300.0}) {
    const double th = deg * std::numbers::pi / 180.0;
    const Vector3 er(std::cos(th), std::sin(th), 0.0);
    const Vector3 X = Vector3(ox, oy, 0.4) + R * er;
    Domain d;
    ZeroLengthContact3D& e = makeContact(d, 0, X, ox, oy);
    EXPECT_LE((e.normal() + er).norm(), 1e-15) << deg;
    EXPECT_LE(std::abs(e.gap()), 1e-15);
    setRelative(d, e, dr * er);
    EXPECT_NEAR(e.normalForce(), kKn * dr, 1e-12) << deg;
    const Vector f = e.resistingForce();
    EXPECT_LE((f.head<3>() - kKn * dr * er).norm(), 1e-12) << deg;
    EXPECT_LE((f.tail<3>() + kKn * dr * er).norm(), 1e-12) << deg;
    // Tangential motion along e_theta in stick: friction along t1 = e_theta.
    const Vector3 et(-std::sin(th), std::cos(th), 0.0);
    setRelative(d, e, dr * er + 0.01 * et);
    EXPECT_LE((Vector3(e.setResponse({"frictionForce"}).value()) - kKt * 0.01 * et).norm(), 1e-12) << deg;
    setRelative(d, e, -dr * er);
    EXPECT_EQ(e.status(), ZeroLengthContact3D::Status::Open) << deg;
  }
  // Radially offset nodes: the initial gap is the difference of the radii.
  Domain d;
  addNode(d, 1, 3, 2.0, 0.0, 0.0);   // constrained, inner (radius 2)
  addNode(d, 2, 3, 0.0, 2.1, 0.0);   // retained, outer (radius 2.1)
  Element& e = addElement(d, "zeroLengthContact3D", 1, 1, 2, kKn, kKt, kMu, kC, 0);
  e.update();
  EXPECT_NEAR(dynamic_cast<ZeroLengthContact3D&>(e).gap(), 0.1, 1e-15);
}

TEST(ZeroLengthContact3D, CommitRevertAndParameters) {
  Domain d;
  ZeroLengthContact3D& e = makeContact(d, 3);
  setRelative(d, e, Vector3(0.2, 0.0, -0.01));  // slide: F = 7
  e.commitState();                              // elastic slip 0.07
  setRelative(d, e, Vector3(0.0, 0.0, -0.01));  // back by 0.2: 7 - 20 -> -7
  EXPECT_NEAR(e.frictionComponents()(0), -7.0, 1e-12);
  e.revertToLastCommit();
  setRelative(d, e, Vector3(0.2, 0.0, -0.01));
  EXPECT_NEAR(e.frictionComponents()(0), 7.0, 1e-12);
  EXPECT_TRUE(e.setParameter({"mu"}, 0.2));  // Fy = 0.2*10 + 2 = 4
  setRelative(d, e, Vector3(0.3, 0.0, -0.01));
  EXPECT_NEAR(e.frictionComponents()(0), 4.0, 1e-12);
  EXPECT_TRUE(e.setParameter({"friction"}, 0.0));  // frictionless stage
  e.update();
  EXPECT_EQ(e.frictionComponents().norm(), 0.0);
  EXPECT_TRUE(e.setParameter({"friction"}, 1.0));
  e.revertToStart();
  setRelative(d, e, Vector3(0.01, 0.0, -0.01));
  EXPECT_NEAR(e.frictionComponents()(0), 1.0, 1e-12);
  EXPECT_FALSE(e.setParameter({"E"}, 1.0));
  EXPECT_NE(errorOf([&] { e.setParameter({"Kn"}, -1.0); }).find("element zeroLengthContact3D 1: Kn must be positive"),
            std::string::npos);
  EXPECT_EQ(e.vertexNode(), 1);
}

TEST(ZeroLengthContact3D, InputErrorsNameTheArgument) {
  Domain d;
  addNode(d, 1, 3, 0, 0, 0);
  addNode(d, 2, 3, 0, 0, 0);
  addNode(d, 6, 6, 0, 0, 0);
  auto add = [&](auto... rest) { return errorOf([&] { addElement(d, "zeroLengthContact3D", 5, rest...); }); };
  auto expectHas = [](const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  expectHas(add(1, 2, kKn, kKt, kMu, kC), "element zeroLengthContact3D 5: argument 8 (dir): expected an integer");
  expectHas(add(1, 2, kKn, kKt), "(mu): expected a number");
  expectHas(add(1, 2, kKn, kKt, kMu, kC, 4), "(dir): expected 0 (radial from originX originY), 1, 2 or 3");
  expectHas(add(1, 2, kKn, kKt, kMu, kC, -1), "(dir)");
  expectHas(add(1, 2, -5.0, kKt, kMu, kC, 1), "(Kn): expected a positive number, got -5");
  expectHas(add(1, 2, kKn, -1.0, kMu, kC, 1), "(Kt): expected a number >= 0");
  expectHas(add(1, 2, kKn, kKt, -0.1, kC, 1), "(mu): expected a number >= 0");
  expectHas(add(1, 2, kKn, kKt, kMu, -2.0, 1), "(c): expected a number >= 0");
  expectHas(add(1, 2, kKn, kKt, kMu, kC, 0, 1.0), "(originY): expected a number");
  expectHas(add(1, 2, kKn, kKt, kMu, kC, 1, 1.0, 2.0), "originX originY only with dir 0");
  expectHas(add(1, 6, kKn, kKt, kMu, kC, 1), "element zeroLengthContact3D 5: retained node 6 has 6 dofs, expected 3");
  expectHas(add(6, 2, kKn, kKt, kMu, kC, 1), "constrained node 6 has 6 dofs, expected 3");
  expectHas(add(1, 9, kKn, kKt, kMu, kC, 1), "node 9 does not exist");
  // dir 0 with the retained node on the axis has no radial direction.
  expectHas(add(1, 2, kKn, kKt, kMu, kC, 0), "dir 0 (radial) needs the retained node 2 off the axis");
  EXPECT_EQ(d.elements().size(), 0u);
}
