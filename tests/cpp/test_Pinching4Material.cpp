// Pinching4: the four-point envelopes hit exactly under monotonic loading
// (and the two tails past the fourth point), the undamaged unload-reload
// path R-B-C-D worked out by hand from the documented ratios, the unloading
// stiffness K0*(1 - gK1*(dmax/dfail)^gK3) after a cycle, the symmetric form
// equal to the mirrored asymmetric one, finite-difference tangents on
// damaging cyclic paths, revert, and input errors. Point-by-point agreement
// with OpenSees is in tests/python/test_uniaxial_oracle.py.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/OpenSeesError.h"
#include "support/ErrorOf.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using namespace beamsolid::uniaxialtest;

namespace {

// Positive envelope (0.01, 10), (0.03, 15), (0.06, 18), (0.1, 12); negative
// (-0.012, -12), (-0.035, -16), (-0.07, -19), (-0.12, -8): both K0 = 1000.
CommandArgs pinching(int tag, std::vector<double> damage, const std::string& type = "energy",
                     double rDispP = 0.5, double rForceP = 0.25, double uForceP = 0.05) {
  std::vector<CommandArgs::Value> v{static_cast<long long>(tag)};
  for (double x : {10.0, 0.01, 15.0, 0.03, 18.0, 0.06, 12.0, 0.1, -12.0, -0.012, -16.0, -0.035, -19.0, -0.07, -8.0,
                   -0.12, rDispP, rForceP, uForceP, 0.4, 0.3, 0.1})
    v.push_back(x);
  for (double g : damage) v.push_back(g);
  v.push_back(10.0);
  v.push_back(type);
  return CommandArgs("uniaxialMaterial", std::move(v));
}

std::vector<double> noDamage() { return std::vector<double>(15, 0.0); }

void step(UniaxialMaterial& m, double strain) {
  m.setTrialStrain(strain);
  m.commitState();
}

// Walks to `target` in steps of `h`, committing each.
void walk(UniaxialMaterial& m, double& current, double target, double h = 1e-4) {
  const int n = static_cast<int>(std::round(std::abs(target - current) / h));
  const double from = current;
  for (int i = 1; i <= n; ++i) step(m, from + (target - from) * i / n);
  current = target;
}

}  // namespace

TEST(Pinching4Material, EnvelopePointsHitExactlyUnderMonotonicLoading) {
  Domain d;
  const double pd[] = {0.01, 0.03, 0.06, 0.1}, pf[] = {10.0, 15.0, 18.0, 12.0};
  const double nd[] = {-0.012, -0.035, -0.07, -0.12}, nf[] = {-12.0, -16.0, -19.0, -8.0};
  auto p = build(d, "Pinching4", pinching(1, noDamage()));
  double current = 0.0;
  for (int i = 0; i < 4; ++i) {
    walk(*p, current, pd[i], 1e-3);
    EXPECT_NEAR(p->stress(), pf[i], 1e-12) << pd[i];
  }
  // Past the falling fourth branch: towards 1.1*f4 at 1e6*d4.
  walk(*p, current, 0.2, 1e-2);
  EXPECT_NEAR(p->tangent(), 1.2 / (1e6 * 0.1 - 0.1), 1e-18);
  EXPECT_NEAR(p->stress(), 12.0 + 0.1 * 1.2 / (1e6 * 0.1 - 0.1), 1e-12);
  auto n = build(d, "Pinching4", pinching(2, noDamage()));
  current = 0.0;
  for (int i = 0; i < 4; ++i) {
    walk(*n, current, nd[i], 1e-3);
    EXPECT_NEAR(n->stress(), nf[i], 1e-12) << nd[i];
  }
  // A rising fourth branch goes on with its slope.
  auto h = build(d, "Pinching4", args("uniaxialMaterial", 3, 10.0, 0.01, 15.0, 0.03, 18.0, 0.06, 20.0, 0.1, 0.5, 0.25,
                                      0.05, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                                      10.0, "energy"));
  current = 0.0;
  walk(*h, current, 0.15, 1e-3);
  EXPECT_NEAR(h->stress(), 20.0 + 0.05 * 50.0, 1e-12);
  EXPECT_NEAR(h->tangent(), 50.0, 1e-12);
}

TEST(Pinching4Material, UndamagedUnloadReloadPath) {
  Domain d;
  auto m = build(d, "Pinching4", pinching(1, noDamage()));
  double current = 0.0;
  walk(*m, current, 0.05);
  ASSERT_NEAR(m->stress(), 17.0, 1e-12);
  // Unloading with K0 = 1000 down to uForceN*eNf3 = -1.9 at B = (0.0311, -1.9).
  step(*m, 0.04);
  EXPECT_NEAR(m->stress(), 7.0, 1e-12);
  EXPECT_NEAR(m->tangent(), 1000.0, 1e-9);
  // Then towards C = (rDispN*eNd1, rForceN*eNf1) = (-0.0048, -3.6), which lies
  // outside the K0 line through D = (-0.012, -12); C is pulled onto it: (-0.0036, -3.6).
  step(*m, 0.0);
  const double slopeBC = (-3.6 + 1.9) / (-0.0036 - 0.0311);
  EXPECT_NEAR(m->tangent(), slopeBC, 1e-9);
  EXPECT_NEAR(m->stress(), -1.9 + slopeBC * (0.0 - 0.0311), 1e-12);
  step(*m, -0.008);  // on C-D, the K0 line
  EXPECT_NEAR(m->stress(), -8.0, 1e-12);
  walk(*m, current = -0.008, -0.05);
  EXPECT_NEAR(m->stress(), -16.0 - 3.0 / 0.035 * 0.015, 1e-12);
  // Back: K0 to uForceP*ePf3 = 0.9, then to C = (0.5*0.05, 0.25*17) and D = (0.05, 17).
  const double fmin = m->stress();
  const double bStrain = -0.05 + (0.9 - fmin) / 1000.0;
  step(*m, 0.0);
  EXPECT_NEAR(m->stress(), 0.9 + (4.25 - 0.9) / (0.025 - bStrain) * (0.0 - bStrain), 1e-12);
  step(*m, 0.04);
  EXPECT_NEAR(m->stress(), 4.25 + (17.0 - 4.25) / 0.025 * 0.015, 1e-12);
  step(*m, 0.055);  // the envelope again
  EXPECT_NEAR(m->stress(), 17.5, 1e-12);
}

TEST(Pinching4Material, UnloadingStiffnessDegradesWithDeformationDemand) {
  Domain d;
  // gK1 = 0.5, gK3 = 1: after a cycle to +-0.03, Ku = 1000*(1 - 0.5*0.03/0.12)
  // (0.12 = the larger |d4|), as the documented k_i = k0*(1 - dk_i).
  std::vector<double> g = noDamage();
  g[0] = 0.5;
  g[2] = 1.0;
  g[4] = 0.9;
  auto m = build(d, "Pinching4", pinching(1, g));
  double current = 0.0;
  walk(*m, current, 0.03);
  walk(*m, current, -0.03);
  walk(*m, current, 0.03);
  step(*m, 0.0299);
  EXPECT_NEAR(m->tangent(), 875.0, 1e-6);
  EXPECT_NEAR(m->stress(), 15.0 - 875.0 * 1e-4, 1e-9);
}

TEST(Pinching4Material, SymmetricFormMirrorsThePositiveSide) {
  Domain d;
  const std::vector<double> path{0.02, -0.015, 0.04, 0.01, 0.03, -0.05, -0.02, 0.07, -0.08, 0.0, 0.09};
  auto sym = build(d, "Pinching4", args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, 18.0, 0.06, 12.0, 0.1, 0.5,
                                        0.25, 0.05, 0.3, 0.2, 1.2, 1.1, 0.9, 0.4, 0.3, 1.0, 0.9, 0.8, 0.2, 0.2, 1.1,
                                        1.3, 0.7, 10.0, "cycle"));
  auto full = build(d, "Pinching4",
                    args("uniaxialMaterial", 2, 10.0, 0.01, 15.0, 0.03, 18.0, 0.06, 12.0, 0.1, -10.0, -0.01, -15.0,
                         -0.03, -18.0, -0.06, -12.0, -0.1, 0.5, 0.25, 0.05, 0.5, 0.25, 0.05, 0.3, 0.2, 1.2, 1.1, 0.9,
                         0.4, 0.3, 1.0, 0.9, 0.8, 0.2, 0.2, 1.1, 1.3, 0.7, 10.0, "cycle"));
  double a = 0.0, b = 0.0;
  for (double target : path) {
    walk(*sym, a, target, 7e-4);
    walk(*full, b, target, 7e-4);
    EXPECT_EQ(sym->stress(), full->stress()) << target;
    EXPECT_EQ(sym->tangent(), full->tangent()) << target;
  }
}

TEST(Pinching4Material, TangentAndRevert) {
  Domain d;
  for (const char* type : {"energy", "cycle"}) {
    const std::vector<double> g{0.3, 0.2, 1.2, 1.1, 0.9, 0.4, 0.3, 1.0, 0.9, 0.8, 0.2, 0.2, 1.1, 1.3, 0.7};
    auto m = build(d, "Pinching4", pinching(1, g, type));
    expectTangentMatchesFiniteDifference(*m, {0.02, -0.015, 0.04, 0.01, 0.03, -0.05, -0.02, 0.07, -0.08, 0.0, 0.11},
                                         0.0013, 1e-8, 1000.0);
    auto r = build(d, "Pinching4", pinching(2, g, type));
    expectRevertRestoresExactly(*r, {0.02, 0.004, -0.015, 0.001, 0.04, 0.012, -0.05, 0.0, 0.07, -0.09}, 0.03);
  }
}

TEST(Pinching4Material, InputErrors) {
  Domain d;
  auto err = [&](CommandArgs a) { return testsupport::errorOf([&] { build(d, "Pinching4", std::move(a)); }); };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, "energy")).find("28 or 39 arguments"),
            std::string::npos);
  std::vector<double> g = noDamage();
  CommandArgs bad = pinching(1, g, "plastic");
  EXPECT_NE(err(bad).find("dmgType must be 'cycle' or 'energy'"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.03, 15.0, 0.01, 18.0, 0.06, 12.0, 0.1, 0.5, 0.25, 0.05, 0.0, 0.0,
                     0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 10.0, "energy"))
                .find("ePd2 must be positive and beyond"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, 18.0, 0.06, 12.0, 0.1, 12.0, -0.012, -16.0, -0.035,
                     -19.0, -0.07, -8.0, -0.12, 0.5, 0.25, 0.05, 0.4, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                     0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 10.0, "energy"))
                .find("eNf1 must be negative"),
            std::string::npos);
  EXPECT_NE(err(pinching(1, noDamage(), "energy", 1.0)).find("rDispP must lie in [0, 1)"), std::string::npos);
  g[4] = 1.0;
  EXPECT_NE(err(pinching(1, g)).find("gKLim must be below 1"), std::string::npos);
  g = noDamage();
  g[6] = -0.1;
  EXPECT_NE(err(pinching(1, g)).find("gD2 must not be negative"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 10.0, 0.01, 15.0, 0.03, 18.0, 0.06, 12.0, 0.1, 0.5, 0.25, 0.05, 0.0, 0.1,
                     0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, "energy"))
                .find("gE must be positive"),
            std::string::npos);
  // Every message names the command and the material.
  EXPECT_NE(err(bad).find("uniaxialMaterial Pinching4 1"), std::string::npos);
}
