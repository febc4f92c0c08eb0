// Elastic and ElasticPP uniaxial materials: hand-computed stress points for
// monotonic and cyclic strain histories, finite-difference tangents, and
// exact state restoration by revertToLastCommit / revertToStart.
#include <gtest/gtest.h>

#include <memory>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "materials/uniaxial/ElasticMaterial.h"
#include "materials/uniaxial/ElasticPPMaterial.h"

using namespace beamsolid;
using beamsolid::solidstest::args;

namespace {

std::unique_ptr<UniaxialMaterial> build(const std::string& type, CommandArgs a) {
  Domain d;
  return Registry::global().uniaxialMaterials.get(type)(a, d);
}

// Central difference of stress with respect to strain at the current trial
// state, relative to the committed state (the material is left at `strain`).
double finiteDifferenceTangent(UniaxialMaterial& m, double strain, double h) {
  m.setTrialStrain(strain + h);
  const double plus = m.stress();
  m.setTrialStrain(strain - h);
  const double minus = m.stress();
  m.setTrialStrain(strain);
  return (plus - minus) / (2.0 * h);
}

std::string errorOf(const std::string& type, CommandArgs a) {
  try {
    build(type, std::move(a));
  } catch (const OpenSeesError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ElasticMaterial, DefaultsAreSymmetricAndUndamped) {
  auto m = build("Elastic", args("uniaxialMaterial", 1, 200.0));
  m->setTrialStrain(-0.01, 3.0);
  EXPECT_DOUBLE_EQ(m->stress(), -2.0);
  EXPECT_DOUBLE_EQ(m->tangent(), 200.0);
  m->setTrialStrain(0.01);
  EXPECT_DOUBLE_EQ(m->stress(), 2.0);
  EXPECT_DOUBLE_EQ(m->initialTangent(), 200.0);
}

TEST(ElasticMaterial, TensionCompressionModuliAndDamping) {
  // E = 200, eta = 5, Eneg = 100.
  auto m = build("Elastic", args("uniaxialMaterial", 1, 200.0, 5.0, 100.0));
  struct Point { double strain, rate, stress, tangent; };
  // stress = E*strain (strain > 0) or Eneg*strain, plus eta*rate; worked by hand.
  const Point history[] = {
      {0.01, 0.0, 2.0, 200.0}, {0.02, 0.1, 4.5, 200.0}, {-0.01, 0.0, -1.0, 100.0},
      {-0.03, -0.2, -4.0, 100.0}, {0.0, 0.0, 0.0, 100.0}, {0.005, 0.0, 1.0, 200.0},
  };
  for (const Point& p : history) {
    m->setTrialStrain(p.strain, p.rate);
    EXPECT_NEAR(m->stress(), p.stress, 1e-12) << "strain " << p.strain;
    EXPECT_DOUBLE_EQ(m->tangent(), p.tangent) << "strain " << p.strain;
    m->commitState();
  }
}

TEST(ElasticMaterial, FiniteDifferenceTangent) {
  // Central differences of a piecewise-linear law are exact away from the
  // kink at zero strain: tolerance 1e-6 relative.
  auto m = build("Elastic", args("uniaxialMaterial", 1, 200.0, 0.0, 50.0));
  for (double strain : {0.02, 0.001, -0.001, -0.05}) {
    const double fd = finiteDifferenceTangent(*m, strain, 1e-7);
    EXPECT_NEAR(fd, m->tangent(), 1e-6 * 200.0) << "strain " << strain;
  }
}

TEST(ElasticMaterial, RevertToLastCommitRestoresStrainAndStress) {
  auto m = build("Elastic", args("uniaxialMaterial", 1, 200.0, 2.0));
  m->setTrialStrain(0.004, 0.5);
  m->commitState();
  const double committedStress = m->stress();
  m->setTrialStrain(0.02, 1.0);
  m->revertToLastCommit();
  EXPECT_EQ(m->strain(), 0.004);
  EXPECT_EQ(m->stress(), committedStress);
  m->revertToStart();
  EXPECT_EQ(m->strain(), 0.0);
  EXPECT_EQ(m->stress(), 0.0);
}

TEST(ElasticMaterial, ClonesAreIndependent) {
  auto m = build("Elastic", args("uniaxialMaterial", 4, 10.0));
  auto c = m->clone();
  c->setTrialStrain(1.0);
  EXPECT_EQ(m->strain(), 0.0);
  EXPECT_EQ(c->tag(), 4);
  EXPECT_DOUBLE_EQ(c->stress(), 10.0);
}

TEST(ElasticMaterial, ErrorsNameCommandAndArgument) {
  const std::string msg = errorOf("Elastic", args("uniaxialMaterial", 3));
  EXPECT_NE(msg.find("uniaxialMaterial Elastic 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(E)"), std::string::npos) << msg;
  const std::string extra = errorOf("Elastic", args("uniaxialMaterial", 3, 1.0, 0.0, 1.0, 7.0));
  EXPECT_NE(extra.find("unexpected extra argument"), std::string::npos) << extra;
}

TEST(ElasticPPMaterial, CyclicHistoryMatchesHandComputedPoints) {
  // E = 200, epsyP = 0.01, epsyN = -0.005: fyP = 2, fyN = -1.
  auto m = build("ElasticPP", args("uniaxialMaterial", 1, 200.0, 0.01, -0.005));
  auto* pp = dynamic_cast<ElasticPPMaterial*>(m.get());
  ASSERT_NE(pp, nullptr);
  struct Point { double strain, stress, tangent, plasticStrain; };
  // Each point: elastic predictor 200*(strain - committed plastic strain),
  // capped at fyP / fyN; worked by hand and committed in turn.
  const Point history[] = {
      {0.005, 1.0, 200.0, 0.0},      // elastic
      {0.02, 2.0, 0.0, 0.01},        // predictor 4 > 2: yields in tension
      {0.015, 1.0, 200.0, 0.01},     // elastic unloading
      {0.0, -1.0, 0.0, 0.005},       // predictor -2 < -1: yields in compression
      {0.01, 1.0, 200.0, 0.005},     // elastic reloading
      {0.03, 2.0, 0.0, 0.02},        // predictor 5: yields in tension again
      {-0.01, -1.0, 0.0, -0.005},    // predictor -6: yields in compression
      {-0.005, 0.0, 200.0, -0.005},  // back to zero stress
  };
  for (const Point& p : history) {
    m->setTrialStrain(p.strain);
    EXPECT_NEAR(m->stress(), p.stress, 1e-12) << "strain " << p.strain;
    EXPECT_DOUBLE_EQ(m->tangent(), p.tangent) << "strain " << p.strain;
    EXPECT_NEAR(pp->plasticStrain(), p.plasticStrain, 1e-15) << "strain " << p.strain;
    m->commitState();
  }
}

TEST(ElasticPPMaterial, DefaultsAndInitialStrain) {
  // epsyN defaults to -epsyP.
  auto sym = build("ElasticPP", args("uniaxialMaterial", 1, 100.0, 0.02));
  sym->setTrialStrain(-0.05);
  EXPECT_DOUBLE_EQ(sym->stress(), -2.0);
  // eps0 = 0.01 shifts the curve: stress = 100*(strain - 0.01) until +-2.
  auto m = build("ElasticPP", args("uniaxialMaterial", 2, 100.0, 0.02, -0.02, 0.01));
  m->setTrialStrain(0.0);
  EXPECT_NEAR(m->stress(), -1.0, 1e-12);
  m->setTrialStrain(0.025);
  EXPECT_NEAR(m->stress(), 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(m->tangent(), 100.0);
  m->setTrialStrain(0.05);
  EXPECT_NEAR(m->stress(), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(m->tangent(), 0.0);
  m->setTrialStrain(-0.02);
  EXPECT_NEAR(m->stress(), -2.0, 1e-12);
}

TEST(ElasticPPMaterial, AStateOnTheYieldSurfaceIsPlastic) {
  // As in OpenSees (checked with OpenSeesPy 3.7.1's testUniaxialMaterial):
  // the yield strain itself gives the yield stress with tangent 0, and after
  // a committed yield the same strain again (the start of the next step)
  // stays plastic. Just inside the surface it is elastic.
  auto m = build("ElasticPP", args("uniaxialMaterial", 1, 200e3, 0.002));
  m->setTrialStrain(0.0019999999);
  EXPECT_DOUBLE_EQ(m->tangent(), 200e3);
  m->setTrialStrain(0.002);
  EXPECT_DOUBLE_EQ(m->stress(), 400.0);
  EXPECT_DOUBLE_EQ(m->tangent(), 0.0);
  // Strains whose predictor lands on the surface only up to round-off.
  for (double strain : {0.003, 0.0030000000000000001, 0.1 / 3.0, 0.7}) {
    auto n = build("ElasticPP", args("uniaxialMaterial", 2, 200e3, 0.002));
    n->setTrialStrain(strain);
    n->commitState();
    n->setTrialStrain(strain);
    EXPECT_NEAR(n->stress(), 400.0, 1e-9) << strain;
    EXPECT_DOUBLE_EQ(n->tangent(), 0.0) << strain;
    n->setTrialStrain(-strain);
    n->commitState();
    n->setTrialStrain(-strain);
    EXPECT_NEAR(n->stress(), -400.0, 1e-9) << strain;
    EXPECT_DOUBLE_EQ(n->tangent(), 0.0) << strain;
    n->setTrialStrain(-strain + 1e-6);  // unloading is elastic
    EXPECT_DOUBLE_EQ(n->tangent(), 200e3) << strain;
  }
}

TEST(ElasticPPMaterial, TrialsWithinAStepDoNotAccumulatePlasticStrain) {
  auto m = build("ElasticPP", args("uniaxialMaterial", 1, 200.0, 0.01));
  m->setTrialStrain(0.03);  // would leave plastic strain 0.02 if committed
  EXPECT_DOUBLE_EQ(m->stress(), 2.0);
  m->setTrialStrain(0.005);  // same step: measured from the committed state
  EXPECT_NEAR(m->stress(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(m->tangent(), 200.0);
}

TEST(ElasticPPMaterial, RevertToLastCommitRestoresStateExactly) {
  auto m = build("ElasticPP", args("uniaxialMaterial", 1, 200.0, 0.01, -0.005));
  auto* pp = dynamic_cast<ElasticPPMaterial*>(m.get());
  m->setTrialStrain(0.02);
  m->commitState();
  const double strain = m->strain(), stress = m->stress(), tangent = m->tangent(), ep = pp->plasticStrain();
  m->setTrialStrain(-0.01);  // yields in compression, not committed
  EXPECT_DOUBLE_EQ(m->stress(), -1.0);
  m->revertToLastCommit();
  EXPECT_EQ(m->strain(), strain);
  EXPECT_EQ(m->stress(), stress);
  EXPECT_EQ(m->tangent(), tangent);
  EXPECT_EQ(pp->plasticStrain(), ep);
  // Continuing from the restored state follows the committed plastic strain.
  m->setTrialStrain(0.015);
  EXPECT_NEAR(m->stress(), 1.0, 1e-12);
  m->revertToStart();
  EXPECT_EQ(m->strain(), 0.0);
  EXPECT_EQ(m->stress(), 0.0);
  EXPECT_EQ(pp->plasticStrain(), 0.0);
  EXPECT_EQ(m->tangent(), 200.0);
}

TEST(ElasticPPMaterial, FiniteDifferenceTangentBeforeAndAfterYield) {
  // Piecewise linear: central differences away from the yield points are
  // exact up to round-off; tolerance 1e-6 * E.
  auto m = build("ElasticPP", args("uniaxialMaterial", 1, 200.0, 0.01, -0.005));
  const double h = 1e-7;
  EXPECT_NEAR(finiteDifferenceTangent(*m, 0.004, h), m->tangent(), 2e-4);
  m->setTrialStrain(0.02);
  m->commitState();  // plastic strain 0.01
  for (double strain : {0.025, 0.012, 0.003, -0.01}) {
    const double fd = finiteDifferenceTangent(*m, strain, h);
    EXPECT_NEAR(fd, m->tangent(), 2e-4) << "strain " << strain;
  }
  m->setTrialStrain(0.025);
  EXPECT_EQ(m->tangent(), 0.0);
}

TEST(ElasticPPMaterial, RejectsNonsenseYieldStrains) {
  const std::string a = errorOf("ElasticPP", args("uniaxialMaterial", 3, 200.0, -0.01));
  EXPECT_NE(a.find("uniaxialMaterial ElasticPP 3"), std::string::npos) << a;
  EXPECT_NE(a.find("epsyP"), std::string::npos) << a;
  const std::string b = errorOf("ElasticPP", args("uniaxialMaterial", 3, 200.0, 0.01, 0.02));
  EXPECT_NE(b.find("epsyN"), std::string::npos) << b;
  const std::string c = errorOf("ElasticPP", args("uniaxialMaterial", 3, 0.0, 0.01));
  EXPECT_NE(c.find("E must be positive"), std::string::npos) << c;
}

TEST(UniaxialMaterials, ResponsesThroughTheBase) {
  auto m = build("ElasticPP", args("uniaxialMaterial", 1, 200.0, 0.01));
  m->setTrialStrain(0.02);
  Response r = m->setResponse({"stressStrain"});
  ASSERT_TRUE(r);
  const Vector v = r.value();
  ASSERT_EQ(v.size(), 2);
  EXPECT_DOUBLE_EQ(v(0), 2.0);
  EXPECT_DOUBLE_EQ(v(1), 0.02);
}
