// J2Plasticity and DruckerPrager at a material point: closed-form yield and
// hardening (uniaxial, pure shear, triaxial compression, tension cutoff),
// one step against many for proportional loading, finite-difference checks
// of the consistent tangents (3D, plane strain, plane stress; elastic, cone,
// apex, cutoff), commit/revert, stages and input validation.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "materials/nd/DruckerPrager.h"
#include "materials/nd/J2Plasticity.h"
#include "materials/nd/PlaneFromThreeDimensional.h"

using namespace beamsolid;
using beamsolid::solidstest::args;

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

template <class... T>
std::unique_ptr<NDMaterial> build(const std::string& type, const T&... values) {
  Domain d;
  CommandArgs a = args("nDMaterial", values...);
  return Registry::global().ndMaterials.get(type)(a, d);
}

Vector6 v6(double a, double b, double c, double d, double e, double f) {
  Vector6 v;
  v << a, b, c, d, e, f;
  return v;
}

// Largest |D - D_fd| / max|D_elastic| with D_fd the central difference of
// the stress about the current trial strain (the committed state
// unchanged); the elastic scale, since D itself may vanish (a perfectly
// plastic apex).
double tangentError(NDMaterial& m, double h) {
  const Vector eps = m.strain();
  const Matrix D = m.tangent();
  const int n = static_cast<int>(eps.size());
  Matrix fd(n, n);
  for (int j = 0; j < n; ++j) {
    Vector e = eps;
    e(j) += h;
    m.setTrialStrain(e);
    const Vector plus = m.stress();
    e(j) -= 2 * h;
    m.setTrialStrain(e);
    const Vector minus = m.stress();
    fd.col(j) = (plus - minus) / (2 * h);
  }
  m.setTrialStrain(eps);
  return (D - fd).cwiseAbs().maxCoeff() / Matrix(m.initialTangent()).cwiseAbs().maxCoeff();
}

// Axial strain e11 with s22 = s33 = lateral (stress control by Newton on
// e22 = e33, shears zero); returns the converged strain.
Vector6 driveAxial(NDMaterial& m, double e11, double lateral, Vector6 start) {
  Vector6 eps = start;
  eps(0) = e11;
  for (int it = 0; it < 50; ++it) {
    m.setTrialStrain(eps);
    const Vector s = m.stress();
    const Matrix D = m.tangent();
    const double r = s(1) - lateral;
    if (std::abs(r) < 1e-13 * (1 + std::abs(s(0))) && std::abs(s(2) - s(1)) < 1e-12 * (1 + std::abs(s(0)))) break;
    // e22 = e33 by symmetry: one unknown.
    const double slope = D(1, 1) + D(1, 2);
    eps(1) -= r / slope;
    eps(2) = eps(1);
  }
  return eps;
}

}  // namespace

// ---------------------------------------------------------------- J2

TEST(J2Plasticity, UniaxialYieldAndLinearHardeningAsClosedForm) {
  const double K = 160e3, G = 80e3, sy = 250.0, H = 2000.0, Hk = 1500.0;
  const double E = 9 * K * G / (3 * K + G);
  for (double kin : {0.0, Hk}) {
    auto m = build("J2Plasticity", 1, K, G, sy, sy, 0.0, H, 0.0, "-kinematic", kin);
    const double ey = sy / E;
    Vector6 eps = Vector6::Zero();
    // Just below yield: elastic with the uniaxial modulus E.
    eps = driveAxial(*m, 0.999 * ey, 0.0, eps);
    EXPECT_NEAR(m->stress()(0), 0.999 * sy, 1e-10 * sy);
    // Past yield: sigma = sy + E (H + Hk) / (E + H + Hk) (e - ey).
    for (double e : {1.5 * ey, 4.0 * ey, 20.0 * ey}) {
      eps = driveAxial(*m, e, 0.0, eps);
      const double Et = E * (H + kin) / (E + H + kin);
      EXPECT_NEAR(m->stress()(0), sy + Et * (e - ey), 1e-10 * sy) << "kin " << kin << " e " << e;
      EXPECT_NEAR(m->stress()(1), 0.0, 1e-9 * sy);
    }
  }
}

TEST(J2Plasticity, PureShearYieldsAtSig0OverSqrt3AndHardensAsClosedForm) {
  const double K = 100.0, G = 50.0, s0 = 1.0, H = 5.0;
  auto m = build("J2Plasticity", 1, K, G, s0, s0, 0.0, H);
  const double tauY = s0 / std::sqrt(3.0);
  m->setTrialStrain(v6(0, 0, 0, 0.999 * tauY / G, 0, 0));
  EXPECT_NEAR(m->stress()(3), 0.999 * tauY, 1e-14);
  for (double g : {0.012, 0.05, 0.3}) {
    m->setTrialStrain(v6(0, 0, 0, g, 0, 0));
    // sqrt(3) tau = s0 + H xi, xi = (2/sqrt3) eps_p12, gamma = tau/G + 2 eps_p12.
    const double tau = (g + std::sqrt(3.0) * s0 / H) / (1.0 / G + 3.0 / H);
    EXPECT_NEAR(m->stress()(3), tau, 1e-13) << g;
    EXPECT_NEAR(m->stress()(0), 0.0, 1e-14);
  }
}

TEST(J2Plasticity, SaturationHardeningMatchesTheScalarConsistencyCondition) {
  // OpenSeesPy 3.7.1 gives 0.5794078532651495 at gamma 0.012 (local tolerance ~1e-9).
  auto m = build("J2Plasticity", 1, 100.0, 50.0, 1.0, 2.0, 10.0, 5.0);
  m->setTrialStrain(v6(0, 0, 0, 0.012, 0, 0));
  const double tau = m->stress()(3);
  const double xi = 2.0 / std::sqrt(3.0) * (0.006 - tau / 100.0);
  const double q = 1.0 + (2.0 - 1.0) * (1 - std::exp(-10.0 * xi)) + 5.0 * xi;
  EXPECT_NEAR(std::sqrt(3.0) * tau, q, 1e-13);
  EXPECT_NEAR(tau, 0.5794078532651495, 1e-8);
}

TEST(J2Plasticity, RadialReturnOneStepEqualsManySteps) {
  const Vector6 direction = v6(0.004, -0.001, 0.0005, 0.003, -0.002, 0.001);
  auto one = build("J2Plasticity", 1, 160e3, 80e3, 250.0, 400.0, 15.0, 800.0, 0.0, "-kinematic", 500.0);
  auto many = one->clone("ThreeDimensional");
  one->setTrialStrain(direction);
  for (int k = 1; k <= 200; ++k) {
    many->setTrialStrain(direction * (k / 200.0));
    many->commitState();
  }
  const Vector a = one->stress(), b = many->stress();
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-12 * a.cwiseAbs().maxCoeff());
}

TEST(J2Plasticity, ConsistentTangentMatchesFiniteDifferences) {
  auto m = build("J2Plasticity", 1, 160e3, 80e3, 250.0, 400.0, 15.0, 800.0, 0.0, "-kinematic", 500.0);
  // Elastic.
  m->setTrialStrain(v6(1e-4, -2e-5, 3e-5, 1e-4, 0, -5e-5));
  EXPECT_LE(tangentError(*m, 1e-9), 1e-8);
  // Plastic from a plastic committed state, then a change of direction.
  m->setTrialStrain(v6(0.004, -0.001, 0.0005, 0.003, -0.002, 0.001));
  m->commitState();
  m->setTrialStrain(v6(0.005, -0.001, 0.0, 0.006, -0.001, 0.0));
  EXPECT_GT(dynamic_cast<J2Plasticity&>(*m).equivalentPlasticStrain(), 0.0);
  EXPECT_LE(tangentError(*m, 1e-9), 1e-8);
}

TEST(J2Plasticity, PlaneStrainAndPlaneStressTangentsMatchFiniteDifferences) {
  auto proto = build("J2Plasticity", 1, 160e3, 80e3, 250.0, 400.0, 15.0, 800.0);
  for (const char* kind : {"PlaneStrain", "PlaneStress"}) {
    auto m = proto->clone(kind);
    ASSERT_TRUE(m) << kind;
    m->setTrialStrain(Eigen::Vector3d(1e-4, -5e-5, 2e-5));
    EXPECT_LE(tangentError(*m, 1e-9), 1e-8) << kind << " elastic";
    m->setTrialStrain(Eigen::Vector3d(0.004, -0.001, 0.003));
    m->commitState();
    m->setTrialStrain(Eigen::Vector3d(0.005, 0.001, 0.002));
    EXPECT_LE(tangentError(*m, 1e-9), 1e-8) << kind << " plastic";
  }
}

TEST(J2Plasticity, PlaneStressIsUniaxialInOneDirectionAndKeepsSigma33Zero) {
  // A plane-stress point pulled in x with s22 = 0 is the uniaxial test.
  const double K = 160e3, G = 80e3, sy = 250.0, H = 2000.0;
  const double E = 9 * K * G / (3 * K + G);
  auto m = build("J2Plasticity", 1, K, G, sy, sy, 0.0, H)->clone("PlaneStress");
  Eigen::Vector3d eps(0, 0, 0);
  const double e = 5 * sy / E;
  eps(0) = e;
  for (int it = 0; it < 50; ++it) {
    m->setTrialStrain(eps);
    const double r = m->stress()(1);
    if (std::abs(r) < 1e-12 * sy) break;
    eps(1) -= r / Matrix(m->tangent())(1, 1);
  }
  EXPECT_NEAR(m->stress()(0), sy + E * H / (E + H) * (e - sy / E), 1e-9 * sy);
  auto& plane = dynamic_cast<PlaneFromThreeDimensional&>(*m);
  EXPECT_NEAR(plane.threeDimensional().stress()(2), 0.0, 1e-9 * sy);
  // In plane strain sigma_33 is kept: nonzero once loaded.
  auto strain = build("J2Plasticity", 1, K, G, sy, sy, 0.0, H)->clone("PlaneStrain");
  strain->setTrialStrain(Eigen::Vector3d(0.001, 0.0, 0.0));
  const auto& s3 = dynamic_cast<PlaneFromThreeDimensional&>(*strain).threeDimensional().stress();
  EXPECT_GT(std::abs(s3(2)), 1.0);
}

TEST(J2Plasticity, RevertRestoresTheCommittedStateExactly) {
  auto m = build("J2Plasticity", 1, 160e3, 80e3, 250.0, 400.0, 15.0, 800.0, 0.0, "-kinematic", 500.0);
  m->setTrialStrain(v6(0.004, -0.001, 0.0005, 0.003, -0.002, 0.001));
  m->commitState();
  const Vector committedStress = m->stress();
  const Matrix committedTangent = m->tangent();
  m->setTrialStrain(v6(-0.004, 0.002, 0.0, -0.006, 0.0, 0.002));
  ASSERT_GT((Vector(m->stress()) - committedStress).norm(), 1.0);
  m->revertToLastCommit();
  EXPECT_EQ(Vector(m->stress()), committedStress);
  EXPECT_EQ(Matrix(m->tangent()), committedTangent);
  // A later trial starts from the same committed plastic state.
  auto reference = m->clone("ThreeDimensional");
  m->setTrialStrain(v6(0.001, 0.0, 0.0, 0.0, 0.0, 0.0));
  reference->setTrialStrain(v6(0.001, 0.0, 0.0, 0.0, 0.0, 0.0));
  EXPECT_EQ(Vector(m->stress()), Vector(reference->stress()));
  m->revertToStart();
  EXPECT_EQ(Vector(m->stress()), Vector(Vector::Zero(6)));
  m->setTrialStrain(v6(1e-4, 0, 0, 0, 0, 0));
  EXPECT_EQ(Matrix(m->tangent()), Matrix(m->initialTangent()));
}

TEST(J2Plasticity, StageZeroIsElasticAndLinear) {
  auto m = build("J2Plasticity", 1, 100.0, 50.0, 1.0, 1.0, 0.0, 0.0);
  EXPECT_FALSE(m->isLinear());
  m->updateStage(0);
  EXPECT_TRUE(m->isLinear());
  m->setTrialStrain(v6(0, 0, 0, 0.1, 0, 0));
  EXPECT_NEAR(m->stress()(3), 50.0 * 0.1, 1e-12);
  m->updateStage(1);
  EXPECT_FALSE(m->isLinear());
  EXPECT_NEAR(m->stress()(3), 1.0 / std::sqrt(3.0), 1e-12);  // perfectly plastic
  EXPECT_THROW(m->updateStage(2), OpenSeesError);
}

TEST(J2Plasticity, BadArgumentsNameTheCommandAndTheArgument) {
  auto expectError = [](std::function<void()> f, const std::string& what) {
    try {
      f();
      ADD_FAILURE() << "no error for " << what;
    } catch (const OpenSeesError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("nDMaterial J2Plasticity 1"), std::string::npos) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  expectError([] { build("J2Plasticity", 1, 100.0, 50.0, 1.0, 2.0, 10.0); }, "H");
  expectError([] { build("J2Plasticity", 1, -100.0, 50.0, 1.0, 2.0, 10.0, 0.0); }, "K");
  expectError([] { build("J2Plasticity", 1, 100.0, 50.0, 0.0, 2.0, 10.0, 0.0); }, "sig0");
  expectError([] { build("J2Plasticity", 1, 100.0, 50.0, 1.0, 2.0, 10.0, 0.0, 0.5); }, "eta");
  expectError([] { build("J2Plasticity", 1, 100.0, 50.0, 1.0, 2.0, 10.0, 0.0, 0.0, "-kin", 1.0); }, "option");
  expectError([] { build("J2Plasticity", 1, 100.0, 50.0, 1.0, 2.0, 10.0, 0.0, 0.0, "-kinematic", -1.0); }, "Hkin");
}

// ---------------------------------------------------------------- Drucker-Prager

namespace {

// K, G, sigmaY, rho, rhoBar, Kinf, Ko, delta1, delta2, H, theta, density
std::unique_ptr<NDMaterial> dp(double rho, double rhoBar, double H = 0.0, double theta = 1.0, double Kinf = 0.0,
                               double Ko = 0.0, double delta1 = 0.0, double delta2 = 0.0) {
  return build("DruckerPrager", 1, 27777.78, 9259.26, 5.0, rho, rhoBar, Kinf, Ko, delta1, delta2, H, theta, 1.7);
}

int lastReturn(const NDMaterial& m) { return dynamic_cast<const DruckerPrager&>(m).lastReturn(); }

}  // namespace

TEST(DruckerPrager, TriaxialCompressionFailsOnTheCone) {
  // Confining pressure pc, axial strain increased: the deviator q = s33 - s11
  // levels off at (sqrt(2/3) sigmaY + 3 rho pc) / (sqrt(2/3) - rho).
  const double pc = 10.0, sY = 5.0;
  for (double rhoBar : {0.398, 0.2, 0.0}) {
    auto m = dp(0.398, rhoBar);
    const double rho = 0.398;
    const double c = std::sqrt(2.0 / 3.0);
    const double qf = (c * sY + 3 * rho * pc) / (c - rho);
    Vector6 eps = Vector6::Zero();
    // Hydrostatic first, then axial compression in x (s22 = s33 = -pc).
    for (double e11 = -pc / (3 * 27777.78); e11 > -0.02; e11 -= 2e-4) {
      eps = driveAxial(*m, e11, -pc, eps);
      m->commitState();
    }
    EXPECT_EQ(lastReturn(*m), 1);
    EXPECT_NEAR(-m->stress()(0) - pc, qf, 1e-9 * qf) << "rhoBar " << rhoBar;
    EXPECT_NEAR(m->stress()(1), -pc, 1e-9 * pc);
  }
}

TEST(DruckerPrager, TensionCutoffHoldsI1AtT0) {
  const double c = std::sqrt(2.0 / 3.0), T0 = c * 5.0 / 0.398;
  for (double rhoBar : {0.398, 0.0}) {
    auto m = dp(0.398, rhoBar);
    m->setTrialStrain(v6(0.01, 0.01, 0.01, 0, 0, 0));
    EXPECT_NEAR(m->stress()(0) * 3, T0, 1e-12 * T0) << rhoBar;
    EXPECT_NEAR(m->stress()(3), 0.0, 1e-12);
    // Tension with shear: on the cutoff, and inside the cone.
    m->setTrialStrain(v6(0.01, 0.01, 0.01, 1e-4, 0, 0));
    EXPECT_NEAR(m->stress()(0) * 3 + 0 * m->stress()(3), T0, 1e-9 * T0);
  }
  // With delta2 the cutoff softens with alphaT: T = T0 exp(-delta2 alphaT), alphaT = dgamma2.
  auto soft = dp(0.398, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 50.0);
  soft->setTrialStrain(v6(0.001, 0.001, 0.001, 0, 0, 0));
  const double I1 = 3 * soft->stress()(0);
  const double I1trial = 3 * 27777.78 * 0.003;
  const double dgamma2 = (I1trial - I1) / (9 * 27777.78);
  EXPECT_NEAR(I1, T0 * std::exp(-50.0 * dgamma2), 1e-12 * T0);
}

TEST(DruckerPrager, KinematicHardeningIsTheConsistentLinearLaw) {
  // rho = 0, theta = 0: von Mises with linear kinematic hardening Hk = H,
  // i.e. J2Plasticity '-kinematic' H, on a pure-shear cycle. Monotonic
  // legs follow tau = (gamma + sqrt3 sY / H) / (1/G + 3/H); after the
  // reversal the stress stays on the translated surface ||s - beta|| =
  // sqrt(2/3) sY (OpenSeesPy 3.7.1 does not: docs/soil_materials.md).
  const double G = 50.0, sY = 1.0, H = 5.0;
  auto m = build("DruckerPrager", 1, 100.0, G, sY, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, H, 0.0, 0.0);
  auto j2 = build("J2Plasticity", 1, 100.0, G, sY, sY, 0.0, 0.0, 0.0, "-kinematic", H);
  for (double g : {0.012, 0.02, 0.05, 0.0, -0.05}) {
    m->setTrialStrain(v6(0, 0, 0, g, 0, 0));
    m->commitState();
    j2->setTrialStrain(v6(0, 0, 0, g, 0, 0));
    j2->commitState();
    EXPECT_NEAR(m->stress()(3), j2->stress()(3), 1e-14) << g;
    if (g > 0.0) EXPECT_NEAR(m->stress()(3), (g + std::sqrt(3.0) * sY / H) / (1 / G + 3 / H), 1e-13) << g;
    const auto state = m->setResponse({"state"}).value();
    EXPECT_NEAR(state(1), std::sqrt(2.0 / 3.0) * sY, 1e-13) << g;  // on the translated surface
  }
  EXPECT_NEAR(m->stress()(3), -0.6393712282480246, 1e-13);  // symmetric to +0.05
}

TEST(DruckerPrager, ReturnMapOneStepEqualsManySteps) {
  const Vector6 direction = v6(-0.001, 0.0005, 0.0002, 0.006, -0.002, 0.001);
  for (auto make : std::vector<std::function<std::unique_ptr<NDMaterial>()>>{
           [] { return dp(0.3, 0.3); }, [] { return dp(0.3, 0.1, 500.0, 1.0, 10.0, 2.0, 20.0); },
           [] { return dp(0.3, 0.2, 300.0, 0.0); }}) {
    auto one = make();
    auto many = make();
    one->setTrialStrain(direction);
    for (int k = 1; k <= 200; ++k) {
      many->setTrialStrain(direction * (k / 200.0));
      many->commitState();
    }
    EXPECT_EQ(lastReturn(*one), 1);
    const Vector a = one->stress(), b = many->stress();
    EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-11 * a.cwiseAbs().maxCoeff());
  }
}

TEST(DruckerPrager, ConsistentTangentMatchesFiniteDifferencesInEveryRegion) {
  struct Case {
    const char* name;
    bool hardening;
    int region;
    Vector6 committed, trial;
  };
  const std::vector<Case> cases = {
      {"elastic", true, 0, Vector6::Zero(), v6(-1e-4, -1e-4, -2e-4, 1e-5, 0, 0)},
      {"cone", true, 1, Vector6::Zero(), v6(-0.001, 0.0005, 0.0002, 0.006, -0.002, 0.001)},
      {"cone from plastic", true, 1, v6(-0.001, 0.0005, 0.0002, 0.006, -0.002, 0.001),
       v6(-0.0012, 0.0006, 0.0003, 0.008, -0.001, 0.002)},
      {"apex", false, 2, Vector6::Zero(), v6(2e-4, 2e-4, 2.2e-4, 1e-5, 0, 0)},
      {"cutoff", true, 3, Vector6::Zero(), v6(0.01, 0.01, 0.01, 0, 0, 0)},
      {"cone and cutoff", true, 4, Vector6::Zero(), v6(0.01, 0.01, 0.01, 0.002, 0.0, 0.0)},
  };
  for (double rhoBar : {0.3, 0.1}) {
    for (const Case& c : cases) {
      auto m = c.hardening ? dp(0.3, rhoBar, 200.0, 0.6, 10.0, 2.0, 20.0, 5.0) : dp(0.3, rhoBar);
      m->setTrialStrain(c.committed);
      m->commitState();
      m->setTrialStrain(c.trial);
      EXPECT_EQ(lastReturn(*m), c.region) << c.name << " rhoBar " << rhoBar;
      // The central difference converges to the consistent tangent: its
      // error falls with h (to round-off) when D is right.
      double best = 1.0;
      for (double h : {1e-7, 1e-8, 1e-9}) best = std::min(best, tangentError(*m, h));
      EXPECT_LE(best, 1e-9) << c.name << " rhoBar " << rhoBar;
    }
  }
}

TEST(DruckerPrager, ApexAndCutoffWithoutDilatancyOrHardening) {
  // The cutoff plane cuts a hardening cone below its apex, so cone and
  // cutoff meet on a circle (region 4); they meet at the apex only for
  // perfect plasticity. With rhoBar = 0 nothing there depends on dgamma1:
  // the deviator is cleared and I1 = T0; the stress is fixed (D = 0).
  auto m = dp(0.3, 0.0);
  m->setTrialStrain(v6(0.01, 0.01, 0.01, 1e-5, 0.0, 0.0));
  EXPECT_EQ(lastReturn(*m), 5);
  const double T0 = std::sqrt(2.0 / 3.0) * 5.0 / 0.3;
  EXPECT_NEAR(3 * m->stress()(0), T0, 1e-12 * T0);
  EXPECT_NEAR(m->stress()(3), 0.0, 1e-12);
  EXPECT_LE(tangentError(*m, 1e-8), 1e-9);  // round-off of the return over 2h
  EXPECT_LE(Matrix(m->tangent()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(DruckerPrager, PlaneStrainTangentMatchesFiniteDifferences) {
  auto m = dp(0.3, 0.1, 200.0, 0.6)->clone("PlaneStrain");
  ASSERT_TRUE(m);
  EXPECT_FALSE(dp(0.3, 0.1)->clone("PlaneStress"));
  m->setTrialStrain(Eigen::Vector3d(-0.003, -0.001, 0.002));
  m->commitState();
  m->setTrialStrain(Eigen::Vector3d(-0.004, 0.0, 0.004));
  EXPECT_LE(tangentError(*m, 1e-10), 1e-7);
}

TEST(DruckerPrager, RevertAndStages) {
  auto m = dp(0.3, 0.1, 200.0, 0.6);
  m->setTrialStrain(v6(-0.004, -0.001, -0.0005, 0.003, -0.002, 0.001));
  m->commitState();
  const Vector committed = m->stress();
  m->setTrialStrain(v6(0.01, 0.01, 0.01, 0.0, 0.0, 0.0));
  m->revertToLastCommit();
  EXPECT_EQ(Vector(m->stress()), committed);
  m->revertToStart();
  EXPECT_EQ(Vector(m->stress()), Vector(Vector::Zero(6)));
  // Stage 0: elastic and linear; stage 1 plastic again (the default).
  m->updateStage(0);
  EXPECT_TRUE(m->isLinear());
  m->setTrialStrain(v6(0, 0, 0, 0.01, 0, 0));
  EXPECT_NEAR(m->stress()(3), 9259.26 * 0.01, 1e-9);
  m->updateStage(1);
  EXPECT_FALSE(m->isLinear());
  EXPECT_LT(m->stress()(3), 9259.26 * 0.01);
  EXPECT_THROW(m->updateStage(2), OpenSeesError);
  EXPECT_THROW(m->setParameter({"materialState"}, 1.0), OpenSeesError);
  EXPECT_TRUE(m->setParameter({"materialState"}, 0.0));
  EXPECT_TRUE(m->isLinear());
  EXPECT_DOUBLE_EQ(m->density(), 1.7);
}

TEST(DruckerPrager, BadArgumentsNameTheCommandAndTheArgument) {
  auto expectError = [](std::function<void()> f, const std::string& what) {
    try {
      f();
      ADD_FAILURE() << "no error for " << what;
    } catch (const OpenSeesError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("nDMaterial DruckerPrager 1"), std::string::npos) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  expectError([] { build("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0); }, "density");
  expectError([] { build("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0); }, "rhoBar");
  expectError([] { build("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.5, 0.0); }, "theta");
  expectError([] { build("DruckerPrager", 1, 1e4, 5e3, 5.0, -0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0); }, "rho");
  expectError([] { build("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1e5, 3.0); },
              "unexpected");
}

// ---------------------------------------------------------------- robustness

TEST(SoilPlasticity, RandomStrainsStayAdmissibleOrFailCleanly) {
  // Random strains from 1e-7 to 1 (log-uniform), committed at random: each
  // answer is finite and on or inside the yield surfaces, or the material
  // raises OpenSeesError (ElementStateError: the step fails). Nothing hangs.
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double c = std::sqrt(2.0 / 3.0);
  int plastic = 0, failures = 0;
  auto j2 = build("J2Plasticity", 1, 160e3, 80e3, 250.0, 400.0, 15.0, 800.0, 0.0, "-kinematic", 500.0);
  auto dpm = dp(0.3, 0.1, 200.0, 0.6, 10.0, 2.0, 20.0, 0.0);  // isotropic and kinematic
  for (int k = 0; k < 3000; ++k) {
    Vector6 eps;
    for (int i = 0; i < 6; ++i) eps(i) = unit(rng);
    eps *= std::pow(10.0, -7.0 + 7.0 * (0.5 + 0.5 * unit(rng)));
    try {
      j2->setTrialStrain(eps);
      const Vector s = j2->stress();
      ASSERT_TRUE(s.allFinite());
      auto& m = dynamic_cast<J2Plasticity&>(*j2);
      const double xi = m.equivalentPlasticStrain();
      const double q = 250.0 + 150.0 * (1 - std::exp(-15.0 * xi)) + 800.0 * xi;
      const Vector beta = m.setResponse({"backStress"}).value();
      Vector6 dev = voigt::deviator(Vector6(s)) - Vector6(beta);
      EXPECT_LE(voigt::norm(dev), c * q * (1 + 1e-10));
      if (xi > 0) ++plastic;
      if (unit(rng) > 0.5) j2->commitState();
    } catch (const OpenSeesError&) {
      ++failures;
    }
    try {
      dpm->setTrialStrain(eps);
      const Vector s = dpm->stress();
      ASSERT_TRUE(s.allFinite());
      const Vector state = dpm->setResponse({"state"}).value();
      const double alpha = dpm->setResponse({"equivalentPlasticStrain"}).value()(0);
      const double Y = 5.0 + 0.6 * 200.0 * alpha + (10.0 - 2.0) * (1 - std::exp(-20.0 * alpha));
      const double scale = std::abs(state(0)) + state(1) + 5.0;
      EXPECT_LE(state(1) + 0.3 * state(0) - c * Y, 1e-9 * scale);  // cone
      EXPECT_LE(state(0) - c * 5.0 / 0.3, 1e-9 * scale);           // cutoff (delta2 = 0)
      if (unit(rng) > 0.5) dpm->commitState();
    } catch (const OpenSeesError&) {
      ++failures;
    }
  }
  EXPECT_GT(plastic, 100);
  EXPECT_EQ(failures, 0);
}
