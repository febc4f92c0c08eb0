// MultiLinear and ElasticMultiLinear: the backbone through the given points
// with the last slope continued, Masing unloading (segments twice as long),
// ElasticMultiLinear loading and unloading on one curve, finite-difference
// tangents on cyclic paths, revert and input errors.
#include <gtest/gtest.h>

#include "core/OpenSeesError.h"
#include "support/ErrorOf.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using namespace beamsolid::uniaxialtest;

namespace {

// Points (1, 10), (2, 15), (4, 18): slopes 10, 5, 1.5.
std::unique_ptr<UniaxialMaterial> multiLinear(Domain& d) {
  return build(d, "MultiLinear", args("uniaxialMaterial", 1, 1.0, 10.0, 2.0, 15.0, 4.0, 18.0));
}

}  // namespace

TEST(MultiLinear, BackboneThroughThePointsAndBeyond) {
  Domain d;
  auto m = multiLinear(d);
  const double strain[] = {0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0};
  const double stress[] = {5.0, 10.0, 12.5, 15.0, 16.5, 18.0, 19.5};
  for (int i = 0; i < 7; ++i) {
    m->setTrialStrain(strain[i]);
    EXPECT_NEAR(m->stress(), stress[i], 1e-13) << strain[i];
    m->setTrialStrain(-strain[i]);  // symmetric
    EXPECT_NEAR(m->stress(), -stress[i], 1e-13) << -strain[i];
  }
}

TEST(MultiLinear, MasingUnloadingDoublesTheSegments) {
  Domain d;
  auto m = multiLinear(d);
  m->setTrialStrain(3.5);  // 17.25 on the backbone
  m->commitState();
  // Unloading: slope 10 over 2 (stress range 2*10), 5 over 2, then 1.5.
  const double strain[] = {2.0, 1.5, 0.5, -0.5, -1.0};
  const double stress[] = {2.25, -2.75, -7.75, -12.75, -13.5};
  const double tangent[] = {10.0, 10.0, 5.0, 5.0, 1.5};
  for (int i = 0; i < 5; ++i) {
    m->setTrialStrain(strain[i]);
    m->commitState();
    EXPECT_NEAR(m->stress(), stress[i], 1e-12) << strain[i];
    EXPECT_DOUBLE_EQ(m->tangent(), tangent[i]) << strain[i];
  }
}

TEST(MultiLinear, TangentAndRevert) {
  Domain d;
  auto m = multiLinear(d);
  expectTangentMatchesFiniteDifference(*m, {3.5, 0.5, 2.0, -4.5, 1.0, -1.0, 5.0}, 0.137, 1e-6, 10.0);
  auto r = multiLinear(d);
  expectRevertRestoresExactly(*r, {0.7, 2.5, 1.1, -0.4, -3.0, 0.2, 4.4}, 1.3);
}

TEST(MultiLinear, InputErrors) {
  Domain d;
  auto err = [&](CommandArgs a) {
    return testsupport::errorOf([&] { build(d, "MultiLinear", std::move(a)); });
  };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1.0, 10.0, 2.0)).find("pairs"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 2.0, 10.0, 1.0, 12.0)).find("increasing"), std::string::npos);
}

TEST(ElasticMultiLinear, LoadsAndUnloadsOnTheCurve) {
  Domain d;
  auto m = build(d, "ElasticMultiLinear",
                 args("uniaxialMaterial", 1, "-strain", -2.0, -1.0, 0.0, 1.0, 3.0, "-stress", -3.0, -2.0, 0.0, 1.0, 2.0));
  // Slopes 1, 2, 1, 0.5, the end ones continued. On a point (strain 0) the
  // tangent is that of the segment above when reached from below, and of the
  // segment below when reached from past the next point (OpenSees' choice).
  const double strain[] = {-3.0, -1.5, -0.5, 0.0, 0.5, 2.0, 4.0, 0.0, 0.5, -3.0};
  const double stress[] = {-4.0, -2.5, -1.0, 0.0, 0.5, 1.5, 2.5, 0.0, 0.5, -4.0};
  const double tangent[] = {1.0, 1.0, 2.0, 1.0, 1.0, 0.5, 0.5, 2.0, 1.0, 1.0};
  for (int i = 0; i < 10; ++i) {
    m->setTrialStrain(strain[i]);
    m->commitState();
    EXPECT_DOUBLE_EQ(m->stress(), stress[i]) << strain[i];
    EXPECT_DOUBLE_EQ(m->tangent(), tangent[i]) << strain[i];
  }
  m->setTrialStrain(1.0, 0.5);  // no viscosity by default
  EXPECT_DOUBLE_EQ(m->stress(), 1.0);
}

TEST(ElasticMultiLinear, ViscousTermTangentAndRevert) {
  Domain d;
  auto m = build(d, "ElasticMultiLinear",
                 args("uniaxialMaterial", 1, 0.3, "-strain", -1.0, 0.0, 2.0, "-stress", -4.0, 0.0, 3.0));
  m->setTrialStrain(1.0, 2.0);
  EXPECT_DOUBLE_EQ(m->stress(), 1.5 + 0.3 * 2.0);
  m->setTrialStrain(0.0);
  expectTangentMatchesFiniteDifference(*m, {2.5, -1.7, 0.3}, 0.11, 1e-6, 4.0);
  expectRevertRestoresExactly(*m, {0.4, -0.3, 2.5}, 1.0);
}

TEST(ElasticMultiLinear, InputErrors) {
  Domain d;
  auto err = [&](CommandArgs a) {
    return testsupport::errorOf([&] { build(d, "ElasticMultiLinear", std::move(a)); });
  };
  EXPECT_NE(err(args("uniaxialMaterial", 1, "-strain", 0.0, 1.0, "-stress", 0.0, 1.0, 2.0)).find("as many"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, "-strain", 0.0, 1.0)).find("-stress"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, "-strain", 1.0, 0.0, "-stress", 0.0, 1.0)).find("increase"),
            std::string::npos);
}
