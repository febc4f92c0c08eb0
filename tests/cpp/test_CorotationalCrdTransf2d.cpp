// geomTransf Corotational in 2D (CorotationalCrdTransf2d) with the 2D
// elasticBeamColumn: zero force under rigid-body motion of any size (also
// past half a turn, with joint offsets), the tangent against finite
// differences in a large deformed state (with an element load), the
// small-displacement limit
// (the Linear transformation's stiffness), and the basic deformations of a
// beam bent into a circular arc.
#include <gtest/gtest.h>

#include <cmath>

#include "BeamTestModel.h"
#include "core/OpenSeesError.h"
#include "elements/ElasticBeam2d.h"
#include "elements/TangentCheck.h"
#include "elements/transforms/CorotationalCrdTransf2d.h"

using namespace beamtest;

namespace {

constexpr double kA = 0.03, kE = 2.0e5, kIz = 4.0e-4;

struct Beam {
  Domain domain;
  Element* element = nullptr;
  Vector3 x[2];
  Eigen::Vector2d offset[2];
};

void build(Beam& b, const std::string& transf, bool offsets) {
  b.domain.setModelSpace(2, 3);
  b.x[0] = Vector3(0.3, -0.2, 0.0);
  b.x[1] = Vector3(2.9, 1.4, 0.0);
  b.offset[0] = offsets ? Eigen::Vector2d(0.2, -0.1) : Eigen::Vector2d::Zero();
  b.offset[1] = offsets ? Eigen::Vector2d(-0.15, 0.05) : Eigen::Vector2d::Zero();
  for (int k = 0; k < 2; ++k) b.domain.addNode(std::make_unique<Node>(k + 1, 3, b.x[k], 2), "node");
  if (offsets)
    addTransf(b.domain, transf, {1LL, std::string("-jntOffset"), 0.2, -0.1, -0.15, 0.05});
  else
    addTransf(b.domain, transf, {1LL});
  b.element = &addElement(b.domain, "elasticBeamColumn", {1LL, 1LL, 2LL, kA, kE, kIz, 1LL});
}

void setDisp(Beam& b, const double (&u)[6]) {
  for (int k = 0; k < 2; ++k) {
    Vector v(3);
    v << u[3 * k], u[3 * k + 1], u[3 * k + 2];
    b.domain.node(k + 1, "t").setTrialDisp(v);
  }
  b.element->update();
}

// Node displacements of a rigid motion: turn by angle about the origin, then
// translate; each joint offset turns with its node.
void setRigid(Beam& b, double angle, const Eigen::Vector2d& shift) {
  const Eigen::Rotation2Dd R(angle);
  double u[6];
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d x = b.x[k].head<2>();
    const Eigen::Vector2d moved = R * x + shift;
    u[3 * k] = moved.x() - x.x();
    u[3 * k + 1] = moved.y() - x.y();
    u[3 * k + 2] = angle;
  }
  setDisp(b, u);
}

class RigidMotion : public ::testing::TestWithParam<double> {};

TEST_P(RigidMotion, GivesNoForceAndNoDeformation) {
  for (bool offsets : {false, true}) {
    Beam b;
    build(b, "Corotational", offsets);
    setRigid(b, GetParam(), Eigen::Vector2d(1.3, -0.7));
    auto& beam = dynamic_cast<beamsolid::ElasticBeam2d&>(*b.element);
    EXPECT_LT(Vector(beam.basicForce()).cwiseAbs().maxCoeff(), 1e-8) << GetParam();
    EXPECT_LT(Vector(b.element->resistingForce()).cwiseAbs().maxCoeff(), 1e-8) << GetParam();
  }
}

// Up to and past half a turn and a full turn: the end rotations relative to
// the chord stay small, so no branch of the angle is crossed.
INSTANTIATE_TEST_SUITE_P(Angles, RigidMotion, ::testing::Values(0.3, -1.2, 3.0, 3.3, -3.5, 5.0, 6.2831853071795862, 8.0));

TEST(CorotationalCrdTransf2d, TangentMatchesFiniteDifferencesInALargeDeformedState) {
  for (bool offsets : {false, true}) {
    Beam b;
    build(b, "Corotational", offsets);
    // A large rotation (about 2.4 rad) plus bending and stretching.
    const double u[6] = {0.1, -0.05, 2.3, -4.1, 2.2, 2.6};
    setDisp(b, u);
    // An element load too: its reactions keep their initial direction.
    b.element->zeroLoad();
    b.element->addLoad(beamsolid::ElementLoad{beamsolid::ElementLoad::Type::BeamUniform, {-30.0, 0.0, 10.0}}, 1.0);
    const Vector f = b.element->resistingForce();
    ASSERT_GT(f.cwiseAbs().maxCoeff(), 1.0);
    const auto check = beamsolid::TangentCheck::of(*b.element, 1e-7);
    EXPECT_LE((check.tangent - check.difference).cwiseAbs().maxCoeff(),
              2e-6 * check.tangent.cwiseAbs().maxCoeff())
        << "offsets " << offsets;
  }
}

TEST(CorotationalCrdTransf2d, UndeformedTangentIsTheLinearOne) {
  for (bool offsets : {false, true}) {
    Beam corot, linear;
    build(corot, "Corotational", offsets);
    build(linear, "Linear", offsets);
    const Matrix kc = corot.element->tangentStiff();
    const Matrix kl = linear.element->tangentStiff();
    EXPECT_LT((kc - kl).cwiseAbs().maxCoeff(), 1e-12 * kl.cwiseAbs().maxCoeff());
    EXPECT_LT((Matrix(corot.element->initialStiff()) - kl).cwiseAbs().maxCoeff(), 1e-12 * kl.cwiseAbs().maxCoeff());
    // Small displacements: the forces agree to second order.
    const double u[6] = {1e-7, -2e-7, 3e-7, 2e-7, 1e-7, -1e-7};
    setDisp(corot, u);
    setDisp(linear, u);
    const Vector fl = linear.element->resistingForce();
    EXPECT_LT((Vector(corot.element->resistingForce()) - fl).cwiseAbs().maxCoeff(), 1e-5 * fl.cwiseAbs().maxCoeff());
  }
}

// A horizontal element of length L bent into an arc of curvature kappa with
// unchanged chord: the ends turn by -+kappa L / 2 against the chord, which
// itself has turned by beta.
TEST(CorotationalCrdTransf2d, ArcHasTheBasicDeformationsOfTheChord) {
  Domain d;
  d.setModelSpace(2, 3);
  const double L = 2.0, beta = 2.8, half = 0.35;
  d.addNode(std::make_unique<Node>(1, 3, Vector3(0.0, 0.0, 0.0), 2), "node");
  d.addNode(std::make_unique<Node>(2, 3, Vector3(L, 0.0, 0.0), 2), "node");
  addTransf(d, "Corotational", {1LL});
  Element& e = addElement(d, "elasticBeamColumn", {1LL, 1LL, 2LL, kA, kE, kIz, 1LL});
  Vector ui = Vector::Zero(3), uj(3);
  ui[2] = beta + half;
  uj << L * std::cos(beta) - L, L * std::sin(beta), beta - half;
  d.node(1, "t").setTrialDisp(ui);
  d.node(2, "t").setTrialDisp(uj);
  e.update();
  const auto& beam = dynamic_cast<beamsolid::ElasticBeam2d&>(e);
  const Vector q = beam.basicForce();
  const double k = kE * kIz / L;
  EXPECT_NEAR(q[0], 0.0, 1e-9);
  EXPECT_NEAR(q[1], 4 * k * half - 2 * k * half, 1e-9 * k);
  EXPECT_NEAR(q[2], 2 * k * half - 4 * k * half, 1e-9 * k);
}

TEST(CorotationalCrdTransf2d, VecxzInA2dModelIsRefused) {
  Domain d;
  d.setModelSpace(2, 3);
  std::string message;
  try {
    addTransf(d, "Corotational", {1LL, 0.0, 0.0, 1.0});
  } catch (const beamsolid::OpenSeesError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("vecxz is for 3D models"), std::string::npos) << message;
}

}  // namespace
