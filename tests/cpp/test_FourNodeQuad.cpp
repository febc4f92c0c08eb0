// quad (FourNodeQuad) with ElasticIsotropic in plane strain and plane
// stress: the material's D against the closed forms, the tangent against
// finite differences, the patch test on a distorted mesh (round-off),
// rigid-body modes, pressure and body-force resultants, lumped mass and
// input errors.
#include <gtest/gtest.h>

#include <cmath>

#include "SolidsTestSupport.h"
#include "core/LoadPattern.h"
#include "core/OpenSeesError.h"
#include "elements/FourNodeQuad.h"
#include "materials/nd/ElasticIsotropic2D.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using beamsolid::testsupport::errorOf;

namespace {

constexpr double kE = 2.0e4, kNu = 0.3, kThick = 0.4;

void addNode2(Domain& d, int tag, double x, double y) {
  d.addNode(std::make_unique<Node>(tag, 2, Vector3(x, y, 0.0), 2), "test");
}

// One distorted (convex, non-parallelogram) quad, nodes counterclockwise.
const double kCorners[4][2] = {{0.0, 0.0}, {2.0, 0.2}, {2.2, 1.5}, {-0.1, 1.2}};
double shoelaceArea() {
  double twice = 0.0;
  for (int a = 0; a < 4; ++a) {
    const int b = (a + 1) % 4;
    twice += kCorners[a][0] * kCorners[b][1] - kCorners[b][0] * kCorners[a][1];
  }
  return 0.5 * twice;
}

FourNodeQuad& singleQuad(Domain& d, const std::string& type, double p = 0.0, double rho = 0.0, double b1 = 0.0,
                         double b2 = 0.0, double materialRho = 0.0) {
  d.setModelSpace(2, 2);
  for (int a = 0; a < 4; ++a) addNode2(d, a + 1, kCorners[a][0], kCorners[a][1]);
  addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu, materialRho);
  return dynamic_cast<FourNodeQuad&>(addElement(d, "quad", 1, 1, 2, 3, 4, kThick, type, 1, p, rho, b1, b2));
}

Eigen::Matrix3d planeD(const std::string& type) {
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  const double G = kE / (2 * (1 + kNu));
  if (type == "PlaneStress") {
    D(0, 0) = D(1, 1) = kE / (1 - kNu * kNu);
    D(0, 1) = D(1, 0) = kNu * kE / (1 - kNu * kNu);
  } else {
    // sigma = lambda tr(eps) + 2 G eps with eps33 = 0.
    const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
    D(0, 0) = D(1, 1) = lambda + 2 * G;
    D(0, 1) = D(1, 0) = lambda;
  }
  D(2, 2) = G;
  return D;
}

class QuadKinds : public ::testing::TestWithParam<const char*> {};

TEST_P(QuadKinds, MaterialTangentIsThePlaneLaw) {
  Domain d;
  FourNodeQuad& q = singleQuad(d, GetParam());
  const Matrix D = q.material(0).tangent();
  EXPECT_LT((D - planeD(GetParam())).cwiseAbs().maxCoeff(), 1e-12 * kE);
  EXPECT_EQ(q.material(0).className(), std::string("ElasticIsotropic") + GetParam() + "2D");
}

TEST_P(QuadKinds, TangentMatchesFiniteDifferences) {
  Domain d;
  FourNodeQuad& q = singleQuad(d, GetParam(), 7.0, 0.0, 1.0, -2.0);
  const double u[8] = {0.01, -0.02, 0.03, 0.005, -0.01, 0.02, 0.004, -0.03};
  for (int a = 0; a < 4; ++a) {
    Vector ua(2);
    ua << u[2 * a], u[2 * a + 1];
    d.node(a + 1, "t").setTrialDisp(ua);
  }
  const auto check = checkTangent(q, 1e-6);
  EXPECT_LT(check.relativeError(), 1e-8);
}

TEST_P(QuadKinds, RigidBodyModesGiveNoForce) {
  Domain d;
  FourNodeQuad& q = singleQuad(d, GetParam());
  const Matrix K = q.tangentStiff();
  // Translations x, y and the infinitesimal rotation about the origin.
  Eigen::Matrix<double, 8, 3> modes = Eigen::Matrix<double, 8, 3>::Zero();
  for (int a = 0; a < 4; ++a) {
    modes(2 * a, 0) = 1.0;
    modes(2 * a + 1, 1) = 1.0;
    modes(2 * a, 2) = -kCorners[a][1];
    modes(2 * a + 1, 2) = kCorners[a][0];
  }
  EXPECT_LT((K * modes).cwiseAbs().maxCoeff(), 1e-11 * K.cwiseAbs().maxCoeff());
  // Exactly three zero eigenvalues: no spurious mechanism with 2x2 Gauss.
  Eigen::SelfAdjointEigenSolver<Matrix> eig(K);
  EXPECT_LT(std::abs(eig.eigenvalues()(2)), 1e-10 * eig.eigenvalues()(7));
  EXPECT_GT(eig.eigenvalues()(3), 1e-3 * eig.eigenvalues()(7));
}

// A 3 x 3 mesh with moved interior nodes; the boundary nodes get a linear
// displacement field, the interior ones are solved for: they must follow the
// same field and every Gauss point must carry its constant stress.
TEST_P(QuadKinds, PatchTestOnADistortedMeshIsExact) {
  Domain d;
  d.setModelSpace(2, 2);
  const int n = 3;
  auto tag = [&](int i, int j) { return 1 + i + (n + 1) * j; };
  const double moved[2][2][2] = {{{0.11, -0.07}, {-0.09, 0.12}}, {{0.06, 0.1}, {-0.12, -0.05}}};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = 1.5 * i + 0.1 * j, y = 1.0 * j + 0.05 * i * i;
      if (i > 0 && i < n && j > 0 && j < n) x += moved[i - 1][j - 1][0], y += moved[i - 1][j - 1][1];
      addNode2(d, tag(i, j), x, y);
    }
  addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu);
  int e = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      addElement(d, "quad", ++e, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), kThick, GetParam(), 1);

  const Eigen::Vector3d strain(1.0e-3, -4.0e-4, 6.0e-4);  // e11, e22, g12
  auto field = [&](const Vector3& x) {
    Vector u(2);
    u << strain(0) * x.x() + 0.5 * strain(2) * x.y() + 2e-4, 0.5 * strain(2) * x.x() + strain(1) * x.y() - 1e-4;
    return u;
  };
  DenseStatics statics(d);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n) {
        Node& node = d.node(tag(i, j), "t");
        node.setTrialDisp(field(node.crd()));
        statics.fixAll(tag(i, j));
      }
  ASSERT_GE(statics.solve(1e-10), 0);
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) {
      const Node& node = d.node(tag(i, j), "t");
      EXPECT_LT((node.trialDisp() - field(node.crd())).cwiseAbs().maxCoeff(), 1e-14) << i << ',' << j;
    }
  const Eigen::Vector3d stress = planeD(GetParam()) * strain;
  for (int k = 1; k <= n * n; ++k) {
    auto& q = dynamic_cast<FourNodeQuad&>(*d.findElement(k));
    for (int g = 0; g < 4; ++g) {
      EXPECT_LT((Vector(q.material(g).strain()) - strain).cwiseAbs().maxCoeff(), 1e-15);
      EXPECT_LT((Vector(q.material(g).stress()) - stress).cwiseAbs().maxCoeff(), 1e-11 * stress.norm());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, QuadKinds, ::testing::Values("PlaneStrain", "PlaneStress"));

TEST(FourNodeQuad, BodyForceResultantIsBTimesVolume) {
  Domain d;
  FourNodeQuad& q = singleQuad(d, "PlaneStress", 0.0, 3.0, 2.0, -5.0);
  const auto load = q.appliedLoad();
  const double volume = kThick * shoelaceArea();
  EXPECT_NEAR(q.area(), shoelaceArea(), 1e-14);
  EXPECT_NEAR(load(Eigen::seq(0, 7, 2)).sum(), 2.0 * volume, 1e-13);
  EXPECT_NEAR(load(Eigen::seq(1, 7, 2)).sum(), -5.0 * volume, 1e-13);
  // No displacement: the resisting force is minus the load.
  EXPECT_LT((Vector(q.resistingForce()) + load).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(FourNodeQuad, PressureGivesEachEdgePTimesItsLengthAlongTheOutwardNormal) {
  Domain d;
  const double p = 7.0;
  FourNodeQuad& q = singleQuad(d, "PlaneStrain", p);
  const auto load = q.appliedLoad();
  // Node a gets half of the edges a-1 -> a and a -> a+1, each p (dy, -dx).
  for (int a = 0; a < 4; ++a) {
    const int prev = (a + 3) % 4, next = (a + 1) % 4;
    const double dx = kCorners[next][0] - kCorners[prev][0], dy = kCorners[next][1] - kCorners[prev][1];
    EXPECT_NEAR(load(2 * a), 0.5 * p * dy, 1e-14) << a;
    EXPECT_NEAR(load(2 * a + 1), -0.5 * p * dx, 1e-14) << a;
  }
  // A closed boundary: no net force and no net moment.
  double fx = 0, fy = 0, m = 0;
  for (int a = 0; a < 4; ++a) {
    fx += load(2 * a), fy += load(2 * a + 1);
    m += kCorners[a][0] * load(2 * a + 1) - kCorners[a][1] * load(2 * a);
  }
  EXPECT_NEAR(fx, 0.0, 1e-13);
  EXPECT_NEAR(fy, 0.0, 1e-13);
  EXPECT_NEAR(m, 0.0, 1e-13);
}

TEST(FourNodeQuad, SelfWeightLoadsReplaceTheBodyForce) {
  Domain d;
  FourNodeQuad& q = singleQuad(d, "PlaneStress", 0.0, 0.0, 2.0, -5.0);
  ElementLoad load{ElementLoad::Type::SelfWeight, {0.5, 2.0, 0.0}};
  q.zeroLoad();
  q.addLoad(load, 0.25);
  const double volume = kThick * shoelaceArea();
  const auto applied = q.appliedLoad();
  EXPECT_NEAR(applied(Eigen::seq(0, 7, 2)).sum(), 0.25 * 0.5 * 2.0 * volume, 1e-13);
  EXPECT_NEAR(applied(Eigen::seq(1, 7, 2)).sum(), 0.25 * 2.0 * -5.0 * volume, 1e-13);
  q.zeroLoad();
  EXPECT_NEAR(q.appliedLoad()(Eigen::seq(1, 7, 2)).sum(), -5.0 * volume, 1e-13);
}

TEST(FourNodeQuad, LumpedMassTotalsRhoThickArea) {
  for (double materialRho : {0.0, 3.0}) {
    Domain d;
    FourNodeQuad& q = singleQuad(d, "PlaneStress", 0.0, 2.0, 0.0, 0.0, materialRho);
    const Matrix M = q.massMatrix();
    EXPECT_NEAR(M.diagonal()(Eigen::seq(0, 7, 2)).sum(), 2.0 * kThick * shoelaceArea(), 1e-13);
    EXPECT_NEAR(M.diagonal()(Eigen::seq(1, 7, 2)).sum(), 2.0 * kThick * shoelaceArea(), 1e-13);
    EXPECT_EQ((M - Matrix(M.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 0.0);
  }
  // Element rho 0: the material's density.
  Domain d;
  FourNodeQuad& q = singleQuad(d, "PlaneStress", 0.0, 0.0, 0.0, 0.0, 3.0);
  EXPECT_NEAR(Matrix(q.massMatrix()).trace(), 2.0 * 3.0 * kThick * shoelaceArea(), 1e-13);
}

TEST(FourNodeQuad, ParallelogramMassIsAQuarterPerNode) {
  Domain d;
  d.setModelSpace(2, 2);
  const double xy[4][2] = {{0, 0}, {2, 0.5}, {2.6, 2.0}, {0.6, 1.5}};
  for (int a = 0; a < 4; ++a) addNode2(d, a + 1, xy[a][0], xy[a][1]);
  addNDMaterial(d, "ElasticIsotropic", 1, kE, kNu);
  auto& q = dynamic_cast<FourNodeQuad&>(addElement(d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrain", 1, 0.0, 1.5));
  const double area = 2.0 * 1.5 - 0.5 * 0.6;
  const Matrix M = q.massMatrix();
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(M(i, i), 1.5 * kThick * area / 4.0, 1e-14);
}

TEST(FourNodeQuad, ResponsesHaveOpenSeesNamesAndSizes) {
  Domain d;
  FourNodeQuad& q = singleQuad(d, "PlaneStrain");
  const Response s = q.setResponse({"stresses"});
  ASSERT_TRUE(s);
  EXPECT_EQ(s.size(), 12u);
  EXPECT_EQ(s.componentNames[3], "sigma11");
  EXPECT_EQ(q.setResponse({"strains"}).componentNames[2], "eta12");
  EXPECT_EQ(q.setResponse({"forces"}).componentNames[7], "P2_4");
  EXPECT_EQ(q.setResponse({"material", "2", "strain"}).componentNames[0], "eta11");
  EXPECT_EQ(q.setResponse({"material", "4", "stress"}).size(), 3u);
  EXPECT_FALSE(q.setResponse({"material", "5", "stress"}));
  EXPECT_FALSE(q.setResponse({"nothing"}));
}

TEST(FourNodeQuad, BadInputIsRefusedByName) {
  auto model = [](int ndm, int ndf) {
    auto d = std::make_unique<Domain>();
    d->setModelSpace(ndm, ndf);
    for (int a = 0; a < 4; ++a)
      d->addNode(std::make_unique<Node>(a + 1, ndf, Vector3(kCorners[a][0], kCorners[a][1], 0.0), ndm), "test");
    addNDMaterial(*d, "ElasticIsotropic", 1, kE, kNu);
    return d;
  };
  {
    auto d = model(2, 2);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, kThick, "PlaneStrain", 1); })
                  .find("element quad 1: expected 4 node tags and thick"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, 1, kThick, "PlaneStrain", 1); })
                  .find("exactly 4 nodes"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrian", 1); })
                  .find("(type): expected 'PlaneStrain' or 'PlaneStress'"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrain", 9); }).find("9"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrain", 1, 1.0, 2.0, 3.0, 4.0, 5.0); })
                  .find("at most 4 optional numbers"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 4, 3, 2, kThick, "PlaneStrain", 1); })
                  .find("Jacobian determinant"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, -1.0, "PlaneStrain", 1); }).find("thick"),
              std::string::npos);
  }
  {
    auto d = model(3, 3);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrain", 1); })
                  .find("quad is a 2D element"),
              std::string::npos);
  }
  {
    auto d = model(2, 3);
    EXPECT_NE(errorOf([&] { addElement(*d, "quad", 1, 1, 2, 3, 4, kThick, "PlaneStrain", 1); })
                  .find("node 1 has ndm 2 and ndf 3"),
              std::string::npos);
  }
}

}  // namespace
