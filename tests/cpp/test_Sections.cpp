// Sections and beam integration: elastic and fiber sections against closed
// forms (rectangle, circle, EPP plastic moment), patch and layer geometry,
// finite-difference section tangents, fiber responses, command errors, and
// the exactness degree of every integration rule.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/OpenSeesError.h"
#include "sections/BeamIntegration.h"
#include "sections/ElasticSection3d.h"
#include "sections/FiberGeometry.h"
#include "sections/FiberSection3d.h"
#include "support/Script.h"

namespace sectionstest {

using beamsolid::BeamIntegration;
using beamsolid::FiberSection3d;
using beamsolid::OpenSeesError;
using beamsolid::SectionForceDeformation;
using beamsolid::testing::Script;
using Vector4 = SectionForceDeformation::Vector4;
using Matrix4 = SectionForceDeformation::Matrix4;
constexpr double kPi = std::numbers::pi;

SectionForceDeformation& sectionOf(Script& s, int tag) {
  return dynamic_cast<SectionForceDeformation&>(s.interp.domain().sections.get(tag, "test"));
}
FiberSection3d& fiberSectionOf(Script& s, int tag) { return dynamic_cast<FiberSection3d&>(sectionOf(s, tag)); }

void model3d(Script& s) { s("model", "basic", "-ndm", 3, "-ndf", 6); }

// Central differences of the section force over the four deformations.
Matrix4 finiteDifferenceTangent(SectionForceDeformation& section, const Vector4& e, const Vector4& h) {
  Matrix4 k;
  for (int j = 0; j < 4; ++j) {
    Vector4 ep = e, em = e;
    ep[j] += h[j];
    em[j] -= h[j];
    section.setTrialDeformation(ep);
    const Vector4 fp = section.force();
    section.setTrialDeformation(em);
    const Vector4 fm = section.force();
    k.col(j) = (fp - fm) / (2.0 * h[j]);
  }
  section.setTrialDeformation(e);
  return k;
}

// --- elastic section -------------------------------------------------------------

TEST(ElasticSection3d, ForceIsDiagonalStiffnessTimesDeformation) {
  Script s;
  model3d(s);
  s("section", "Elastic", 1, 2.0e5, 0.02, 3.0e-4, 1.0e-4, 8.0e4, 2.0e-4);
  SectionForceDeformation& sec = sectionOf(s, 1);
  const Vector4 e(1e-3, 2e-3, -3e-3, 4e-3);
  sec.setTrialDeformation(e);
  const Vector4 expected(2.0e5 * 0.02 * 1e-3, 2.0e5 * 3.0e-4 * 2e-3, 2.0e5 * 1.0e-4 * -3e-3, 8.0e4 * 2.0e-4 * 4e-3);
  EXPECT_LT((sec.force() - expected).norm(), 1e-14 * expected.norm());
  EXPECT_LT((sec.tangent() - Matrix4(expected.cwiseQuotient(e).asDiagonal())).norm(), 1e-9);
  // Commit and revert.
  sec.commitState();
  sec.setTrialDeformation(2.0 * e);
  sec.revertToLastCommit();
  EXPECT_LT((sec.force() - expected).norm(), 1e-14 * expected.norm());
  sec.revertToStart();
  EXPECT_EQ(sec.force().norm(), 0.0);
}

TEST(ElasticSection3d, CommandErrorsNameTheArgument) {
  Script s;
  model3d(s);
  try {
    s("section", "Elastic", 1, 2.0e5, 0.02, 3.0e-4);
    FAIL();
  } catch (const OpenSeesError& e) {
    EXPECT_NE(std::string(e.what()).find("2D form"), std::string::npos) << e.what();
  }
  try {
    s("section", "Elastic", 1, 2.0e5, -0.02, 3.0e-4, 1.0e-4, 8.0e4, 2.0e-4);
    FAIL();
  } catch (const OpenSeesError& e) {
    EXPECT_NE(std::string(e.what()).find("(A)"), std::string::npos) << e.what();
  }
}

// --- fiber geometry -----------------------------------------------------------------

// Sums over fibers: area, first and second moments about the origin.
struct Moments {
  double area = 0, Qy = 0, Qz = 0, Iyy = 0, Izz = 0, Iyz = 0;  // Iyy = sum A y^2 (bending about z)
};
Moments momentsOf(const std::vector<beamsolid::FiberPoint>& fibers) {
  Moments m;
  for (const auto& f : fibers) {
    m.area += f.area;
    m.Qy += f.area * f.y;
    m.Qz += f.area * f.z;
    m.Iyy += f.area * f.y * f.y;
    m.Izz += f.area * f.z * f.z;
    m.Iyz += f.area * f.y * f.z;
  }
  return m;
}

TEST(FiberGeometry, RectPatchMidpointInertiaIsExactForItsGrid) {
  // Midpoint cells: sum A y^2 = b h^3/12 (1 - 1/n^2) exactly.
  const double b = 0.3, h = 0.5;
  for (int n : {1, 2, 5, 40}) {
    const Moments m = momentsOf(beamsolid::fibergeometry::rectPatch(n, 3, -h / 2, -b / 2, h / 2, b / 2));
    EXPECT_NEAR(m.area, b * h, 1e-15);
    EXPECT_NEAR(m.Iyy, b * h * h * h / 12.0 * (1.0 - 1.0 / (n * n)), 1e-15);
    EXPECT_NEAR(m.Izz, h * b * b * b / 12.0 * (1.0 - 1.0 / 9.0), 1e-15);
    EXPECT_NEAR(m.Qy, 0.0, 1e-15);
    EXPECT_NEAR(m.Qz, 0.0, 1e-15);
  }
}

TEST(FiberGeometry, CircPatchAreaIsExactAndInertiaConvergesAtSecondOrder) {
  const double r = 0.4;
  const double exactI = kPi * std::pow(r, 4) / 4.0;
  std::vector<double> errors;
  for (int n : {4, 8, 16, 32, 64}) {
    const Moments m = momentsOf(beamsolid::fibergeometry::circPatch(2 * n, n, 0.0, 0.0, 0.0, r, 0.0, 360.0));
    EXPECT_NEAR(m.area, kPi * r * r, 1e-13);
    EXPECT_NEAR(m.Qy, 0.0, 1e-14);
    EXPECT_NEAR(m.Qz, 0.0, 1e-14);
    EXPECT_NEAR(m.Iyy, m.Izz, 1e-14);
    errors.push_back(std::fabs(m.Iyy - exactI) / exactI);
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_GT(order, 1.9) << "refinement " << k;
    EXPECT_LT(order, 2.1) << "refinement " << k;
  }
  EXPECT_LT(errors.back(), 1e-3);  // 64 x 128 cells: 2.4e-4
  // A hollow quarter-ring about an offset centre: exact area and centroid.
  const Moments ring =
      momentsOf(beamsolid::fibergeometry::circPatch(1, 1, 1.0, 2.0, 0.2, 0.5, 0.0, 90.0));
  const double area = kPi / 4.0 * (0.25 - 0.04);
  EXPECT_NEAR(ring.area, area, 1e-15);
  // Centroid of a quarter annulus: 4 (r2^3 - r1^3) / (3 pi (r2^2 - r1^2)) from the centre along each axis.
  const double c = 4.0 * (0.125 - 0.008) / (3.0 * kPi * (0.25 - 0.04));
  EXPECT_NEAR(ring.Qy / ring.area, 1.0 + c, 1e-14);
  EXPECT_NEAR(ring.Qz / ring.area, 2.0 + c, 1e-14);
}

TEST(FiberGeometry, QuadPatchTilesTheQuadrilateralExactly) {
  // Trapezoid with parallel sides along z at y = 0 (width 2) and y = 1 (width 1).
  const std::array<Eigen::Vector2d, 4> v = {Eigen::Vector2d(0, -1), Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 0.5),
                                            Eigen::Vector2d(1, -0.5)};
  const double exactArea = 1.5;
  const double exactCentroidY = (1.0 - 1.0 / 3.0) / exactArea;        // integral of y (2 - y) dy / A
  const double exactIyy = 2.0 / 3.0 - 1.0 / 4.0;                      // integral of y^2 (2 - y) dy
  double previous = 1.0;
  for (int n : {2, 4, 8, 16, 32}) {
    for (bool reversed : {false, true}) {
      std::array<Eigen::Vector2d, 4> w = v;
      if (reversed) std::swap(w[1], w[3]);  // clockwise: same cells
      const Moments m = momentsOf(beamsolid::fibergeometry::quadPatch(n, n, w));
      EXPECT_NEAR(m.area, exactArea, 1e-14);
      EXPECT_NEAR(m.Qy / m.area, exactCentroidY, 1e-14);
      EXPECT_NEAR(m.Qz, 0.0, 1e-14);
      const double error = std::fabs(m.Iyy - exactIyy) / exactIyy;
      if (!reversed) {
        EXPECT_LT(error, previous / 3.5) << n;
        previous = error;
      }
    }
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(FiberGeometry, Layers) {
  const auto line = beamsolid::fibergeometry::straightLayer(5, 0.1, 0.0, 1.0, 4.0, -1.0);
  ASSERT_EQ(line.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(line[k].y, k * 1.0, 1e-15);
    EXPECT_NEAR(line[k].z, 1.0 - 0.5 * k, 1e-15);
    EXPECT_EQ(line[k].area, 0.1);
  }
  // Default circular layer: n bars evenly around the circle, sum y^2 = n r^2 / 2.
  const int n = 12;
  const auto ring = beamsolid::fibergeometry::circLayer(n, 1.0, 0.0, 0.0, 0.3, 0.0, 360.0 - 360.0 / n);
  const Moments m = momentsOf(ring);
  EXPECT_NEAR(m.Iyy, n * 0.09 / 2.0, 1e-14);
  EXPECT_NEAR(m.Izz, n * 0.09 / 2.0, 1e-14);
  EXPECT_NEAR(m.Qy, 0.0, 1e-14);
  EXPECT_NEAR(ring[3].y, 0.0, 1e-15);
  EXPECT_NEAR(ring[3].z, 0.3, 1e-15);
}

// --- fiber section --------------------------------------------------------------------

TEST(FiberSection3d, ElasticRectangleStiffnessFromCommands) {
  Script s;
  model3d(s);
  const double E = 2.0e5, b = 0.3, h = 0.5, GJ = 1234.0;
  const int ny = 20, nz = 6;
  s("uniaxialMaterial", "Elastic", 1, E);
  s("section", "Fiber", 3, "-GJ", GJ);
  s("patch", "rect", 1, ny, nz, -h / 2, -b / 2, h / 2, b / 2);
  FiberSection3d& sec = fiberSectionOf(s, 3);
  EXPECT_EQ(sec.numFibers(), static_cast<std::size_t>(ny * nz));
  const Matrix4& k = sec.initialTangent();
  EXPECT_NEAR(k(0, 0), E * b * h, 1e-9 * E * b * h);
  EXPECT_NEAR(k(1, 1), E * b * h * h * h / 12 * (1 - 1.0 / (ny * ny)), 1e-12 * E);
  EXPECT_NEAR(k(2, 2), E * h * b * b * b / 12 * (1 - 1.0 / (nz * nz)), 1e-12 * E);
  EXPECT_NEAR(k(3, 3), GJ, 0.0);
  EXPECT_NEAR(k(0, 1), 0.0, 1e-9);
  EXPECT_NEAR(k(1, 2), 0.0, 1e-9);
  // Sign conventions: a positive curvature about z compresses +y fibers and
  // gives a positive Mz; about y it stretches +z fibers and gives a positive My.
  sec.setTrialDeformation(Vector4(0.0, 1e-3, 0.0, 0.0));
  EXPECT_GT(sec.force()[1], 0.0);
  const int top = sec.nearestFiber(h / 2, 0.0);
  EXPECT_LT(sec.fiber(top).material->stress(), 0.0);
  sec.setTrialDeformation(Vector4(0.0, 0.0, 1e-3, 2e-3));
  EXPECT_GT(sec.force()[2], 0.0);
  EXPECT_NEAR(sec.force()[3], GJ * 2e-3, 1e-15);
  EXPECT_GT(sec.fiber(sec.nearestFiber(0.0, b / 2)).material->stress(), 0.0);
}

TEST(FiberSection3d, ElasticPerfectlyPlasticRectangleReachesPlasticMoment) {
  Script s;
  model3d(s);
  const double E = 2.0e5, fy = 300.0, b = 0.1, h = 0.2;
  const double epsy = fy / E, kappaY = 2 * epsy / h;
  const double Mp = fy * b * h * h / 4.0;
  s("uniaxialMaterial", "ElasticPP", 1, E, epsy);
  s("section", "Fiber", 1, "-GJ", 1.0e3);
  s("patch", "rect", 1, 200, 1, -h / 2, -b / 2, h / 2, b / 2);
  FiberSection3d& sec = fiberSectionOf(s, 1);
  // M(kappa) = Mp (1 - (kappaY/kappa)^2 / 3) beyond yield (continuous section).
  for (double ratio : {2.0, 5.0, 50.0}) {
    sec.setTrialDeformation(Vector4(0.0, ratio * kappaY, 0.0, 0.0));
    const double closed = Mp * (1.0 - 1.0 / (3.0 * ratio * ratio));
    EXPECT_NEAR(sec.force()[1], closed, 1e-4 * Mp) << ratio;
    EXPECT_NEAR(sec.force()[0], 0.0, 1e-9 * fy * b * h);
  }
  EXPECT_NEAR(sec.force()[1], Mp, 0.005 * Mp);
  // Negative curvature about y with a 200 x 1 grid turned: the same plastic moment.
  s("section", "Fiber", 2, "-GJ", 1.0e3);
  s("patch", "rect", 1, 1, 200, -b / 2, -h / 2, b / 2, h / 2);
  FiberSection3d& turned = fiberSectionOf(s, 2);
  turned.setTrialDeformation(Vector4(0.0, 0.0, -50.0 * kappaY, 0.0));
  EXPECT_NEAR(turned.force()[2], -Mp, 0.005 * Mp);
}

TEST(FiberSection3d, TangentMatchesFiniteDifferences) {
  Script s;
  model3d(s);
  const double E = 2.0e5, fy = 300.0;
  s("uniaxialMaterial", "ElasticPP", 1, E, fy / E);
  s("uniaxialMaterial", "ElasticPP", 2, 2.0 * E, 0.5 * fy / E, -1.5 * fy / E);
  s("uniaxialMaterial", "Elastic", 3, 0.1 * E);
  s("uniaxialMaterial", "ElasticPP", 4, 50.0, 0.01);  // torsion: twist rate -> torque
  s("section", "Fiber", 1, "-torsion", 4);
  s("patch", "quad", 1, 9, 7, -0.21, -0.1, 0.19, -0.12, 0.2, 0.11, -0.2, 0.09);
  s("patch", "circ", 3, 12, 3, 0.05, 0.02, 0.0, 0.06);
  s("layer", "straight", 2, 5, 0.001, -0.15, -0.08, 0.16, 0.07);
  s("layer", "circ", 2, 8, 0.0005, 0.0, 0.0, 0.12);
  s("fiber", 0.1, 0.1, 0.002, 2);
  FiberSection3d& sec = fiberSectionOf(s, 1);
  const Vector4 h(1e-9, 1e-8, 1e-8, 1e-8);
  for (const Vector4& e : {Vector4(2e-4, 3e-3, -2e-3, 5e-3), Vector4(-1e-3, -1e-2, 4e-3, 2e-2)}) {
    sec.setTrialDeformation(e);
    // No fiber may sit within the finite-difference step of a kink.
    for (std::size_t i = 0; i < sec.numFibers(); ++i) {
      const auto& f = sec.fiber(i);
      const double strain = e[0] - f.y * e[1] + f.z * e[2];
      for (double kink : {fy / E, -fy / E, 0.5 * fy / E, -1.5 * fy / E})
        ASSERT_GT(std::fabs(strain - kink), 1e-7) << "fiber " << i;
    }
    const Matrix4 k = sec.tangent();
    const Matrix4 fd = finiteDifferenceTangent(sec, e, h);
    EXPECT_LT((k - fd).norm(), 1e-6 * k.norm()) << "tangent\n" << k << "\nfd\n" << fd;
    EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
    EXPECT_GT(k.norm(), 0.0);
  }
  // Mixed yield: some fibers are plastic, so the tangent is below the initial one.
  EXPECT_LT(sec.tangent()(1, 1), sec.initialTangent()(1, 1));
}

TEST(FiberSection3d, CommitRevertAndCopiesAreIndependent) {
  Script s;
  model3d(s);
  s("uniaxialMaterial", "ElasticPP", 1, 1000.0, 0.001);
  s("section", "Fiber", 1, "-GJ", 10.0);
  s("patch", "rect", 1, 10, 2, -0.5, -0.25, 0.5, 0.25);
  FiberSection3d& prototype = fiberSectionOf(s, 1);
  auto copy = prototype.clone();
  const Vector4 yielded(0.0, 0.01, 0.0, 0.0);
  copy->setTrialDeformation(yielded);
  copy->commitState();
  const Vector4 committedForce = copy->force();
  // The prototype never saw the deformation.
  EXPECT_EQ(prototype.force().norm(), 0.0);
  // Unloading from the committed plastic state leaves residual moment at zero curvature.
  copy->setTrialDeformation(Vector4::Zero());
  EXPECT_LT(copy->force()[1], 0.0);
  copy->revertToLastCommit();
  EXPECT_LT((copy->force() - committedForce).norm(), 1e-12 * committedForce.norm());
  EXPECT_EQ(copy->deformation(), yielded);
  copy->revertToStart();
  copy->setTrialDeformation(Vector4(0.0, 1e-4, 0.0, 0.0));
  EXPECT_NEAR(copy->force()[1], copy->initialTangent()(1, 1) * 1e-4, 1e-12);
}

TEST(FiberSection3d, FiberResponses) {
  Script s;
  model3d(s);
  s("uniaxialMaterial", "Elastic", 1, 100.0);
  s("uniaxialMaterial", "Elastic", 2, 300.0);
  s("section", "Fiber", 1, "-GJ", 10.0);
  s("fiber", 0.5, 0.0, 0.01, 1);
  s("fiber", -0.5, 0.0, 0.01, 1);
  s("fiber", 0.45, 0.0, 0.02, 2);
  FiberSection3d& sec = fiberSectionOf(s, 1);
  // The reference axis is the area centroid, as in OpenSees:
  // yBar = (0.5 * 0.01 - 0.5 * 0.01 + 0.45 * 0.02) / 0.04 = 0.225.
  const double yBar = 0.225;
  EXPECT_NEAR(sec.centroidY(), yBar, 1e-15);
  EXPECT_EQ(sec.centroidZ(), 0.0);
  const double eps = 1e-3, kappa = 1e-3;
  sec.setTrialDeformation(Vector4(eps, kappa, 0.0, 0.0));
  const double strain[3] = {eps - (0.5 - yBar) * kappa, eps - (-0.5 - yBar) * kappa, eps - (0.45 - yBar) * kappa};
  // Nearest fiber to (0.49, 0): fiber 0 (material 1); with material 2 requested: fiber 2.
  auto r = sec.setResponse({"fiber", "0.49", "0", "stressStrain"});
  ASSERT_TRUE(r);
  EXPECT_NEAR(r.value()[0], 100.0 * strain[0], 1e-15);
  EXPECT_NEAR(r.value()[1], strain[0], 1e-15);
  r = sec.setResponse({"fiber", "0.49", "0", "2", "stress"});
  ASSERT_TRUE(r);
  EXPECT_NEAR(r.value()[0], 300.0 * strain[2], 1e-13);
  r = sec.setResponse({"fiber", "1", "strain"});
  ASSERT_TRUE(r);
  EXPECT_NEAR(r.value()[0], strain[1], 1e-15);
  EXPECT_FALSE(sec.setResponse({"fiber", "7", "strain"}));
  EXPECT_FALSE(sec.setResponse({"fiber", "0.1", "0.2"}));
  r = sec.setResponse({"fiberData"});
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().size(), 15);
  EXPECT_NEAR(r.value()[5 * 2 + 3], 300.0 * strain[2], 1e-13);
  r = sec.setResponse({"force"});
  ASSERT_TRUE(r);
  EXPECT_NEAR(r.value()[0], 100 * 0.01 * (strain[0] + strain[1]) + 300 * 0.02 * strain[2], 1e-14);
  EXPECT_NEAR(r.value()[1],
              -(100 * 0.01 * ((0.5 - yBar) * strain[0] + (-0.5 - yBar) * strain[1]) + 300 * 0.02 * (0.45 - yBar) * strain[2]),
              1e-14);
  r = sec.setResponse({"stiffness"});
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().size(), 16);
  EXPECT_NEAR(r.value()[0], 100 * 0.02 + 300 * 0.02, 1e-12);
}

TEST(FiberSection3d, CommandErrors) {
  Script s;
  model3d(s);
  s("uniaxialMaterial", "Elastic", 1, 100.0);
  auto expectError = [&s](const std::string& fragment, auto... args) {
    try {
      s(args...);
      ADD_FAILURE() << "no error, expected '" << fragment << "'";
    } catch (const OpenSeesError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError("no section to add fibers to", "patch", "rect", 1, 2, 2, -1.0, -1.0, 1.0, 1.0);
  expectError("needs its torsional response", "section", "Fiber", 1);
  s("section", "Elastic", 2, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0);
  expectError("is not a Fiber section", "fiber", 0.0, 0.0, 1.0, 1);
  s("section", "Fiber", 3, "-GJ", 1.0);
  expectError("uniaxialMaterial 9 does not exist", "patch", "rect", 9, 2, 2, -1.0, -1.0, 1.0, 1.0);
  expectError("numSubdivY", "patch", "rect", 1, 0, 2, -1.0, -1.0, 1.0, 1.0);
  expectError("no area", "patch", "rect", 1, 2, 2, -1.0, 1.0, 1.0, 1.0);
  expectError("extRad", "patch", "circ", 1, 4, 2, 0.0, 0.0, 0.5, 0.2);
  expectError("patch type 'hex' is unknown", "patch", "hex", 1, 4, 2);
  expectError("areaFiber", "layer", "straight", 1, 3, -1.0, 0.0, 0.0, 1.0, 1.0);
  expectError("section with tag 3 already exists", "section", "Fiber", 3, "-GJ", 1.0);
  expectError("type 'Bogus' is unknown", "section", "Bogus", 4);
  // A failed patch adds nothing.
  EXPECT_EQ(fiberSectionOf(s, 3).numFibers(), 0u);
}

// --- beam integration -------------------------------------------------------------------

double integrate(const std::vector<double>& xi, const std::vector<double>& w, int degree) {
  double sum = 0.0;
  for (std::size_t i = 0; i < xi.size(); ++i) sum += w[i] * std::pow(xi[i], degree);
  return sum;
}

// The highest degree a rule integrates exactly on [0, 1] (checked up to 3n).
int exactDegree(const std::vector<double>& xi, const std::vector<double>& w) {
  int degree = 0;
  while (degree <= 3 * static_cast<int>(xi.size()) &&
         std::fabs(integrate(xi, w, degree) - 1.0 / (degree + 1)) < 1e-13)
    ++degree;
  return degree - 1;
}

TEST(BeamIntegration, RulesIntegrateToTheirDegree) {
  // Up to 8 points the first inexact degree is detectable at 1e-13; beyond,
  // the rules' error constants fall below it, so only ">=" is checked.
  std::vector<double> xi, w;
  for (int n = 1; n <= 12; ++n) {
    auto check = [n](int measured, int expected, const char* rule) {
      if (n <= 8) EXPECT_EQ(measured, expected) << rule << " " << n;
      else EXPECT_GE(measured, expected) << rule << " " << n;
    };
    BeamIntegration::gaussLegendre(n, xi, w);
    check(exactDegree(xi, w), 2 * n - 1, "Legendre");
    BeamIntegration::gaussRadau(n, xi, w);
    check(exactDegree(xi, w), 2 * n - 2, "Radau");
    EXPECT_EQ(xi.front(), 0.0);
    if (n >= 2) {
      BeamIntegration::gaussLobatto(n, xi, w);
      check(exactDegree(xi, w), std::max(1, 2 * n - 3), "Lobatto");
      EXPECT_EQ(xi.front(), 0.0);
      EXPECT_EQ(xi.back(), 1.0);
      BeamIntegration::newtonCotes(n, xi, w);
      check(exactDegree(xi, w), n % 2 ? n : n - 1, "NewtonCotes");
    }
  }
  // Points ascend inside [0, 1] with positive weights (Gauss rules).
  BeamIntegration::gaussLobatto(10, xi, w);
  for (std::size_t i = 1; i < xi.size(); ++i) EXPECT_GT(xi[i], xi[i - 1]);
  for (double weight : w) EXPECT_GT(weight, 0.0);
  // Known small rules.
  BeamIntegration::gaussLobatto(3, xi, w);
  EXPECT_NEAR(xi[1], 0.5, 1e-15);
  EXPECT_NEAR(w[0], 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(w[1], 2.0 / 3.0, 1e-15);
  BeamIntegration::gaussRadau(2, xi, w);
  EXPECT_NEAR(xi[1], 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(w[0], 0.25, 1e-15);
  BeamIntegration::gaussLegendre(2, xi, w);
  EXPECT_NEAR(xi[0], 0.5 - 0.5 / std::sqrt(3.0), 1e-15);
}

TEST(BeamIntegration, HingeRulesFromCommands) {
  Script s;
  model3d(s);
  s("section", "Elastic", 1, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0);
  s("section", "Elastic", 2, 2.0, 1.0, 1.0, 1.0, 1.0, 1.0);
  s("beamIntegration", "HingeRadau", 7, 1, 0.1, 1, 0.2, 2);
  s("beamIntegration", "HingeRadauTwo", 8, 1, 0.1, 1, 0.2, 2);
  const BeamIntegration& radau = s.interp.domain().beamIntegrations.get(7, "test");
  const double L = 4.0;
  std::vector<double> xi, w;
  radau.pointsAndWeights(L, xi, w);
  ASSERT_EQ(xi.size(), 6u);
  // End weights equal the hinge lengths; the second points sit at 8/3 lp.
  EXPECT_NEAR(w[0] * L, 0.1, 1e-15);
  EXPECT_NEAR(w[5] * L, 0.2, 1e-15);
  EXPECT_NEAR(xi[1] * L, 8.0 / 3.0 * 0.1, 1e-15);
  EXPECT_NEAR((1.0 - xi[4]) * L, 8.0 / 3.0 * 0.2, 1e-15);
  // Only the end points are hinge sections (Scott and Fenves' modified Radau:
  // the hinge is lp long); HingeRadauTwo puts both points of a region in the hinge.
  EXPECT_EQ(radau.sectionTags(), (std::vector<int>{1, 2, 2, 2, 2, 1}));
  EXPECT_EQ(s.interp.domain().beamIntegrations.get(8, "test").sectionTags(), (std::vector<int>{1, 1, 2, 2, 1, 1}));
  // Each region integrates quadratics exactly, so the whole rule does.
  for (int degree = 0; degree <= 2; ++degree)
    EXPECT_NEAR(integrate(xi, w, degree), 1.0 / (degree + 1), 1e-15) << degree;
  s.interp.domain().beamIntegrations.get(8, "test").pointsAndWeights(L, xi, w);
  EXPECT_NEAR(w[0] * L, 0.025, 1e-15);
  EXPECT_NEAR(xi[1] * L, 2.0 / 3.0 * 0.1, 1e-15);
  for (int degree = 0; degree <= 2; ++degree)
    EXPECT_NEAR(integrate(xi, w, degree), 1.0 / (degree + 1), 1e-15) << degree;
  // Hinges longer than the element.
  EXPECT_THROW(radau.pointsAndWeights(1.0, xi, w), OpenSeesError);
}

TEST(BeamIntegration, CommandForms) {
  Script s;
  model3d(s);
  s("section", "Elastic", 1, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0);
  s("section", "Elastic", 2, 2.0, 1.0, 1.0, 1.0, 1.0, 1.0);
  s("beamIntegration", "Lobatto", 1, 1, 5);
  s("beamIntegration", "Legendre", 2, 3, 1, 2, 1);
  auto& domain = s.interp.domain();
  EXPECT_EQ(domain.beamIntegrations.get(1, "t").sectionTags(), std::vector<int>(5, 1));
  EXPECT_EQ(domain.beamIntegrations.get(2, "t").sectionTags(), (std::vector<int>{1, 2, 1}));
  EXPECT_THROW(s("beamIntegration", "Lobatto", 3, 1, 1), OpenSeesError);   // one Lobatto point
  EXPECT_THROW(s("beamIntegration", "Lobatto", 3, 9, 4), OpenSeesError);   // no section 9
  EXPECT_THROW(s("beamIntegration", "Legendre", 3, 3, 1, 2), OpenSeesError);  // 3 points, 2 tags
  EXPECT_THROW(s("beamIntegration", "Simpson", 3, 1, 3), OpenSeesError);
  EXPECT_THROW(s("beamIntegration", "Lobatto", 1, 1, 3), OpenSeesError);  // duplicate tag
}

}  // namespace sectionstest
