// PySimple1, TzSimple1, QzSimple1: closed forms of the components (far field,
// near field, closure, drag) on the backbone and after reversals, the
// soil-type constants, the gap memory, the dashpot, tangents against finite
// differences, revert, and input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/OpenSeesError.h"
#include "materials/uniaxial/PySimple1.h"
#include "materials/uniaxial/QzSimple1.h"
#include "materials/uniaxial/TzSimple1.h"
#include "support/ErrorOf.h"
#include "support/UniaxialChecks.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;
using namespace beamsolid::testsupport;
using namespace beamsolid::uniaxialtest;

namespace {

constexpr double kPult = 120.0, kY50 = 0.02;

struct PyBackbone {
  double c, n, Cr, Ce;
};
PyBackbone pyBackbone(int soilType) { return soilType == 1 ? PyBackbone{10, 5, 0.35, 1 / 0.98} : PyBackbone{0.5, 2, 0.2, 0.542}; }

// The closure at rest (y0+- = +-y50/100) and no drag: p = 1.8 pult [1/(1.5 - x) -
// 1/(1.5 + x)], x = 50 yg / y50, inverted: r x^2 + 2x - 2.25 r = 0, r = p / (1.8 pult).
double restingGap(double p) {
  const double r = p / (1.8 * kPult);
  if (r == 0.0) return 0.0;
  return (-1.0 + std::sqrt(1.0 + 2.25 * r * r)) / r * kY50 / 50.0;
}

// Displacement of a virgin PySimple1 (Cd = 0) at force p, while the gap
// memory has not moved (near field + gap below 1.51 y50) and the gap is
// below y0+ (p < 0.9 pult).
double pyVirginDisplacement(int soilType, double p) {
  const PyBackbone b = pyBackbone(soilType);
  const double Kf = b.Ce * kPult / kY50, Kn = 50.0 * kPult / kY50, p0 = b.Cr * kPult;
  const double near = std::abs(p) <= p0 ? p / Kn
                                        : std::copysign(p0 / Kn + b.c * kY50 *
                                                                      (std::pow((kPult - p0) / (kPult - std::abs(p)),
                                                                                1.0 / b.n) - 1.0),
                                                        p);
  return p / Kf + near + restingGap(p);
}

std::unique_ptr<UniaxialMaterial> py(Domain& d, int soilType, double Cd, double c = 0.0) {
  return build(d, "PySimple1", args("uniaxialMaterial", 1, soilType, kPult, kY50, Cd, c));
}

}  // namespace

TEST(PySimple1, InitialTangentIsTheSeriesOfTheComponents) {
  for (int soilType : {1, 2})
    for (double Cd : {0.0, 0.3, 1.0}) {
      Domain d;
      auto m = py(d, soilType, Cd);
      // Far field 1/Ce, near field 0.02 and closure 1/80 plus drag 2 Cd, in y50/pult.
      const double flexibility = (1.0 / pyBackbone(soilType).Ce + 0.02 + 1.0 / (80.0 + 2.0 * Cd)) * kY50 / kPult;
      EXPECT_NEAR(m->initialTangent(), 1.0 / flexibility, 1e-12 / flexibility);
      EXPECT_EQ(m->tangent(), m->initialTangent());
    }
}

TEST(PySimple1, VirginBackboneFollowsTheComponentClosedForms) {
  for (int soilType : {1, 2}) {
    // Rigid (elastic) range up to Cr pult, then plastic; each point from rest.
    const std::vector<double> fractions =
        soilType == 1 ? std::vector<double>{0.05, 0.2, 0.34, 0.4, 0.5, 0.6} : std::vector<double>{0.1, 0.19, 0.3, 0.5, 0.7, 0.85};
    for (double f : fractions)
      for (double sign : {1.0, -1.0}) {
        Domain d;
        auto m = py(d, soilType, 0.0);
        const double p = sign * f * kPult;
        m->setTrialStrain(pyVirginDisplacement(soilType, p));
        EXPECT_NEAR(m->stress(), p, 1e-11 * kPult) << "soilType " << soilType << " p/pult " << sign * f;
      }
  }
}

TEST(PySimple1, ReachesAboutHalfOfPultAtY50) {
  // The backbone constants were fitted to Matlock's and API's curves, not to
  // p(y50) = pult / 2 exactly: 0.4919 pult (clay) and 0.4737 pult (sand), as OpenSees.
  for (int soilType : {1, 2}) {
    Domain d;
    auto m = py(d, soilType, 0.0);
    m->setTrialStrain(kY50);
    EXPECT_NEAR(m->stress(), 0.5 * kPult, 0.03 * kPult) << "soilType " << soilType;
    EXPECT_NEAR(m->stress() / kPult, soilType == 1 ? 0.49192 : 0.47366, 1e-4);
  }
}

TEST(PySimple1, UnloadsThroughTheRigidRangeAndYieldsAtItsMovedBound) {
  for (int soilType : {1, 2}) {
    Domain d;
    auto m = py(d, soilType, 0.0);
    const PyBackbone b = pyBackbone(soilType);
    const double y1 = 0.8 * kY50;
    m->setTrialStrain(y1);
    m->commitState();
    const double p1 = m->stress();
    ASSERT_GT(p1, b.Cr * kPult);
    // Unloading: far field, near field (50 pult/y50) and the resting closure,
    // all elastic: y - y1 = (p - p1) (1/Kf + 1/Kn) + yg(p) - yg(p1).
    const double Kf = b.Ce * kPult / kY50, Kn = 50.0 * kPult / kY50;
    auto elasticY = [&](double p) { return y1 + (p - p1) * (1.0 / Kf + 1.0 / Kn) + restingGap(p) - restingGap(p1); };
    const double lower = std::min(p1 - 2.0 * b.Cr * kPult, -0.25 * kPult);
    for (double p : {p1 - 0.1 * kPult, 0.0, lower + 1e-6 * kPult}) {
      m->setTrialStrain(elasticY(p));
      EXPECT_NEAR(m->stress(), p, 1e-10 * kPult) << "soilType " << soilType;
    }
    // Past the bound: plastic again, a new excursion from the bound:
    // y = y(lower) + (p - lower) / Kf + yg(p) - yg(lower) - c y50 [((pult + lower) / (pult + p))^(1/n) - 1].
    for (double p2 : {lower - 0.05 * kPult, lower - 0.2 * kPult}) {
      const double y2 = elasticY(lower) + (p2 - lower) / Kf + restingGap(p2) - restingGap(lower) -
                        b.c * kY50 * (std::pow((kPult + lower) / (kPult + p2), 1.0 / b.n) - 1.0);
      m->setTrialStrain(y2);
      EXPECT_NEAR(m->stress(), p2, 1e-10 * kPult) << "soilType " << soilType;
    }
  }
}

TEST(PySimple1, GapOpensBehindThePileAndClosesAtTheMemoryTerm) {
  Domain d;
  auto m = py(d, 1, 0.0);
  auto& p = dynamic_cast<PySimple1&>(*m);
  // Push to 6 y50: near field plus gap go past 1.51 y50, which opens the
  // other side: y0- = -(max(yp + yg) - 1.5 y50).
  for (int i = 1; i <= 60; ++i) {
    m->setTrialStrain(i * 0.1 * kY50);
    m->commitState();
  }
  const double reach = p.nearFieldDisplacement() + p.gapDisplacement();
  EXPECT_NEAR(p.gapLeft(), -(reach - 1.5 * kY50), 1e-15);
  EXPECT_NEAR(p.gapRight(), kY50 / 100.0, 1e-18);
  // Back through zero: once the pile leaves the front soil (yg falls), the
  // force in the open gap is the closure alone, a few percent of pult, until
  // yg comes within a few hundredths of y50 of y0- and the back soil takes
  // over (half of pult at yg - y0- = 0.052 y50 by the closure formula).
  double y = 6.0 * kY50, smallest = kPult;
  bool closed = false;
  for (int i = 0; i < 400 && !closed; ++i) {
    y -= 0.025 * kY50;
    m->setTrialStrain(y);
    m->commitState();
    const double g = p.gapDisplacement();
    const double A = 1.8 * kPult;
    const double closure =
        A * (kY50 / (kY50 + 50.0 * (p.gapRight() - g)) - kY50 / (kY50 - 50.0 * (p.gapLeft() - g)));
    if (g > p.gapLeft() && g < p.gapRight()) EXPECT_NEAR(m->stress(), closure, 1e-10 * kPult);
    if (g > p.gapLeft() + 0.2 * kY50 && g < -0.2 * kY50) smallest = std::min(smallest, std::abs(m->stress()));
    closed = m->stress() <= -0.5 * kPult;
    if (closed) EXPECT_LT(g - p.gapLeft(), 0.055 * kY50);
  }
  EXPECT_LT(smallest, 0.02 * kPult);
  EXPECT_TRUE(closed);
}

TEST(PySimple1, DragHoldsCdPultInAnOpenGap) {
  for (double Cd : {0.3, 1.0}) {
    Domain d;
    auto m = py(d, 2, Cd);
    auto& p = dynamic_cast<PySimple1&>(*m);
    for (int i = 1; i <= 100; ++i) {
      m->setTrialStrain(i * 0.1 * kY50);
      m->commitState();
    }
    // Unload far into the gap behind: the closure is small there, the drag
    // mobilises towards -Cd pult along -Cd pult - (-Cd pult - pd0) y50 / (y50 + 2 |dyg|).
    double y = 10.0 * kY50;
    for (int i = 0; i < 140; ++i) {
      y -= 0.05 * kY50;
      m->setTrialStrain(y);
      m->commitState();
    }
    const double g = p.gapDisplacement();
    ASSERT_GT(g, p.gapLeft() + kY50);
    EXPECT_LT(m->stress(), -0.85 * Cd * kPult);
    EXPECT_GT(m->stress(), -1.05 * Cd * kPult);
  }
}

TEST(PySimple1, TangentMatchesFiniteDifferencesWhereOpenSeesDoesNotFloorIt) {
  // Cycles within +-1.2 y50: the gap memory does not move and every component
  // tangent stays above OpenSees' 0.01 pult / y50 floor.
  for (int soilType : {1, 2})
    for (double Cd : {0.0, 0.3}) {
      Domain d;
      auto m = py(d, soilType, Cd);
      expectTangentMatchesFiniteDifference(*m, {0.6 * kY50, -0.4 * kY50, 1.2 * kY50, -1.0 * kY50, 0.3 * kY50},
                                           0.03 * kY50, 1e-7 * kY50, m->initialTangent(), 1e-6);
    }
}

TEST(PySimple1, ReportsTheNearFieldTangentFlooredAt1PercentOfPultOverY50) {
  Domain d;
  auto m = py(d, 1, 0.0);
  for (int i = 1; i <= 300; ++i) {
    m->setTrialStrain(i * 0.1 * kY50);
    m->commitState();
  }
  // At 30 y50 the plastic tangent is ~1e-6 pult / y50; the reported tangent
  // is the series with 0.01 pult / y50 (and the far field and gap): 0.0099.
  EXPECT_NEAR(m->tangent() / (kPult / kY50), 0.0099, 2e-5);
}

TEST(PySimple1, DashpotActsOnTheFarFieldShareAndTheStressIsBounded) {
  Domain d;
  const double c = 40.0;
  auto m = py(d, 1, 0.3, c);
  auto& p = dynamic_cast<PySimple1&>(*m);
  m->setTrialStrain(0.3 * kY50);
  m->commitState();
  const double p1 = p.springForce(), y1 = 0.3 * kY50;
  // Before the commit: the share of the increment that went into the far field.
  const double y2 = 0.5 * kY50, v = 0.7;
  m->setTrialStrain(y2, v);
  const double p2 = p.springForce();
  const double share = (p2 - p1) / (p.farFieldStiffness() * (y2 - y1));
  EXPECT_NEAR(m->stress(), p2 + c * v * share, 1e-12 * kPult);
  EXPECT_NEAR(m->dampingTangent(), c * share, 1e-12 * c);
  // After it (no increment left): the tangent share, as OpenSees reports it.
  m->commitState();
  EXPECT_NEAR(m->stress(), p2 + c * v * m->tangent() / p.farFieldStiffness(), 1e-12 * kPult);
  // A fast pull never takes the force past pult.
  m->setTrialStrain(0.6 * kY50, 1e6);
  EXPECT_DOUBLE_EQ(m->stress(), (1.0 - 1e-12) * kPult);
  m->setTrialStrain(0.6 * kY50, -1e6);
  EXPECT_DOUBLE_EQ(m->stress(), -(1.0 - 1e-12) * kPult);
}

TEST(PySimple1, RevertRestoresTheState) {
  for (double Cd : {0.0, 0.5}) {
    Domain d;
    auto m = py(d, 1, Cd);
    expectRevertRestoresExactly(*m, {0.2 * kY50, 1.5 * kY50, 4.0 * kY50, -2.0 * kY50, -6.0 * kY50, 1.0 * kY50},
                                0.7 * kY50);
  }
}

TEST(PySimple1, BadArgumentsNameTheCommandAndTheArgument) {
  Domain d;
  auto err = [&](CommandArgs a) { return errorOf([&] { build(d, "PySimple1", a); }); };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 3, 100.0, 0.01, 0.3)).find("uniaxialMaterial PySimple1 1: soilType"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, -1.0, 0.01, 0.3)).find("pult"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 100.0, 0.0, 0.3)).find("Y50"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 100.0, 0.01, -0.3)).find("Cd"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 100.0, 0.01, 0.3, -1.0)).find("dashpot"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 100.0, 0.01)).find("Cd"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 100.0, 0.01, 0.3, 0.0, 5.0)).find("PySimple1"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, "clay", 100.0, 0.01, 0.3)).find("soilType"), std::string::npos);
}

namespace {
struct TzBackbone {
  double c, n, Ce;
};
TzBackbone tzBackbone(int t) { return t == 1 ? TzBackbone{0.5, 1.5, 0.70791} : TzBackbone{0.6, 0.85, 2.0504}; }
constexpr double kTult = 35.0, kZ50 = 0.004;
}  // namespace

TEST(TzSimple1, BackboneAndReversalsFollowTheClosedForm) {
  for (int tzType : {1, 2}) {
    const TzBackbone b = tzBackbone(tzType);
    const double Kf = b.Ce * kTult / kZ50;
    // Virgin: z = t / Kf + c z50 [(tult / (tult - t))^(1/n) - 1].
    auto virgin = [&](double t) { return t / Kf + b.c * kZ50 * (std::pow(kTult / (kTult - t), 1.0 / b.n) - 1.0); };
    Domain d;
    auto m = build(d, "TzSimple1", args("uniaxialMaterial", 1, tzType, kTult, kZ50));
    EXPECT_NEAR(m->initialTangent(), 1.0 / (1.0 / Kf + b.c * kZ50 / (b.n * kTult)), 1e-12 * Kf);
    const double t1 = 0.8 * kTult;
    m->setTrialStrain(virgin(t1));
    EXPECT_NEAR(m->stress(), t1, 1e-12 * kTult);
    m->commitState();
    // Reversal: a new plastic excursion at once (no rigid range),
    // z = z1 - (t1 - t) / Kf - c z50 [((tult + t1) / (tult + t))^(1/n) - 1].
    const double z1 = virgin(t1);
    for (double t : {0.5 * kTult, -0.3 * kTult, -0.9 * kTult}) {
      const double z = z1 - (t1 - t) / Kf - b.c * kZ50 * (std::pow((kTult + t1) / (kTult + t), 1.0 / b.n) - 1.0);
      m->setTrialStrain(z);
      EXPECT_NEAR(m->stress(), t, 1e-11 * kTult) << "tzType " << tzType;
    }
    // t = tult / 2 at z50 (Ce rounded to 5 digits by OpenSees: 1e-5).
    Domain d2;
    auto fresh = build(d2, "TzSimple1", args("uniaxialMaterial", 1, tzType, kTult, kZ50));
    fresh->setTrialStrain(kZ50);
    EXPECT_NEAR(fresh->stress(), 0.5 * kTult, 1e-5 * kTult);
  }
}

TEST(TzSimple1, TangentMatchesFiniteDifferencesAndRevertRestores) {
  for (int tzType : {1, 2}) {
    Domain d;
    auto m = build(d, "TzSimple1", args("uniaxialMaterial", 1, tzType, kTult, kZ50));
    expectTangentMatchesFiniteDifference(*m, {2.0 * kZ50, -1.0 * kZ50, 5.0 * kZ50, -4.0 * kZ50}, 0.1 * kZ50,
                                         1e-7 * kZ50, m->initialTangent(), 1e-6);
    Domain d2;
    auto r = build(d2, "TzSimple1", args("uniaxialMaterial", 1, tzType, kTult, kZ50, 3.0));
    expectRevertRestoresExactly(*r, {0.5 * kZ50, 3.0 * kZ50, -2.0 * kZ50, 10.0 * kZ50}, 0.8 * kZ50);
  }
}

TEST(TzSimple1, BadArgumentsNameTheCommandAndTheArgument) {
  Domain d;
  auto err = [&](CommandArgs a) { return errorOf([&] { build(d, "TzSimple1", a); }); };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 0, 10.0, 0.01)).find("uniaxialMaterial TzSimple1 1: tzType"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 0.0, 0.01)).find("tult"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0, -0.01)).find("z50"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0, 0.01, -2.0)).find("dashpot"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0)).find("z50"), std::string::npos);
}

namespace {
struct QzBackbone {
  double c, n, Cr, Ce;
};
QzBackbone qzBackbone(int t) { return t == 1 ? QzBackbone{0.35, 1.2, 0.2, 0.525} : QzBackbone{12.3, 5.5, 0.3, 1.39}; }
constexpr double kQult = 800.0, kZ50q = 0.01;
}  // namespace

TEST(QzSimple1, BearingBackboneFollowsTheComponentClosedForms) {
  for (int qzType : {1, 2}) {
    const QzBackbone b = qzBackbone(qzType);
    const double Kf = b.Ce * kQult / kZ50q, Kn = 1e4 * kQult / kZ50q, kc = 1000.0 * kQult / kZ50q;
    const double q0 = b.Cr * kQult;
    // Bearing is negative: z = -(|q|/Kf + near(|q|) + |q|/kc).
    auto bearing = [&](double a) {
      const double near =
          a <= q0 ? a / Kn : q0 / Kn + b.c * kZ50q * (std::pow((kQult - q0) / (kQult - a), 1.0 / b.n) - 1.0);
      return -(a / Kf + near + a / kc);
    };
    for (double f : {0.1, 0.25, 0.5, 0.9, 0.99}) {
      Domain d;
      auto m = build(d, "QzSimple1", args("uniaxialMaterial", 1, qzType, kQult, kZ50q));
      m->setTrialStrain(bearing(f * kQult));
      EXPECT_NEAR(m->stress(), -f * kQult, 1e-11 * kQult) << "qzType " << qzType << " q/qult " << f;
    }
    // The initial tangent OpenSees reports takes the closure as 100 qult / z50.
    Domain d;
    auto m = build(d, "QzSimple1", args("uniaxialMaterial", 1, qzType, kQult, kZ50q, 0.1, 0.0));
    EXPECT_NEAR(m->initialTangent(), 1.0 / (1.0 / Kf + 1.0 / Kn + kZ50q / (100.2 * kQult)), 1e-12 * Kf);
  }
}

TEST(QzSimple1, UpliftResistanceIsTheSuctionDrag) {
  for (double suction : {0.0, 0.05, 0.1}) {
    Domain d;
    auto m = build(d, "QzSimple1", args("uniaxialMaterial", 1, 1, kQult, kZ50q, suction, 0.0));
    auto& q = dynamic_cast<QzSimple1&>(*m);
    for (int i = 1; i <= 200; ++i) {
      m->setTrialStrain(i * 0.25 * kZ50q);
      m->commitState();
    }
    // The open closure (1e-6 qult / z50) plus a drag towards suction qult:
    // q = kt zg + Cd qult (1 - z50 / (z50 + 2 zg)).
    const double g = q.gapDisplacement();
    const double kt = 1.000002e-6 * kQult / kZ50q;
    EXPECT_NEAR(m->stress(), kt * g + suction * kQult * (1.0 - kZ50q / (kZ50q + 2.0 * g)), 1e-10 * kQult);
    EXPECT_LT(m->stress(), suction * kQult + kt * g);
    if (suction > 0.0) EXPECT_GT(m->stress(), 0.98 * suction * kQult);
  }
}

TEST(QzSimple1, RigidRangeWidensToSevenTenthsOfQult) {
  Domain d;
  auto m = build(d, "QzSimple1", args("uniaxialMaterial", 1, 2, kQult, kZ50q, 0.1, 0.0));
  for (int i = 1; i <= 100; ++i) {
    m->setTrialStrain(-i * 0.2 * kZ50q);
    m->commitState();
  }
  const double q1 = m->stress();
  ASSERT_LT(q1, -0.75 * kQult);
  // Unloading stays elastic (tangent of far field + near field + closure)
  // until q1 + 0.7 qult, then yields: find the bound on a fine path.
  const QzBackbone b = qzBackbone(2);
  const double elastic = 1.0 / (kZ50q / kQult * (1.0 / b.Ce + 1e-4 + 1e-3));
  double z = m->strain(), last = q1;
  for (int i = 0; i < 40000; ++i) {
    z += 5e-5 * kZ50q;
    m->setTrialStrain(z);
    m->commitState();
    if (m->tangent() < 0.9 * elastic) break;
    last = m->stress();
  }
  EXPECT_NEAR(last, q1 + 0.7 * kQult, 1e-4 * kQult);
}

TEST(QzSimple1, TangentMatchesFiniteDifferencesAndRevertRestores) {
  for (int qzType : {1, 2}) {
    Domain d;
    auto m = build(d, "QzSimple1", args("uniaxialMaterial", 1, qzType, kQult, kZ50q, 0.1, 0.0));
    // Bearing cycles that stay closed (the bilinear closure kinks at zg = 0).
    expectTangentMatchesFiniteDifference(*m, {-1.0 * kZ50q, -0.3 * kZ50q, -3.0 * kZ50q, -1.5 * kZ50q},
                                         0.05 * kZ50q, 1e-8 * kZ50q, m->initialTangent(), 1e-6);
    Domain d2;
    auto r = build(d2, "QzSimple1", args("uniaxialMaterial", 1, qzType, kQult, kZ50q, 0.1, 5.0));
    expectRevertRestoresExactly(*r, {-0.5 * kZ50q, -4.0 * kZ50q, 2.0 * kZ50q, -8.0 * kZ50q, 5.0 * kZ50q},
                                0.6 * kZ50q);
  }
}

TEST(QzSimple1, BadArgumentsNameTheCommandAndTheArgument) {
  Domain d;
  auto err = [&](CommandArgs a) { return errorOf([&] { build(d, "QzSimple1", a); }); };
  EXPECT_NE(err(args("uniaxialMaterial", 1, 3, 10.0, 0.01)).find("uniaxialMaterial QzSimple1 1: qzType"),
            std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, -10.0, 0.01)).find("qult"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0, 0.0)).find("Z50"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0, 0.01, 0.3)).find("suction"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0, 0.01, -0.01)).find("suction"), std::string::npos);
  EXPECT_NE(err(args("uniaxialMaterial", 1, 1, 10.0, 0.01, 0.1, -1.0)).find("dashpot"), std::string::npos);
}

TEST(LiquefiableSoilSprings, SayTheyAreNotAvailable) {
  Domain d;
  for (const char* type : {"PyLiq1", "TzLiq1", "QzLiq1"}) {
    const std::string e =
        errorOf([&] { build(d, type, args("uniaxialMaterial", 4, 1, 100.0, 0.01, 0.3, 0.0, 0.1, "-timeSeries", 1)); });
    EXPECT_NE(e.find(std::string("uniaxialMaterial ") + type + " 4"), std::string::npos) << e;
    EXPECT_NE(e.find("not available"), std::string::npos) << e;
  }
}
