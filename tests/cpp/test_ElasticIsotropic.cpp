// ElasticIsotropic (three-dimensional): closed-form moduli, uniaxial stress,
// pure shear and hydrostatic states, finite-difference tangent, clone kinds,
// state handling and input validation.
#include <gtest/gtest.h>

#include <memory>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "materials/nd/ElasticIsotropic3D.h"

using namespace beamsolid;
using beamsolid::solidstest::args;

namespace {

std::unique_ptr<NDMaterial> build(CommandArgs a) {
  Domain d;
  return Registry::global().ndMaterials.get("ElasticIsotropic")(a, d);
}

using Vector6 = Eigen::Matrix<double, 6, 1>;

}  // namespace

TEST(ElasticIsotropic, TangentIsTheIsotropicStiffness) {
  const double E = 210.0, nu = 0.3;
  auto m = build(args("nDMaterial", 1, E, nu));
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double G = E / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) D(i, i) += 2 * G, D(i + 3, i + 3) = G;
  EXPECT_LE((Matrix(m->tangent()) - D).cwiseAbs().maxCoeff(), 1e-12 * E);
  EXPECT_LE((Matrix(m->initialTangent()) - D).cwiseAbs().maxCoeff(), 1e-12 * E);
}

TEST(ElasticIsotropic, UniaxialStressShearAndHydrostaticStates) {
  const double E = 30e3, nu = 0.2, e = 1e-3;
  auto m = build(args("nDMaterial", 1, E, nu));
  Vector6 uniaxial;
  uniaxial << e, -nu * e, -nu * e, 0, 0, 0;
  m->setTrialStrain(uniaxial);
  Vector6 expected;
  expected << E * e, 0, 0, 0, 0, 0;
  EXPECT_LE((Vector(m->stress()) - expected).cwiseAbs().maxCoeff(), 1e-12 * E * e);

  // Engineering shear strains: tau = G * gamma for each shear component.
  const double G = E / (2 * (1 + nu));
  Vector6 shear;
  shear << 0, 0, 0, 2e-3, -1e-3, 5e-4;
  m->setTrialStrain(shear);
  for (int i = 3; i < 6; ++i) EXPECT_NEAR(m->stress()(i), G * shear(i), 1e-12 * E * 1e-3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m->stress()(i), 0.0, 1e-12 * E * 1e-3);

  const double K = E / (3 * (1 - 2 * nu));
  Vector6 volumetric;
  volumetric << e, e, e, 0, 0, 0;
  m->setTrialStrain(volumetric);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m->stress()(i), 3 * K * e, 1e-12 * E * e);
}

TEST(ElasticIsotropic, FiniteDifferenceTangent) {
  // Linear law: central differences are exact to round-off; tolerance 1e-7 * E.
  const double E = 1000.0;
  auto m = build(args("nDMaterial", 1, E, 0.35));
  Vector6 base;
  base << 1e-3, -2e-3, 5e-4, 3e-3, -1e-3, 2e-3;
  const double h = 1e-6;
  Eigen::Matrix<double, 6, 6> fd;
  for (int j = 0; j < 6; ++j) {
    Vector6 p = base, q = base;
    p(j) += h;
    q(j) -= h;
    m->setTrialStrain(p);
    const Vector6 sp = m->stress();
    m->setTrialStrain(q);
    const Vector6 sq = m->stress();
    fd.col(j) = (sp - sq) / (2 * h);
  }
  m->setTrialStrain(base);
  EXPECT_LE((fd - Matrix(m->tangent())).cwiseAbs().maxCoeff(), 1e-7 * E);
}

TEST(ElasticIsotropic, ClonesForThreeDimensionalAndPlaneUse) {
  auto m = build(args("nDMaterial", 7, 100.0, 0.25, 1.8));
  auto c = m->clone("ThreeDimensional");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->tag(), 7);
  EXPECT_DOUBLE_EQ(c->density(), 1.8);
  EXPECT_EQ(Matrix(c->tangent()), Matrix(m->tangent()));
  // The plane forms are the 3D law with e33 = 0 (strain) or s33 = 0 (stress).
  auto strain = m->clone("PlaneStrain");
  auto stress = m->clone("PlaneStress");
  ASSERT_NE(strain, nullptr);
  ASSERT_NE(stress, nullptr);
  EXPECT_EQ(strain->className(), "ElasticIsotropicPlaneStrain2D");
  EXPECT_DOUBLE_EQ(stress->density(), 1.8);
  const Matrix D3 = m->tangent();
  const int inPlane[3] = {0, 1, 3};  // xx, yy, xy of the Voigt 6-vector
  Matrix condensed = D3;
  // Static condensation of s33 = 0: D_ab - D_a3 D_3b / D_33.
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) condensed(a, b) = D3(a, b) - D3(a, 2) * D3(2, b) / D3(2, 2);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      EXPECT_NEAR(Matrix(strain->tangent())(a, b), D3(inPlane[a], inPlane[b]), 1e-12 * D3(0, 0));
      EXPECT_NEAR(Matrix(stress->tangent())(a, b), condensed(inPlane[a], inPlane[b]), 1e-12 * D3(0, 0));
    }
  Vector e(3);
  e << 1e-3, -2e-4, 5e-4;
  strain->setTrialStrain(e);
  EXPECT_LT((Vector(strain->stress()) - Matrix(strain->tangent()) * e).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(stress->clone("PlaneStrain"), nullptr);
  EXPECT_EQ(m->clone("ContactMaterial3D"), nullptr);
  EXPECT_DOUBLE_EQ(build(args("nDMaterial", 8, 100.0, 0.25))->density(), 0.0);
}

TEST(ElasticIsotropic, CommitRevertAndSetParameter) {
  auto m = build(args("nDMaterial", 1, 100.0, 0.25));
  Vector6 a;
  a << 1, 2, 3, 4, 5, 6;
  m->setTrialStrain(a * 1e-3);
  m->commitState();
  const Vector committedStress = m->stress();
  m->setTrialStrain(-a);
  m->revertToLastCommit();
  EXPECT_EQ(Vector(m->strain()), Vector(a * 1e-3));
  EXPECT_EQ(Vector(m->stress()), committedStress);
  // Doubling E doubles the stress at the same strain.
  EXPECT_TRUE(m->setParameter({"E"}, 200.0));
  EXPECT_LE((Vector(m->stress()) - 2.0 * committedStress).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW(m->setParameter({"nu"}, 0.5), OpenSeesError);
  EXPECT_FALSE(m->setParameter({"friction"}, 1.0));
  m->revertToStart();
  EXPECT_EQ(Vector(m->stress()).norm(), 0.0);
}

TEST(ElasticIsotropic, RejectsUnstableConstants) {
  auto errorOf = [](CommandArgs a) -> std::string {
    try {
      build(std::move(a));
    } catch (const OpenSeesError& e) {
      return e.what();
    }
    return "(no error)";
  };
  const std::string zeroE = errorOf(args("nDMaterial", 5, 0.0, 0.3));
  EXPECT_NE(zeroE.find("nDMaterial ElasticIsotropic 5"), std::string::npos) << zeroE;
  EXPECT_NE(zeroE.find("E must be positive"), std::string::npos) << zeroE;
  EXPECT_NE(errorOf(args("nDMaterial", 5, 1.0, 0.5)).find("-1 < nu < 0.5"), std::string::npos);
  EXPECT_NE(errorOf(args("nDMaterial", 5, 1.0, -1.0)).find("-1 < nu < 0.5"), std::string::npos);
  EXPECT_NE(errorOf(args("nDMaterial", 5, 1.0)).find("(nu)"), std::string::npos);
  EXPECT_EQ(errorOf(args("nDMaterial", 5, 1.0, 0.49, 2.0)), "(no error)");
}
