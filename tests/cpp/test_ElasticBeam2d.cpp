// elasticBeamColumn in 2D (ElasticBeam2d with LinearCrdTransf2d and
// PDeltaCrdTransf2d): the 2D beam is the 3D beam confined to the x-y plane,
// so on an inclined element with joint offsets, element loads and a release-
// free section, its stiffness and resisting force must equal the 3D beam's
// (vecxz = Z, ndf-6 nodes) restricted to ux, uy, rz, for Linear and PDelta.
// Also: the Linear tangent against finite differences, and 2D truss bars
// (ndf 2 and 3) against the 3D bar in the plane.
#include <gtest/gtest.h>

#include "BeamTestModel.h"
#include "elements/ElasticBeam2d.h"
#include "elements/ElasticBeam3d.h"
#include "elements/TangentCheck.h"
#include "materials/uniaxial/UniaxialMaterial.h"

using namespace beamtest;
using beamsolid::ElementLoad;

namespace {

constexpr double kA = 0.03, kE = 2.0e5, kIz = 4.0e-4;
// ux, uy, rz of a 6-dof node.
constexpr int kInPlane[3] = {0, 1, 5};

struct Pair {
  Domain plane, space;
  Element* beam2 = nullptr;
  Element* beam3 = nullptr;
};

void build(Pair& p, const std::string& transf, const Vector3& xi, const Vector3& xj) {
  p.plane.setModelSpace(2, 3);
  for (int k = 0; k < 2; ++k) {
    const Vector3 x = k == 0 ? xi : xj;
    p.plane.addNode(std::make_unique<Node>(k + 1, 3, x, 2), "node");
    p.space.addNode(std::make_unique<Node>(k + 1, 6, x, 3), "node");
  }
  addTransf(p.plane, transf, {1LL, std::string("-jntOffset"), 0.2, -0.1, -0.15, 0.05});
  addTransf(p.space, transf, {1LL, 0.0, 0.0, 1.0, std::string("-jntOffset"), 0.2, -0.1, 0.0, -0.15, 0.05, 0.0});
  p.beam2 = &addElement(p.plane, "elasticBeamColumn", {1LL, 1LL, 2LL, kA, kE, kIz, 1LL});
  // G, J, Iy only load the out-of-plane dofs, which the comparison leaves out.
  p.beam3 = &addElement(p.space, "elasticBeamColumn", {1LL, 1LL, 2LL, kA, kE, 1.0e5, 1.0e-4, 3.0e-4, kIz, 1LL});
  ASSERT_NE(dynamic_cast<beamsolid::ElasticBeam2d*>(p.beam2), nullptr);
}

void setDisplacements(Pair& p, const double (&u)[6]) {
  for (int k = 0; k < 2; ++k) {
    Vector u2(3), u6 = Vector::Zero(6);
    for (int d = 0; d < 3; ++d) {
      u2[d] = u[3 * k + d];
      u6[kInPlane[d]] = u[3 * k + d];
    }
    p.plane.node(k + 1, "t").setTrialDisp(u2);
    p.space.node(k + 1, "t").setTrialDisp(u6);
  }
  p.beam2->update();
  p.beam3->update();
}

int index6(int a) { return 6 * (a / 3) + kInPlane[a % 3]; }

void expectSamePlaneResponse(Pair& p) {
  const Matrix k2 = Matrix(p.beam2->tangentStiff());
  const Matrix k3 = Matrix(p.beam3->tangentStiff());
  const Vector f2 = Vector(p.beam2->resistingForce());
  const Vector f3 = Vector(p.beam3->resistingForce());
  const double kScale = k3.cwiseAbs().maxCoeff(), fScale = f3.cwiseAbs().maxCoeff();
  for (int a = 0; a < 6; ++a) {
    EXPECT_NEAR(f2[a], f3[index6(a)], 1e-12 * fScale) << "force " << a;
    for (int b = 0; b < 6; ++b) EXPECT_NEAR(k2(a, b), k3(index6(a), index6(b)), 1e-12 * kScale) << a << ',' << b;
  }
}

class ElasticBeam2dAgainst3d : public ::testing::TestWithParam<const char*> {};

TEST_P(ElasticBeam2dAgainst3d, StiffnessAndForceEqualThe3dBeamInThePlane) {
  Pair p;
  build(p, GetParam(), Vector3(0.3, -0.2, 0.0), Vector3(2.9, 1.4, 0.0));
  if (HasFatalFailure()) return;
  // Element loads in both: 2D (Wy, 0, Wx) and (Py, 0, xL, Px) in ElementLoad's layout.
  const ElementLoad uniform{ElementLoad::Type::BeamUniform, {-3.0, 0.0, 0.7}};
  const ElementLoad point{ElementLoad::Type::BeamPoint, {5.0, 0.0, 0.35, -1.2}};
  for (Element* e : {p.beam2, p.beam3}) {
    e->zeroLoad();
    e->addLoad(uniform, 1.5);
    e->addLoad(point, 0.5);
  }
  // A compressive stretch and bending, so PDelta's chord terms are non-zero.
  setDisplacements(p, {1e-3, -2e-3, 3e-4, -4e-3, 5e-3, -6e-4});
  expectSamePlaneResponse(p);
}

INSTANTIATE_TEST_SUITE_P(Transforms, ElasticBeam2dAgainst3d, ::testing::Values("Linear", "PDelta"));

TEST(ElasticBeam2d, LinearTangentIsTheDerivativeOfTheForce) {
  Pair p;
  build(p, "Linear", Vector3(0.0, 0.0, 0.0), Vector3(1.5, 2.0, 0.0));
  if (HasFatalFailure()) return;
  setDisplacements(p, {1e-3, -2e-3, 3e-4, -4e-3, 5e-3, -6e-4});
  const auto check = beamsolid::TangentCheck::of(*p.beam2, 1e-6);
  EXPECT_LE((check.tangent - check.difference).cwiseAbs().maxCoeff(), 1e-7 * check.tangent.cwiseAbs().maxCoeff());
}

// A 2D truss bar (ndf 2 or 3) is the 3D bar (ndf 3) in the plane.
TEST(Truss2d, StiffnessAndForceEqualThe3dBarInThePlane) {
  for (int ndf : {2, 3}) {
    Domain plane, space;
    plane.setModelSpace(2, ndf);
    const Vector3 x[2] = {Vector3(0.4, 0.1, 0.0), Vector3(-1.1, 2.3, 0.0)};
    for (int k = 0; k < 2; ++k) {
      plane.addNode(std::make_unique<Node>(k + 1, ndf, x[k], 2), "node");
      space.addNode(std::make_unique<Node>(k + 1, 3, x[k], 3), "node");
    }
    for (Domain* d : {&plane, &space}) {
      CommandArgs m("uniaxialMaterial", Args{1LL, 210.0});
      d->uniaxialMaterials.add(
          1, std::shared_ptr<beamsolid::UniaxialMaterial>(Registry::global().uniaxialMaterials.get("Elastic")(m, *d)),
          "mat");
    }
    for (const char* type : {"truss", "corotTruss"}) {
      Element& bar2 = addElement(plane, type, {1LL, 1LL, 2LL, 1.3, 1LL});
      Element& bar3 = addElement(space, type, {1LL, 1LL, 2LL, 1.3, 1LL});
      for (int k = 0; k < 2; ++k) {
        Vector u2 = Vector::Zero(ndf), u3 = Vector::Zero(3);
        u2[0] = u3[0] = 0.01 * (k + 1);
        u2[1] = u3[1] = -0.02 * (2 - k);
        plane.node(k + 1, "t").setTrialDisp(u2);
        space.node(k + 1, "t").setTrialDisp(u3);
      }
      bar2.update();
      bar3.update();
      const Matrix k2 = Matrix(bar2.tangentStiff()), k3 = Matrix(bar3.tangentStiff());
      const Vector f2 = Vector(bar2.resistingForce()), f3 = Vector(bar3.resistingForce());
      for (int a = 0; a < 2 * ndf; ++a) {
        const bool translation = a % ndf < 2;
        const int a3 = 3 * (a / ndf) + a % ndf;
        EXPECT_NEAR(f2[a], translation ? f3[a3] : 0.0, 1e-13 * f3.cwiseAbs().maxCoeff()) << type << ' ' << a;
        for (int b = 0; b < 2 * ndf; ++b) {
          const bool both = translation && b % ndf < 2;
          const double expected = both ? k3(a3, 3 * (b / ndf) + b % ndf) : 0.0;
          EXPECT_NEAR(k2(a, b), expected, 1e-13 * k3.cwiseAbs().maxCoeff()) << type << ' ' << a << ',' << b;
        }
      }
      plane.removeElement(1, "t");
      space.removeElement(1, "t");
    }
  }
}

}  // namespace
