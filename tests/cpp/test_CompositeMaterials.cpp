// Materials built from other materials: Parallel (stress and tangent are
// factored sums), Series (equal stress, flexibilities add: checked against
// the closed form of two springs and an elastic-plastic one), MinMax (zero
// stress after the limit, for good), InitStrainMaterial (the other material
// shifted by eps0) and InitStressMaterial (shifted to carry sigma0 at zero
// strain); finite-difference tangents, revert and input errors.
#include <gtest/gtest.h>

#include "core/OpenSeesError.h"
#include "materials/uniaxial/InitStressMaterial.h"
#include "materials/uniaxial/MinMaxMaterial.h"
#include "support/ErrorOf.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using namespace beamsolid::uniaxialtest;

namespace {

// 1: Elastic 100; 2: Hardening E 200, sigmaY 2, Hiso 10, Hkin 5; 3: Steel01 Fy 2, E 200, b 0.05.
void addBaseMaterials(Domain& d) {
  addUniaxialMaterial(d, "Elastic", 1, 100.0);
  addUniaxialMaterial(d, "Hardening", 2, 200.0, 2.0, 10.0, 5.0);
  addUniaxialMaterial(d, "Steel01", 3, 2.0, 200.0, 0.05);
}

std::string errorIn(Domain& d, const std::string& type, CommandArgs a) {
  return testsupport::errorOf([&] { build(d, type, std::move(a)); });
}

}  // namespace

TEST(ParallelMaterial, StressAndTangentAreFactoredSums) {
  Domain d;
  addBaseMaterials(d);
  auto p = build(d, "Parallel", args("uniaxialMaterial", 9, 1, 3, "-factors", 0.5, 2.0));
  auto steel = d.uniaxialMaterials.get(3, "test").clone();
  for (double e : {0.005, 0.03, -0.01, -0.04, 0.02}) {
    p->setTrialStrain(e);
    p->commitState();
    steel->setTrialStrain(e);
    steel->commitState();
    EXPECT_NEAR(p->stress(), 0.5 * 100.0 * e + 2.0 * steel->stress(), 1e-14) << e;
    EXPECT_DOUBLE_EQ(p->tangent(), 0.5 * 100.0 + 2.0 * steel->tangent()) << e;
  }
  EXPECT_DOUBLE_EQ(p->initialTangent(), 450.0);
  auto q = build(d, "Parallel", args("uniaxialMaterial", 10, 1, 2, 3));  // factors default to 1
  expectTangentMatchesFiniteDifference(*q, {0.03, -0.02, 0.05, -0.01}, 0.0031, 1e-7, 300.0);
  expectRevertRestoresExactly(*q, {0.01, 0.03, -0.02, 0.0}, 0.02);
}

TEST(SeriesMaterial, ElasticSpringsAddFlexibilities) {
  Domain d;
  addBaseMaterials(d);
  addUniaxialMaterial(d, "Elastic", 4, 50.0);
  auto s = build(d, "Series", args("uniaxialMaterial", 9, 1, 4));
  for (double e : {0.01, -0.03, 0.02}) {
    s->setTrialStrain(e);
    s->commitState();
    EXPECT_NEAR(s->stress(), e / (1.0 / 100.0 + 1.0 / 50.0), 1e-13);
    EXPECT_NEAR(s->tangent(), 100.0 / 3.0, 1e-12);
  }
}

TEST(SeriesMaterial, ElasticAndHardeningBarConvergeToTheClosedForm) {
  // Elastic 100 in series with Hardening: past yield the stress is
  // sigmaY + k_p*(strain - yieldStrain) with compliances added:
  // yield at 2/100 + 2/200 = 0.03, then 1/k_p = 1/100 + 1/Ep.
  Domain d;
  addBaseMaterials(d);
  auto s = build(d, "Series", args("uniaxialMaterial", 9, 1, 2, "-iter", 20, 1e-14));
  const double Ep = 200.0 * 15.0 / 215.0, kp = 1.0 / (0.01 + 1.0 / Ep);
  double e = 0.0;
  for (int k = 0; k < 10; ++k) {
    e += 0.006;
    s->setTrialStrain(e);
    s->commitState();
    const double expected = e <= 0.03 ? e / 0.015 : 2.0 + kp * (e - 0.03);
    EXPECT_NEAR(s->stress(), expected, 1e-12) << e;
    // At the yield point itself (e = 0.03) the bar already reports yielding.
    EXPECT_NEAR(s->tangent(), e < 0.0299 ? 1.0 / 0.015 : kp, 1e-9) << e;
  }
  auto c = build(d, "Series", args("uniaxialMaterial", 10, 1, 2, "-iter", 30, 1e-14));
  expectTangentMatchesFiniteDifference(*c, {0.05, -0.02, 0.06, -0.04}, 0.0041, 1e-7, 70.0, 1e-5);
  auto r = build(d, "Series", args("uniaxialMaterial", 11, 1, 3));
  expectRevertRestoresExactly(*r, {0.01, 0.035, 0.01, -0.03, 0.0}, 0.02);
}

TEST(MinMaxMaterial, FailsForGoodPastEitherLimit) {
  Domain d;
  addBaseMaterials(d);
  auto m = build(d, "MinMax", args("uniaxialMaterial", 9, 3, "-min", -0.02, "-max", 0.032));
  m->setTrialStrain(0.03);
  m->commitState();
  EXPECT_NEAR(m->stress(), 1.9 + 10.0 * 0.03, 1e-14);  // Steel01 hardening line
  m->setTrialStrain(0.033);                            // trial past the limit
  EXPECT_EQ(m->stress(), 0.0);
  EXPECT_DOUBLE_EQ(m->tangent(), 1e-8 * 200.0);
  m->revertToLastCommit();  // not committed: alive again
  EXPECT_NEAR(m->stress(), 2.2, 1e-14);
  m->setTrialStrain(0.033);
  m->commitState();
  for (double e : {0.01, 0.0, -0.01}) {
    m->setTrialStrain(e);
    m->commitState();
    EXPECT_EQ(m->stress(), 0.0);
    EXPECT_EQ(static_cast<MinMaxMaterial&>(*m).failed(), true);
  }
  auto n = build(d, "MinMax", args("uniaxialMaterial", 10, 1, "-min", -0.02));
  n->setTrialStrain(-0.021);
  EXPECT_EQ(n->stress(), 0.0);
  n->setTrialStrain(5.0);  // no upper limit given
  EXPECT_DOUBLE_EQ(n->stress(), 500.0);
  expectRevertRestoresExactly(*build(d, "MinMax", args("uniaxialMaterial", 11, 3, "-max", 0.05)),
                              {0.01, 0.04, -0.02, 0.06, 0.0}, 0.02);
}

TEST(InitStrainMaterial, ShiftsTheOtherMaterialByEps0) {
  Domain d;
  addBaseMaterials(d);
  auto m = build(d, "InitStrainMaterial", args("uniaxialMaterial", 9, 1, 0.004));
  m->setTrialStrain(0.0);
  EXPECT_DOUBLE_EQ(m->stress(), 0.4);
  m->setTrialStrain(0.01);
  EXPECT_DOUBLE_EQ(m->stress(), 1.4);
  EXPECT_DOUBLE_EQ(m->strain(), 0.01);
  auto s = build(d, "InitStrainMaterial", args("uniaxialMaterial", 10, 3, -0.004));
  auto steel = d.uniaxialMaterials.get(3, "test").clone();
  for (double e : {0.01, 0.03, -0.02, 0.0}) {
    s->setTrialStrain(e);
    s->commitState();
    steel->setTrialStrain(e - 0.004);
    steel->commitState();
    EXPECT_DOUBLE_EQ(s->stress(), steel->stress()) << e;
  }
  expectTangentMatchesFiniteDifference(*s, {0.04, -0.03, 0.02}, 0.0029, 1e-7, 200.0);
  expectRevertRestoresExactly(*s, {0.01, 0.03, -0.02}, 0.02);
}

TEST(InitStressMaterial, CarriesSigma0AtZeroStrain) {
  Domain d;
  addBaseMaterials(d);
  auto m = build(d, "InitStressMaterial", args("uniaxialMaterial", 9, 3, 1.0));
  EXPECT_DOUBLE_EQ(static_cast<InitStressMaterial&>(*m).initialStrain(), 0.005);
  m->setTrialStrain(0.0);
  EXPECT_DOUBLE_EQ(m->stress(), 1.0);
  m->setTrialStrain(0.01);  // other material at 0.015: past yield (0.01)
  EXPECT_NEAR(m->stress(), 1.9 + 10.0 * 0.015, 1e-14);
  // Past yield of the other material the shift comes from Newton on its curve.
  auto h = build(d, "InitStressMaterial", args("uniaxialMaterial", 10, 2, 2.5));
  h->setTrialStrain(0.0);
  EXPECT_NEAR(h->stress(), 2.5, 1e-12);
  addUniaxialMaterial(d, "ElasticPP", 5, 100.0, 0.01);  // stress bounded by 1
  EXPECT_NE(errorIn(d, "InitStressMaterial", args("uniaxialMaterial", 11, 5, 1.5)).find("reaches no strain"),
            std::string::npos);
}

TEST(CompositeMaterials, InputErrorsNameCommandAndArgument) {
  Domain d;
  addBaseMaterials(d);
  EXPECT_NE(errorIn(d, "Parallel", args("uniaxialMaterial", 9, 1, 77)).find("uniaxialMaterial 77 does not exist"),
            std::string::npos);
  EXPECT_NE(errorIn(d, "Parallel", args("uniaxialMaterial", 9, 1, 2, "-factors", 1.0)).find("factors"),
            std::string::npos);
  EXPECT_NE(errorIn(d, "Series", args("uniaxialMaterial", 9, 1, 2, "-iter", 0)).find("maxIter"), std::string::npos);
  EXPECT_NE(errorIn(d, "Series", args("uniaxialMaterial", 9, 1, "-bogus")).find("'-iter'"), std::string::npos);
  EXPECT_NE(errorIn(d, "MinMax", args("uniaxialMaterial", 9, 1, "-min", 0.1, "-max", 0.0)).find("below"),
            std::string::npos);
  EXPECT_NE(errorIn(d, "MinMax", args("uniaxialMaterial", 9)).find("otherTag"), std::string::npos);
  EXPECT_NE(errorIn(d, "InitStrainMaterial", args("uniaxialMaterial", 9, 1)).find("initStrain"), std::string::npos);
}
