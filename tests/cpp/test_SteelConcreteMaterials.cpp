// Steel01, Steel02, Concrete01, Concrete02 and ENT uniaxial materials:
// hand-computed stress points on monotonic and cyclic strain histories,
// finite-difference tangents along cyclic paths, exact restoration by
// revertToLastCommit, energy dissipated over closed cycles, and the
// argument checks of the factories.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "materials/uniaxial/Concrete01.h"
#include "materials/uniaxial/Concrete02.h"
#include "materials/uniaxial/ENTMaterial.h"
#include "materials/uniaxial/Steel01.h"
#include "materials/uniaxial/Steel02.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using beamsolid::solidstest::args;
using beamsolid::uniaxialtest::build;

namespace {

std::unique_ptr<UniaxialMaterial> make(const std::string& type, CommandArgs a) {
  Domain d;
  return Registry::global().uniaxialMaterials.get(type)(a, d);
}

std::string errorOf(const std::string& type, CommandArgs a) {
  try {
    make(type, std::move(a));
  } catch (const OpenSeesError& e) {
    return e.what();
  }
  return "(no error)";
}

// One converged step: trial strain, then commit.
void step(UniaxialMaterial& m, double strain) {
  m.setTrialStrain(strain);
  m.commitState();
}

// Piecewise-linear strain history through the turning points (starting
// from zero), in increments no larger than `increment`.
std::vector<double> history(const std::vector<double>& turningPoints, double increment) {
  std::vector<double> path;
  double from = 0.0;
  for (double to : turningPoints) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(to - from) / increment)));
    for (int i = 1; i <= n; ++i) path.push_back(from + (to - from) * i / n);
    from = to;
  }
  return path;
}

struct TangentCheck {
  int checked = 0;
  int kinks = 0;
  double worst = 0.0;  // largest |central difference - tangent|
};

// Walks the path committing every point; at each point the tangent of the
// trial state is compared with the central difference of stress over
// strain +- h from the same committed state. Points where the forward and
// backward differences disagree by more than kinkTolerance straddle a kink
// (yield point, crack closure, ...) and are skipped.
TangentCheck checkTangents(UniaxialMaterial& m, const std::vector<double>& path, double h, double kinkTolerance) {
  TangentCheck result;
  for (double strain : path) {
    m.setTrialStrain(strain);
    const double stress = m.stress(), tangent = m.tangent();
    m.setTrialStrain(strain + h);
    const double plus = m.stress();
    m.setTrialStrain(strain - h);
    const double minus = m.stress();
    const double forward = (plus - stress) / h, backward = (stress - minus) / h;
    if (std::abs(forward - backward) > kinkTolerance) {
      ++result.kinks;
    } else {
      ++result.checked;
      result.worst = std::max(result.worst, std::abs((plus - minus) / (2.0 * h) - tangent));
    }
    step(m, strain);
  }
  return result;
}

// Work done on the material along the path, integral of stress d(strain)
// by the trapezoidal rule (steps committed).
double work(UniaxialMaterial& m, const std::vector<double>& path) {
  double w = 0.0, strain = m.strain(), stress = m.stress();
  for (double next : path) {
    step(m, next);
    w += 0.5 * (stress + m.stress()) * (next - strain);
    strain = next;
    stress = m.stress();
  }
  return w;
}

// Steel used throughout: Fy = 400, E0 = 200000, b = 0.01 (yield strain 0.002).
constexpr double fy = 400.0, E0 = 200000.0, b = 0.01, ey = fy / E0;
// Concrete: fpc = -30, epsc0 = -0.002, fpcu = -6, epsU = -0.006, Ec = 30000.
constexpr double fpc = -30.0, epsc0 = -0.002, fpcu = -6.0, epsU = -0.006, Ec = 2.0 * fpc / epsc0;

double kentPark(double e) {
  if (e > epsc0) return fpc * (2.0 * e / epsc0 - (e / epsc0) * (e / epsc0));
  if (e > epsU) return fpc + (fpcu - fpc) / (epsU - epsc0) * (e - epsc0);
  return fpcu;
}

}  // namespace

// ---------------------------------------------------------------- Steel01

TEST(Steel01, MonotonicYieldPointAndHardeningSlope) {
  auto m = make("Steel01", args("uniaxialMaterial", 1, fy, E0, b));
  EXPECT_DOUBLE_EQ(m->initialTangent(), E0);
  m->setTrialStrain(0.5 * ey);
  EXPECT_NEAR(m->stress(), 200.0, 1e-9);
  EXPECT_DOUBLE_EQ(m->tangent(), E0);
  m->setTrialStrain(ey);  // exactly at yield: still elastic
  EXPECT_NEAR(m->stress(), fy, 1e-9);
  EXPECT_DOUBLE_EQ(m->tangent(), E0);
  for (double e : {1.5 * ey, 4.0 * ey, 20.0 * ey}) {
    m->setTrialStrain(e);
    EXPECT_NEAR(m->stress(), fy + b * E0 * (e - ey), 1e-9) << "strain " << e;
    EXPECT_DOUBLE_EQ(m->tangent(), b * E0);
  }
  m->setTrialStrain(-3.0 * ey);  // same from the virgin state in compression
  EXPECT_NEAR(m->stress(), -fy - b * E0 * 2.0 * ey, 1e-9);
}

TEST(Steel01, CyclicHistoryFollowsTheKinematicYieldLines) {
  auto m = make("Steel01", args("uniaxialMaterial", 1, fy, E0, b));
  // Yield lines b*E0*e +- (1-b)*Fy; elastic moves with E0. Worked by hand.
  const double upper5 = b * E0 * 5 * ey + (1 - b) * fy;  // 416
  struct Point { double strain, stress, tangent; };
  const Point history[] = {
      {5 * ey, upper5, b * E0},                                   // tension yield line
      {4 * ey, upper5 - E0 * ey, E0},                             // elastic unloading: 16
      {2 * ey, b * E0 * 2 * ey - (1 - b) * fy, b * E0},          // predictor 416-1200 < lower line: -388
      {-3 * ey, b * E0 * -3 * ey - (1 - b) * fy, b * E0},        // -408 on the compression line
      {-2 * ey, b * E0 * -3 * ey - (1 - b) * fy + E0 * ey, E0},  // elastic reloading: -8
      {6 * ey, b * E0 * 6 * ey + (1 - b) * fy, b * E0},          // back on the tension line: 420
  };
  for (const Point& p : history) {
    m->setTrialStrain(p.strain);
    EXPECT_NEAR(m->stress(), p.stress, 1e-9) << "strain " << p.strain;
    EXPECT_DOUBLE_EQ(m->tangent(), p.tangent) << "strain " << p.strain;
    m->commitState();
  }
}

TEST(Steel01, IsotropicHardeningGrowsTheYieldLines) {
  // a1 = 0.1, a2 = 1: after a reversal from tension the compression line
  // grows by 0.1*((maxStrain - minStrain)/(2*Fy/E0))^0.8 of Fy; a3 = a4 = 0
  // leave the tension line alone. The growth acts from the step after the
  // reversal, so the path is walked in small steps.
  auto m = make("Steel01", args("uniaxialMaterial", 1, fy, E0, b, 0.1, 1.0, 0.0, 1.0));
  auto* s = dynamic_cast<Steel01*>(m.get());
  ASSERT_NE(s, nullptr);
  for (double e : history({3 * ey, -10 * ey}, 0.05 * ey)) step(*m, e);
  const double growth = 0.1 * std::pow(3.0 / 2.0, 0.8);
  EXPECT_NEAR(s->compressionGrowth(), growth, 1e-12);
  EXPECT_NEAR(m->stress(), b * E0 * -10 * ey - (1 - b) * fy * (1 + growth), 1e-9);
  EXPECT_DOUBLE_EQ(m->tangent(), b * E0);
  // Back to tension: tension line unchanged (a3 = 0).
  for (double e : history({30 * ey}, 0.05 * ey)) step(*m, e - 10 * ey);
  EXPECT_DOUBLE_EQ(s->tensionGrowth(), 0.0);
  EXPECT_NEAR(m->stress(), b * E0 * 20 * ey + (1 - b) * fy, 1e-9);

  // a3 = 0.2, a4 = 0.5 grow the tension line after a compression excursion
  // to -4 ey: range 4 ey over 2*0.5*ey gives 0.2*4^0.8.
  auto t = make("Steel01", args("uniaxialMaterial", 2, fy, E0, b, 0.0, 1.0, 0.2, 0.5));
  for (double e : history({-4 * ey, 12 * ey}, 0.05 * ey)) step(*t, e);
  const double tensionGrowth = 0.2 * std::pow(4.0, 0.8);
  EXPECT_NEAR(dynamic_cast<Steel01&>(*t).tensionGrowth(), tensionGrowth, 1e-12);
  EXPECT_NEAR(t->stress(), b * E0 * 12 * ey + (1 - b) * fy * (1 + tensionGrowth), 1e-9);
}

TEST(Steel01, DissipationOverAStabilizedCycleIsTheParallelogramArea) {
  // Kinematic bilinear loop between +-ea: a parallelogram of area
  // 4*Fy*(1-b)*(ea - ey). Trapezoidal work on 0.001 ey steps.
  auto m = make("Steel01", args("uniaxialMaterial", 1, fy, E0, b));
  const double ea = 5 * ey;
  for (double e : history({ea}, 0.01 * ey)) step(*m, e);
  std::vector<double> cycle = history({-2 * ea, 0.0}, 0.001 * ey);
  for (double& e : cycle) e += ea;  // ea -> -ea -> ea
  const double w = work(*m, cycle);
  EXPECT_NEAR(w, 4 * fy * (1 - b) * (ea - ey), 1e-6 * w);
  EXPECT_GT(w, 0.0);
}

// ---------------------------------------------------------------- Steel02

TEST(Steel02, FirstBranchIsTheMenegottoPintoCurve) {
  // R0 = 20: s*/Fy = b e* + (1-b) e* / (1 + e*^R)^(1/R) with e* = e/ey.
  auto m = make("Steel02", args("uniaxialMaterial", 1, fy, E0, b, 20.0, 0.925, 0.15));
  auto mp = [](double x) { return fy * (b * x + (1 - b) * x / std::pow(1 + std::pow(x, 20.0), 1.0 / 20.0)); };
  for (double x : {0.2, 0.9, 1.0, 1.3, 3.0, 10.0}) {
    m->setTrialStrain(x * ey);
    EXPECT_NEAR(m->stress(), mp(x), 1e-9 * fy) << "e/ey " << x;
  }
  // At the asymptote intersection (ey, Fy) the curve is Fy*(b + (1-b)/2^(1/R)) ...
  m->setTrialStrain(ey);
  EXPECT_NEAR(m->stress(), fy * (b + (1 - b) * std::pow(2.0, -1.0 / 20.0)), 1e-9 * fy);
  // ... it starts with slope E0 and ends on the hardening asymptote.
  m->setTrialStrain(1e-3 * ey);
  EXPECT_NEAR(m->tangent(), E0, 1e-9 * E0);
  m->setTrialStrain(30 * ey);
  EXPECT_NEAR(m->tangent(), b * E0, 1e-6 * E0);
  EXPECT_NEAR(m->stress(), fy + b * E0 * 29 * ey, 1e-9 * fy);
}

TEST(Steel02, BauschingerBranchThroughTheAsymptoteIntersection) {
  // Load to 5 ey, reverse. The new branch starts at the reversal point
  // (eR, sR); the elastic line sR + E0 (e - eR) meets the compression
  // asymptote b E0 e - (1-b) Fy at (e0, s0), and R = R0 (1 - cR1 xi/(cR2 + xi))
  // with xi = |minStrain - e0|/ey, minStrain = -ey for a virgin compression side.
  const double R0 = 18.0, cR1 = 0.925, cR2 = 0.15;
  auto m = make("Steel02", args("uniaxialMaterial", 1, fy, E0, b, R0, cR1, cR2));
  auto* s = dynamic_cast<Steel02*>(m.get());
  ASSERT_NE(s, nullptr);
  for (double e : history({5 * ey}, 0.1 * ey)) step(*m, e);
  const double eR = 5 * ey, sR = m->stress();
  const double e0 = (-(1 - b) * fy - sR + E0 * eR) / (E0 * (1 - b));
  const double s0 = b * E0 * e0 - (1 - b) * fy;
  const double xi = std::abs(-ey - e0) / ey;
  const double R = R0 * (1 - cR1 * xi / (cR2 + xi));

  m->setTrialStrain(e0);
  EXPECT_NEAR(s->asymptoteStrain(), e0, 1e-15);
  EXPECT_NEAR(s->asymptoteStress(), s0, 1e-9);
  EXPECT_NEAR(s->curvature(), R, 1e-12);
  // At e* = 1 the curve sits at s* = b + (1-b)/2^(1/R) between the lines.
  EXPECT_NEAR(m->stress(), sR + (s0 - sR) * (b + (1 - b) * std::pow(2.0, -1.0 / R)), 1e-9);
  // Heading into compression the curve stays above both the elastic line and the asymptote.
  for (double e = eR - 0.1 * ey; e > -8 * ey; e -= 0.25 * ey) {
    m->setTrialStrain(e);
    const double elastic = sR + E0 * (e - eR), asymptote = b * E0 * e - (1 - b) * fy;
    EXPECT_GE(m->stress(), elastic - 1e-9) << e;
    EXPECT_GE(m->stress(), asymptote - 1e-9) << e;
  }
  // A larger excursion gives a rounder curve (smaller R, stress farther from s0 at e0).
  auto big = make("Steel02", args("uniaxialMaterial", 2, fy, E0, b, R0, cR1, cR2));
  for (double e : history({15 * ey}, 0.1 * ey)) step(*big, e);
  big->setTrialStrain(14 * ey);
  EXPECT_LT(dynamic_cast<Steel02&>(*big).curvature(), R);
}

TEST(Steel02, IsotropicHardeningShiftsTheAsymptote) {
  // a1 = 0.1, a2 = 1: a reversal towards compression after reaching 3 ey
  // grows the compression asymptote by 0.1*((3 ey - (-ey))/(2 ey))^0.8 of Fy
  // (the virgin extremes are +-ey).
  auto m = make("Steel02", args("uniaxialMaterial", 1, fy, E0, b, 20.0, 0.925, 0.15, 0.1, 1.0, 0.0, 1.0));
  auto* s = dynamic_cast<Steel02*>(m.get());
  for (double e : history({3 * ey}, 0.1 * ey)) step(*m, e);
  const double eR = m->strain(), sR = m->stress();
  const double growth = 0.1 * std::pow(2.0, 0.8);
  const double offset = -(1 - b) * fy * (1 + growth);
  const double e0 = (offset - sR + E0 * eR) / (E0 * (1 - b));
  m->setTrialStrain(2 * ey);
  EXPECT_NEAR(s->asymptoteStrain(), e0, 1e-15);
  EXPECT_NEAR(s->asymptoteStress(), b * E0 * e0 + offset, 1e-9);
  // Far along the branch the stress closes on the shifted asymptote, below the unshifted one.
  m->setTrialStrain(-60 * ey);
  EXPECT_NEAR(m->stress(), b * E0 * -60 * ey + offset, 1e-3 * fy);
  EXPECT_LT(m->stress(), b * E0 * -60 * ey - (1 - b) * fy - 0.9 * growth * fy);
}

TEST(Steel02, DefaultsAndInitialStress) {
  auto m = make("Steel02", args("uniaxialMaterial", 1, fy, E0, b));
  m->setTrialStrain(0.5 * ey);
  EXPECT_DOUBLE_EQ(dynamic_cast<Steel02&>(*m).curvature(), 15.0);  // R0 default
  // sigInit = 100: stress 100 at zero strain, the curve shifted by 100/E0.
  auto p = make("Steel02", args("uniaxialMaterial", 2, fy, E0, b, 20.0, 0.925, 0.15, 0.0, 1.0, 0.0, 1.0, 100.0));
  EXPECT_DOUBLE_EQ(p->stress(), 100.0);
  EXPECT_DOUBLE_EQ(p->strain(), 0.0);
  p->setTrialStrain(0.0);
  EXPECT_DOUBLE_EQ(p->stress(), 100.0);
  p->setTrialStrain(0.1 * ey);  // internal strain 0.35 ey: (1 + 0.35^20)^(-1/20) = 1 - 4e-11
  EXPECT_NEAR(p->stress(), 100.0 + 0.1 * fy, 1e-5 * fy);
  p->setTrialStrain(10 * ey);
  EXPECT_NEAR(p->stress(), fy + b * E0 * (10 * ey + 100.0 / E0 - ey), 1e-6 * fy);
}

// ---------------------------------------------------------------- Concrete01

TEST(Concrete01, EnvelopeCrushingAtEpsc0AndResidualStrength) {
  auto m = make("Concrete01", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU));
  EXPECT_DOUBLE_EQ(m->initialTangent(), 30000.0);
  struct Point { double strain, stress, tangent; };
  // Hognestad parabola to (-0.002, -30), line to (-0.006, -6), then -6.
  const Point monotonic[] = {
      {-0.0005, -13.125, 22500.0}, {-0.001, -22.5, 15000.0}, {-0.0019, -29.925, 1500.0},
      {-0.003, -24.0, -6000.0},    {-0.005, -12.0, -6000.0}, {-0.008, -6.0, 0.0},
  };
  for (const Point& p : monotonic) {
    m->setTrialStrain(p.strain);
    EXPECT_NEAR(m->stress(), p.stress, 1e-9) << p.strain;
    EXPECT_NEAR(m->tangent(), p.tangent, 1e-6) << p.strain;
    m->commitState();
  }
  // Peak: the parabola reaches fpc with zero slope at epsc0.
  auto peak = make("Concrete01", args("uniaxialMaterial", 2, fpc, epsc0, fpcu, epsU));
  peak->setTrialStrain(epsc0 * (1 - 1e-9));
  EXPECT_NEAR(peak->stress(), fpc, 1e-9);
  EXPECT_NEAR(peak->tangent(), 0.0, 1e-3);
  // No tension.
  auto t = make("Concrete01", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, epsU));
  t->setTrialStrain(0.001);
  EXPECT_EQ(t->stress(), 0.0);
  EXPECT_EQ(t->tangent(), 0.0);
}

TEST(Concrete01, KarsanJirsaUnloadingAndReloading) {
  auto m = make("Concrete01", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU));
  // From -0.003 (r = 1.5, sigma -24): epsP = -0.002*(0.145*2.25 + 0.13*1.5) = -0.0010425,
  // unloading slope 24/(0.003 - 0.0010425).
  step(*m, -0.003);
  const double slope = 24.0 / (0.003 - 0.0010425);
  step(*m, -0.002);
  EXPECT_NEAR(m->stress(), -24.0 + slope * 0.001, 1e-9);
  EXPECT_NEAR(m->tangent(), slope, 1e-6);
  step(*m, -0.0005);  // past epsP: open, no stress
  EXPECT_EQ(m->stress(), 0.0);
  EXPECT_EQ(m->tangent(), 0.0);
  step(*m, 0.001);
  EXPECT_EQ(m->stress(), 0.0);
  step(*m, -0.0025);  // reloading on the same line
  EXPECT_NEAR(m->stress(), -24.0 + slope * 0.0005, 1e-9);
  step(*m, -0.0035);  // through the old envelope point onto the envelope
  EXPECT_NEAR(m->stress(), kentPark(-0.0035), 1e-9);
  EXPECT_NEAR(m->tangent(), -6000.0, 1e-6);

  // r = 2.5 uses the second branch: epsP = -0.002*(0.707*0.5 + 0.834) = -0.002375.
  auto f = make("Concrete01", args("uniaxialMaterial", 2, fpc, epsc0, fpcu, epsU));
  step(*f, -0.005);
  f->setTrialStrain(-0.004);
  EXPECT_NEAR(f->tangent(), 12.0 / (0.005 - 0.002375), 1e-6);
  // Beyond epsU the plastic strain stays at its value for r = 3: -0.003082.
  auto g = make("Concrete01", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, epsU));
  step(*g, -0.01);
  g->setTrialStrain(-0.009);
  EXPECT_NEAR(g->tangent(), 6.0 / (0.01 - 0.003082), 1e-6);
  EXPECT_NEAR(g->stress(), -6.0 + 6.0 / (0.01 - 0.003082) * 0.001, 1e-9);
  // Small r: the Karsan-Jirsa slope would exceed Ec, so it is capped at Ec.
  auto h = make("Concrete01", args("uniaxialMaterial", 4, fpc, epsc0, fpcu, epsU));
  step(*h, -0.0005);
  h->setTrialStrain(-0.0004);
  EXPECT_DOUBLE_EQ(h->tangent(), Ec);
  EXPECT_NEAR(h->stress(), -13.125 + Ec * 0.0001, 1e-9);
}

TEST(Concrete01, PositiveInputMeansCompression) {
  auto neg = make("Concrete01", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU));
  auto pos = make("Concrete01", args("uniaxialMaterial", 2, 30.0, 0.002, 6.0, 0.006));
  for (double e : history({-0.004, -0.001, -0.007, 0.001}, 2e-4)) {
    step(*neg, e);
    step(*pos, e);
    EXPECT_EQ(neg->stress(), pos->stress());
  }
}

// ---------------------------------------------------------------- Concrete02

TEST(Concrete02, TensionCutOffAndLinearSoftening) {
  // ft = 3 reached at ft/Ec = 1e-4, then slope -Ets = -1500 to zero at 0.0021.
  auto m = make("Concrete02", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU, 0.1, 3.0, 1500.0));
  struct Point { double strain, stress, tangent; };
  const Point monotonic[] = {
      {5e-5, 1.5, Ec}, {1e-4, 3.0, Ec}, {0.001, 3.0 - 1500.0 * 0.0009, -1500.0}, {0.002, 0.15, -1500.0}, {0.003, 0.0, 0.0},
  };
  for (const Point& p : monotonic) {
    m->setTrialStrain(p.strain);
    EXPECT_NEAR(m->stress(), p.stress, 1e-9) << p.strain;
    EXPECT_NEAR(m->tangent(), p.tangent, 1e-6) << p.strain;
    m->commitState();
  }
  // Unloading from the softening branch aims at the crack-closing point (0, 0).
  auto u = make("Concrete02", args("uniaxialMaterial", 2, fpc, epsc0, fpcu, epsU, 0.1, 3.0, 1500.0));
  step(*u, 0.001);
  u->setTrialStrain(0.0005);
  EXPECT_NEAR(u->tangent(), 1.65 / 0.001, 1e-6);
  EXPECT_NEAR(u->stress(), 1.65 * 0.5, 1e-9);
}

TEST(Concrete02, CompressionEnvelopeMatchesConcrete01) {
  auto m = make("Concrete02", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU, 0.1, 3.0, 1500.0));
  for (double e : {-0.0005, -0.001, -0.002, -0.003, -0.0055, -0.009}) {
    step(*m, e);
    EXPECT_NEAR(m->stress(), kentPark(e), 1e-9) << e;
  }
}

TEST(Concrete02, YassinUnloadingReloadingThroughTheFocalPoint) {
  const double lambda = 0.1;
  auto m = make("Concrete02", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU, lambda, 3.0, 1500.0));
  auto* c = dynamic_cast<Concrete02*>(m.get());
  ASSERT_NE(c, nullptr);
  // Focal point: Ec*e meets the line through (epsU, fpcu) of slope lambda*Ec.
  const double epsR = (fpcu - lambda * Ec * epsU) / (Ec * (1 - lambda)), sigR = Ec * epsR;
  double slope, crack;
  c->reloadingLine(epsU, slope, crack);
  EXPECT_NEAR(slope, lambda * Ec, 1e-9);  // lambda: unloading slope at epsU over Ec

  // Envelope point (-0.003, -24): Er through the focal point, zero at epsT.
  step(*m, -0.003);
  const double Er = (-24.0 - sigR) / (-0.003 - epsR), epsT = -0.003 + 24.0 / Er;
  c->reloadingLine(-0.003, slope, crack);
  EXPECT_NEAR(slope, Er, 1e-9);
  EXPECT_NEAR(crack, epsT, 1e-15);
  // Unloading starts with Ec ...
  step(*m, -0.0029);
  EXPECT_NEAR(m->stress(), -24.0 + Ec * 0.0001, 1e-9);
  EXPECT_DOUBLE_EQ(m->tangent(), Ec);
  // ... until it meets the unloading line 0.5*Er*(e - epsT).
  step(*m, -0.002);
  EXPECT_NEAR(m->stress(), 0.5 * Er * (-0.002 - epsT), 1e-9);
  EXPECT_NEAR(m->tangent(), 0.5 * Er, 1e-9);
  // Reloading: Ec until the reloading line -24 + Er*(e + 0.003), then on it.
  step(*m, -0.00205);
  EXPECT_NEAR(m->stress(), 0.5 * Er * (-0.002 - epsT) - Ec * 0.00005, 1e-9);
  EXPECT_DOUBLE_EQ(m->tangent(), Ec);
  step(*m, -0.0025);
  EXPECT_NEAR(m->stress(), -24.0 + Er * 0.0005, 1e-9);
  EXPECT_NEAR(m->tangent(), Er, 1e-9);
  // Past the envelope point the envelope takes over again.
  step(*m, -0.0035);
  EXPECT_NEAR(m->stress(), kentPark(-0.0035), 1e-9);

  // Tension after compression: the tension envelope starts at the new epsT.
  c->reloadingLine(-0.0035, slope, crack);
  step(*m, crack - 1e-6);
  step(*m, crack + 5e-5);
  EXPECT_NEAR(m->stress(), Ec * 5e-5, 1e-9);
  step(*m, crack + 1e-3);
  EXPECT_NEAR(m->stress(), 3.0 - 1500.0 * (1e-3 - 1e-4), 1e-9);
}

TEST(Concrete02, DefaultsOfTheTensionParameters) {
  // lambda = 0.1, ft = 0.1*|fpc| = 3, Ets = 0.1*|fpc/epsc0| = 1500.
  auto d = make("Concrete02", args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU));
  auto e = make("Concrete02", args("uniaxialMaterial", 2, fpc, epsc0, fpcu, epsU, 0.1, 3.0, 1500.0));
  for (double s : history({0.001, -0.004, -0.001, 0.002, -0.007}, 1e-4)) {
    step(*d, s);
    step(*e, s);
    EXPECT_NEAR(d->stress(), e->stress(), 1e-12 * 30.0) << s;  // 0.1*30 need not be exactly 3
  }
}

// ---------------------------------------------------------------- ENT

TEST(ENTMaterial, ElasticInCompressionNothingInTension) {
  auto m = make("ENT", args("uniaxialMaterial", 1, 1000.0));
  step(*m, -0.01);
  EXPECT_DOUBLE_EQ(m->stress(), -10.0);
  EXPECT_DOUBLE_EQ(m->tangent(), 1000.0);
  step(*m, 0.02);
  EXPECT_EQ(m->stress(), 0.0);
  EXPECT_EQ(m->tangent(), 0.0);
  step(*m, -0.005);
  EXPECT_DOUBLE_EQ(m->stress(), -5.0);
  step(*m, 0.0);
  EXPECT_EQ(m->stress(), 0.0);
  EXPECT_DOUBLE_EQ(m->tangent(), 1000.0);
  EXPECT_DOUBLE_EQ(m->initialTangent(), 1000.0);
}

// ---------------------------------------------------------------- all materials

namespace {

struct Case {
  std::string type;
  CommandArgs (*arguments)();
  std::vector<double> cycle;  // turning points of a cyclic strain history
  double increment;           // step along it
  int loopTurn;               // closed cycle cycle[0] -> cycle[loopTurn] -> cycle[0]
  double h;                   // finite-difference step
  double modulus;             // scale of the tangents
};

std::vector<Case> allCases() {
  return {
      {"Steel01", [] { return args("uniaxialMaterial", 1, fy, E0, b); },
       {4.3 * ey, -3.7 * ey, 2.1 * ey, -0.4 * ey, 6.2 * ey, -7.9 * ey}, 0.13 * ey, 1, 1e-8, E0},
      {"Steel01", [] { return args("uniaxialMaterial", 1, fy, E0, b, 0.05, 1.5, 0.08, 2.0); },
       {4.3 * ey, -3.7 * ey, 2.1 * ey, -0.4 * ey, 6.2 * ey, -7.9 * ey}, 0.13 * ey, 1, 1e-8, E0},
      {"Steel02", [] { return args("uniaxialMaterial", 1, fy, E0, b, 18.0, 0.925, 0.15); },
       {4.3 * ey, -3.7 * ey, 2.1 * ey, -0.4 * ey, 6.2 * ey, -7.9 * ey}, 0.13 * ey, 1, 1e-8, E0},
      {"Steel02",
       [] { return args("uniaxialMaterial", 1, fy, E0, b, 20.0, 0.9, 0.1, 0.04, 2.0, 0.03, 1.0, 50.0); },
       {4.3 * ey, -3.7 * ey, 2.1 * ey, -0.4 * ey, 6.2 * ey, -7.9 * ey}, 0.13 * ey, 1, 1e-8, E0},
      {"Concrete01", [] { return args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU); },
       {-0.0013, 0.0004, -0.0027, -0.0011, -0.0046, 0.0007, -0.0081}, 1.3e-4, 2, 1e-9, Ec},
      {"Concrete02", [] { return args("uniaxialMaterial", 1, fpc, epsc0, fpcu, epsU, 0.1, 3.0, 1500.0); },
       {0.00033, -0.0013, 0.0004, -0.0027, -0.0011, -0.0046, 0.0017, -0.0081}, 0.7e-4, 1, 1e-9, Ec},
      {"ENT", [] { return args("uniaxialMaterial", 1, 1000.0); }, {-0.013, 0.007, -0.021, 0.004}, 1.1e-3, 1, 1e-8, 1000.0},
  };
}

}  // namespace

TEST(SteelConcreteMaterials, FiniteDifferenceTangentsAlongCyclicPaths) {
  // Central differences +-h from the committed state. For the piecewise
  // linear laws they are exact up to round-off; the Menegotto-Pinto curve
  // adds h^2 f'''/6, far below the tolerance 1e-6 * modulus. Kinks inside
  // +-h are recognised by one-sided differences disagreeing by more than
  // 1e-3 * modulus, and skipped; they must stay a small minority.
  for (const Case& c : allCases()) {
    auto m = make(c.type, c.arguments());
    const std::vector<double> path = history(c.cycle, c.increment);
    const TangentCheck r = checkTangents(*m, path, c.h, 1e-3 * c.modulus);
    EXPECT_LE(r.worst, 1e-6 * c.modulus) << c.type;
    EXPECT_GT(r.checked, 9 * r.kinks) << c.type << ": " << r.kinks << " kinks of " << path.size();
  }
}

TEST(SteelConcreteMaterials, RevertToLastCommitRestoresTheStateExactly) {
  for (const Case& c : allCases()) {
    auto m = make(c.type, c.arguments());
    const std::vector<double> path = history(c.cycle, c.increment);
    const std::size_t half = path.size() / 2;
    for (std::size_t i = 0; i < half; ++i) step(*m, path[i]);
    auto reference = m->clone();  // the committed state, untouched from here on
    const double strain = m->strain(), stress = m->stress(), tangent = m->tangent();
    // Trials that would load, reverse and crack, none committed.
    for (double trial : {strain + 5 * c.increment, strain - 40 * c.increment, strain + 40 * c.increment})
      m->setTrialStrain(trial);
    m->revertToLastCommit();
    EXPECT_EQ(m->strain(), strain) << c.type;
    EXPECT_EQ(m->stress(), stress) << c.type;
    EXPECT_EQ(m->tangent(), tangent) << c.type;
    // The rest of the history is bit-for-bit that of the untouched copy.
    for (std::size_t i = half; i < path.size(); ++i) {
      step(*m, path[i]);
      step(*reference, path[i]);
      ASSERT_EQ(m->stress(), reference->stress()) << c.type << " step " << i;
      ASSERT_EQ(m->tangent(), reference->tangent()) << c.type << " step " << i;
    }
    // revertToStart gives back the virgin material.
    m->revertToStart();
    auto fresh = make(c.type, c.arguments());
    for (double e : path) {
      step(*m, e);
      step(*fresh, e);
      ASSERT_EQ(m->stress(), fresh->stress()) << c.type;
    }
  }
}

TEST(SteelConcreteMaterials, DissipationOverClosedCyclesIsPositive) {
  // After the first loading, a closed strain cycle back to the same strain
  // must dissipate energy (positive work) for the hysteretic laws; the
  // elastic ENT returns it all (zero to round-off).
  for (const Case& c : allCases()) {
    auto m = make(c.type, c.arguments());
    const double start = c.cycle[0];
    for (double e : history({start}, c.increment)) step(*m, e);
    std::vector<double> loop = history({c.cycle[c.loopTurn] - start, 0.0}, 0.05 * c.increment);
    for (double& e : loop) e += start;
    const double w = work(*m, loop);
    const double scale = std::abs(m->initialTangent()) * start * start;
    if (c.type == "ENT") {
      EXPECT_NEAR(w, 0.0, 1e-12 * scale);
    } else {
      EXPECT_GT(w, 1e-3 * scale) << c.type;
    }
  }
}

TEST(SteelConcreteMaterials, RegisteredAndCloneable) {
  for (const Case& c : allCases()) {
    auto m = make(c.type, c.arguments());
    EXPECT_EQ(m->className(), c.type);
    step(*m, c.cycle[0]);
    auto copy = m->clone();
    copy->setTrialStrain(c.cycle[1]);
    EXPECT_EQ(m->strain(), c.cycle[0]) << c.type;  // the original is untouched
  }
}

TEST(SteelConcreteMaterials, BadParametersNameCommandAndArgument) {
  struct Bad { std::string type; CommandArgs a; std::string expected; };
  std::vector<Bad> cases;
  cases.push_back({"Steel01", args("uniaxialMaterial", 3, -400.0, E0, b), "Fy must be positive"});
  cases.push_back({"Steel01", args("uniaxialMaterial", 3, fy, 0.0, b), "E0 must be positive"});
  cases.push_back({"Steel01", args("uniaxialMaterial", 3, fy, E0, 1.0), "b must lie in"});
  cases.push_back({"Steel01", args("uniaxialMaterial", 3, fy, E0, b, 0.1), "all four of a1, a2, a3, a4"});
  cases.push_back({"Steel01", args("uniaxialMaterial", 3, fy, E0, b, 0.1, 0.0, 0.0, 1.0), "a2 and a4 must be positive"});
  cases.push_back({"Steel01", args("uniaxialMaterial", 3, fy, E0), "(b)"});
  cases.push_back({"Steel02", args("uniaxialMaterial", 3, fy, -E0, b), "E0 must be positive"});
  cases.push_back({"Steel02", args("uniaxialMaterial", 3, fy, E0, b, 18.0), "<R0 cR1 cR2>"});
  cases.push_back({"Steel02", args("uniaxialMaterial", 3, fy, E0, b, 18.0, 0.925, 0.15, 0.1), "got 4 optional"});
  cases.push_back({"Steel02", args("uniaxialMaterial", 3, fy, E0, b, 18.0, 1.2, 0.15), "cR1 must lie in"});
  cases.push_back({"Steel02", args("uniaxialMaterial", 3, fy, E0, b, -1.0, 0.925, 0.15), "R0 must be positive"});
  cases.push_back({"Concrete01", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, -0.001), "|epsU| must exceed |epsc0|"});
  cases.push_back({"Concrete01", args("uniaxialMaterial", 3, 0.0, epsc0, fpcu, epsU), "fpc must be nonzero"});
  cases.push_back({"Concrete01", args("uniaxialMaterial", 3, fpc, epsc0, -40.0, epsU), "|fpcu| must not exceed |fpc|"});
  cases.push_back({"Concrete02", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, epsU, 1.0, 3.0, 1500.0), "lambda must lie in"});
  cases.push_back({"Concrete02", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, epsU, 0.1, -3.0, 1500.0), "ft must not be negative"});
  cases.push_back({"Concrete02", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, epsU, 0.1, 3.0), "come together"});
  cases.push_back({"Concrete02", args("uniaxialMaterial", 3, fpc, epsc0, fpcu, epsU, 0.1, 3.0, 1500.0, 25000.0), "come together"});
  cases.push_back({"ENT", args("uniaxialMaterial", 3, -5.0), "E must be positive"});
  cases.push_back({"ENT", args("uniaxialMaterial", 3, 5.0, 1.0), "unexpected extra argument"});
  for (Bad& bad : cases) {
    const std::string msg = errorOf(bad.type, std::move(bad.a));
    EXPECT_NE(msg.find("uniaxialMaterial " + bad.type + " 3"), std::string::npos) << msg;
    EXPECT_NE(msg.find(bad.expected), std::string::npos) << bad.type << ": " << msg;
  }
}

// Steel01's sensitivities (direct differentiation) on a cyclic strain path with isotropic
// hardening (reversals grow the yield lines): at every step d stress / d theta against central
// differences of the whole path run with theta +- h, for Fy, E0, b and a1..a4.
TEST(Steel01, StressSensitivityMatchesFiniteDifferencesOfThePath) {
  std::vector<double> path;
  for (int i = 1; i <= 60; ++i) path.push_back(0.04 * std::sin(0.25 * i) * (1.0 + 0.02 * i) + 0.0005 * i);
  auto make = [](const std::vector<double>& v) {
    Domain d;
    return build(d, "Steel01", args("uniaxialMaterial", 1, v[0], v[1], v[2], v[3], v[4], v[5], v[6]));
  };
  beamsolid::uniaxialtest::expectSensitivitiesMatchFiniteDifferences(
      make, {2.0, 200.0, 0.05, 0.4, 1.5, 0.3, 2.0}, {"Fy", "E0", "b", "a1", "a2", "a3", "a4"}, path, 1e-6);
}
