#include "materials/uniaxial/Pinching4Material.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

// The envelope's extra first point lies at this fraction of the larger |d1|,
// on the line of Kmax (found by running OpenSees).
constexpr double kFirstPoint = 1e-4;
constexpr double kReversalTolerance = 1e-12;

}  // namespace

Pinching4Material::Pinching4Material(int tag, const Side& positive, const Side& negative,
                                     const Degradation& stiffness, const Degradation& deformation,
                                     const Degradation& strength, double gE, bool cycleDamage)
    : UniaxialMaterial(tag), side_{positive, negative}, gK_(stiffness), gD_(deformation), gF_(strength), gE_(gE),
      cycleDamage_(cycleDamage) {
  k0p_ = positive.stress[0] / positive.strain[0];
  k0n_ = negative.stress[0] / negative.strain[0];
  kmax_ = std::max(k0p_, k0n_);
  failureStrain_ = std::max(std::fabs(positive.strain[3]), std::fabs(negative.strain[3]));
  firstPoint_ = kFirstPoint * std::max(positive.strain[0], -negative.strain[0]);
  // Area under each monotonic envelope up to its fourth point.
  double area[2];
  for (int s = 0; s < 2; ++s) {
    const Side& side = side_[s];
    const double first = s == 0 ? firstPoint_ : -firstPoint_;
    double x[6] = {0.0, first, side.strain[0], side.strain[1], side.strain[2], side.strain[3]};
    double f[6] = {0.0, kmax_ * first, side.stress[0], side.stress[1], side.stress[2], side.stress[3]};
    area[s] = 0.0;
    for (int i = 0; i < 5; ++i) area[s] += 0.5 * (f[i] + f[i + 1]) * (x[i + 1] - x[i]);
  }
  energyMono_ = gE_ * std::max(std::fabs(area[0]), std::fabs(area[1]));
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Pinching4Material::clone() const {
  return std::make_unique<Pinching4Material>(*this);
}

void Pinching4Material::revertToStart() {
  committed_ = State{};
  committed_.tangent = kmax_;
  committed_.maxStrain = side_[0].strain[0];
  committed_.minStrain = side_[1].strain[0];
  committed_.damageMax = side_[0].strain[0];
  committed_.damageMin = -side_[1].strain[0];
  committed_.targetMax = committed_.damageMax;
  committed_.targetMin = committed_.damageMin;
  trial_ = committed_;
}

void Pinching4Material::envelope(double strain, double dF, double& stress, double& slope) const {
  const Side& s = strain >= 0.0 ? side_[0] : side_[1];
  const double first = strain >= 0.0 ? firstPoint_ : -firstPoint_;
  const double x[6] = {0.0, first, s.strain[0], s.strain[1], s.strain[2], s.strain[3]};
  const double scale = 1.0 - dF;
  const double f[6] = {0.0, kmax_ * first * scale, s.stress[0] * scale, s.stress[1] * scale, s.stress[2] * scale,
                       s.stress[3] * scale};
  for (int i = 0; i < 5; ++i)
    if (std::fabs(strain) <= std::fabs(x[i + 1])) {
      slope = (f[i + 1] - f[i]) / (x[i + 1] - x[i]);
      stress = f[i] + slope * (strain - x[i]);
      return;
    }
  // Past the fourth point: a rising last branch continues, anything else
  // creeps towards 1.1*f4 at 1e6*d4.
  slope = (f[5] - f[4]) / (x[5] - x[4]);
  if (!(slope > 0.0)) slope = 0.1 * f[5] / (1e6 * x[5] - x[5]);
  stress = f[5] + slope * (strain - x[5]);
}

double Pinching4Material::envelopeStress(double strain, double dF) const {
  double stress, slope;
  envelope(strain, dF, stress, slope);
  return stress;
}

double Pinching4Material::unloadingStiffness(const State& s, bool positiveSide) const {
  return (positiveSide ? k0p_ : k0n_) * (1.0 - s.dK);
}

void Pinching4Material::updateDamage(const State& c, State& t) const {
  const double extreme = std::max(c.damageMax, c.damageMin);
  const double deformation = extreme / failureStrain_;
  double demand;
  if (cycleDamage_) {
    t.cycles = c.cycles + std::fabs(c.strain - c.lastReversal) / (4 * extreme);
    t.lastReversal = c.strain;
    demand = t.cycles;
  } else {
    // The dissipated energy can dip just below zero on a virgin path whose
    // first point lies on the steeper side's line; it counts as none.
    demand = energyMono_ > 0.0 ? std::max(c.dissipated / energyMono_, 0.0) : 0.0;
  }
  auto index = [&](const Degradation& g) {
    const double energyTerm = g.g2 == 0.0 ? 0.0 : g.g2 * std::pow(demand, g.g4);
    return std::min(g.g1 * std::pow(deformation, g.g3) + energyTerm, g.limit);
  };
  t.dD = index(gD_);
  t.dF = index(gF_);
  // Unloading no softer than the secant to either damage extreme.
  const double secantP = envelopeStress(c.damageMax, c.dF) / c.damageMax;
  const double secantN = envelopeStress(-c.damageMin, c.dF) / (-c.damageMin);
  t.dK = std::min({index(gK_), 1 - secantP / k0p_, 1 - secantN / k0n_});
}

void Pinching4Material::buildPath(State& t, const State& c, bool towardsPositive, bool direct) const {
  const Side& s = side_[towardsPositive ? 0 : 1];
  double target;
  double fB;
  if (towardsPositive) {
    target = t.damageMax * (1 + t.dD);
    t.targetMax = target;
    fB = s.uForce * (t.maxStrain > s.strain[2] ? s.stress[3] : s.stress[2]) * (1 - t.dF);
  } else {
    target = -t.damageMin * (1 + t.dD);
    t.targetMin = -target;
    fB = s.uForce * (t.minStrain < s.strain[2] ? s.stress[3] : s.stress[2]) * (1 - t.dF);
  }
  const Point R{c.strain, c.stress};
  const Point D{target, envelopeStress(target, t.dF)};
  const double kD = unloadingStiffness(t, towardsPositive);
  const double kB = unloadingStiffness(t, !towardsPositive);
  Point C{s.rDisp * D.strain, s.rForce * D.stress};
  if ((D.stress - C.stress) / (D.strain - C.strain) > kD) {
    // When C must move onto the line of slope kD through D and the unloading
    // force lies beyond the reloading one, both go to just either side of
    // their mean first (found by running OpenSees).
    if (towardsPositive ? fB > C.stress : fB < C.stress) {
      const double mean = 0.5 * (fB + C.stress);
      fB = 0.99 * mean;
      C.stress = 1.01 * mean;
    }
    C.strain = D.strain - (D.stress - C.stress) / kD;
  }
  t.path[0] = R;
  if (direct) {
    t.path[1] = D;
    t.pathPoints = 2;
    return;
  }
  int n = 1;
  if (towardsPositive ? R.stress < fB : R.stress > fB) {
    const Point B{R.strain + (fB - R.stress) / kB, fB};
    // B past C drops B; a B-C segment steeper (either way) than both
    // unloading stiffnesses makes the path the straight line R-D; B with a
    // force beyond C's is dropped (all found by running OpenSees).
    const bool pastC = towardsPositive ? B.strain >= C.strain : B.strain <= C.strain;
    if (!pastC) {
      if (std::fabs((C.stress - B.stress) / (C.strain - B.strain)) > std::max(kD, kB)) {
        t.path[1] = D;
        t.pathPoints = 2;
        return;
      }
      const bool beyondC = towardsPositive ? B.stress >= C.stress : B.stress <= C.stress;
      if (!beyondC) t.path[n++] = B;
    }
  }
  t.path[n++] = C;
  t.path[n++] = D;
  t.pathPoints = n;
}

void Pinching4Material::evaluatePath(const State& t, double strain, double& stress, double& slope) {
  for (int i = 0; i + 1 < t.pathPoints; ++i) {
    const Point& a = t.path[i];
    const Point& b = t.path[i + 1];
    const bool inside = b.strain >= a.strain ? strain <= b.strain : strain >= b.strain;
    if (inside || i + 2 == t.pathPoints) {
      slope = (b.stress - a.stress) / (b.strain - a.strain);
      stress = a.stress + slope * (strain - a.strain);
      return;
    }
  }
}

void Pinching4Material::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  State& t = trial_;
  const double step = strain - c.strain;
  if (step == 0.0) return;
  t.strain = strain;
  // A change below 1e-12 cannot reverse the direction (as OpenSees, found by
  // running it): round-off in a fiber strain must not start a new path.
  const int direction = std::fabs(step) < kReversalTolerance && c.direction != 0 ? c.direction : step > 0.0 ? 1 : -1;
  t.direction = direction;
  const bool reversal = c.direction != 0 && direction != c.direction;
  const bool onEnvelope =
      (c.mode == kPositiveEnvelope && direction > 0) || (c.mode == kNegativeEnvelope && direction < 0);
  if (reversal) {
    updateDamage(c, t);
    // Leaving an envelope grows that side's damage extreme.
    if (direction < 0 && c.mode == kPositiveEnvelope)
      t.damageMax = std::max(c.maxStrain, c.damageMax * (1 + t.dD));
    if (direction > 0 && c.mode == kNegativeEnvelope)
      t.damageMin = std::max(-c.minStrain, c.damageMin * (1 + t.dD));
    if (!onEnvelope) {
      const bool towardsPositive = direction > 0;
      // An interior reversal already on the side it heads to goes straight for the target.
      const bool direct = c.mode == kPath && (towardsPositive ? c.strain > 0.0 : c.strain < 0.0);
      buildPath(t, c, towardsPositive, direct);
      t.mode = kPath;
    }
  }
  if ((direction > 0 && strain > t.targetMax) || (direction < 0 && strain < -t.targetMin) || onEnvelope ||
      c.direction == 0) {
    envelope(strain, t.dF, t.stress, t.tangent);
    t.mode = strain > 0.0 ? kPositiveEnvelope : kNegativeEnvelope;
    t.pathPoints = 0;
  } else {
    evaluatePath(t, strain, t.stress, t.tangent);
    // Beyond the historic extreme a path never rises above the envelope.
    double envStress, envSlope;
    envelope(strain, t.dF, envStress, envSlope);
    if ((direction > 0 && strain > c.maxStrain && t.stress > envStress) ||
        (direction < 0 && strain < c.minStrain && t.stress < envStress)) {
      t.stress = envStress;
      t.tangent = envSlope;
      t.mode = strain > 0.0 ? kPositiveEnvelope : kNegativeEnvelope;
      t.pathPoints = 0;
    }
  }
  t.energy = c.energy + 0.5 * (c.stress + t.stress) * step;
  if (-failureStrain_ < strain && strain < failureStrain_)
    t.dissipated = t.energy - 0.5 * (t.stress * t.stress) / unloadingStiffness(t, strain > 0.0);
}

void Pinching4Material::commitState() {
  if (trial_.mode != kPath) {
    trial_.maxStrain = std::max(trial_.maxStrain, trial_.strain);
    trial_.minStrain = std::min(trial_.minStrain, trial_.strain);
  }
  committed_ = trial_;
}

void Pinching4Material::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Pinching4";
  for (int s = 0; s < 2; ++s) {
    os << (s == 0 ? " positive envelope" : " negative envelope");
    for (int i = 0; i < 4; ++i) os << " (" << side_[s].strain[i] << ", " << side_[s].stress[i] << ")";
    os << " rDisp " << side_[s].rDisp << " rForce " << side_[s].rForce << " uForce " << side_[s].uForce;
  }
  os << " gK " << gK_.g1 << ' ' << gK_.g2 << ' ' << gK_.g3 << ' ' << gK_.g4 << ' ' << gK_.limit << " gD " << gD_.g1
     << ' ' << gD_.g2 << ' ' << gD_.g3 << ' ' << gD_.g4 << ' ' << gD_.limit << " gF " << gF_.g1 << ' ' << gF_.g2 << ' '
     << gF_.g3 << ' ' << gF_.g4 << ' ' << gF_.limit << " gE " << gE_ << " dmgType "
     << (cycleDamage_ ? "cycle" : "energy") << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildPinching4(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Pinching4 " + std::to_string(tag));
  // 27 numbers and dmgType for the symmetric form, 38 and dmgType with the
  // negative envelope and reloading ratios given.
  const std::size_t n = args.remaining();
  if (n != 28 && n != 39)
    args.fail("expected ePf1 ePd1 ... ePf4 ePd4 <eNf1 eNd1 ... eNf4 eNd4> rDispP rForceP uForceP "
              "<rDispN rForceN uForceN> gK1 gK2 gK3 gK4 gKLim gD1 gD2 gD3 gD4 gDLim gF1 gF2 gF3 gF4 gFLim gE dmgType: "
              "28 or 39 arguments after the tag, got " + std::to_string(n));
  const bool asymmetric = n == 39;
  static const char* names[2][4][2] = {
      {{"ePf1", "ePd1"}, {"ePf2", "ePd2"}, {"ePf3", "ePd3"}, {"ePf4", "ePd4"}},
      {{"eNf1", "eNd1"}, {"eNf2", "eNd2"}, {"eNf3", "eNd3"}, {"eNf4", "eNd4"}}};
  Pinching4Material::Side sides[2];
  for (int s = 0; s < (asymmetric ? 2 : 1); ++s)
    for (int i = 0; i < 4; ++i) {
      sides[s].stress[i] = args.nextDouble(names[s][i][0]);
      sides[s].strain[i] = args.nextDouble(names[s][i][1]);
    }
  sides[0].rDisp = args.nextDouble("rDispP");
  sides[0].rForce = args.nextDouble("rForceP");
  sides[0].uForce = args.nextDouble("uForceP");
  if (asymmetric) {
    sides[1].rDisp = args.nextDouble("rDispN");
    sides[1].rForce = args.nextDouble("rForceN");
    sides[1].uForce = args.nextDouble("uForceN");
  } else {
    // The symmetric form mirrors the positive envelope and ratios.
    for (int i = 0; i < 4; ++i) {
      sides[1].stress[i] = -sides[0].stress[i];
      sides[1].strain[i] = -sides[0].strain[i];
    }
    sides[1].rDisp = sides[0].rDisp;
    sides[1].rForce = sides[0].rForce;
    sides[1].uForce = sides[0].uForce;
  }
  Pinching4Material::Degradation g[3];
  static const char* gNames[3][5] = {{"gK1", "gK2", "gK3", "gK4", "gKLim"},
                                     {"gD1", "gD2", "gD3", "gD4", "gDLim"},
                                     {"gF1", "gF2", "gF3", "gF4", "gFLim"}};
  for (int k = 0; k < 3; ++k) {
    g[k].g1 = args.nextDouble(gNames[k][0]);
    g[k].g2 = args.nextDouble(gNames[k][1]);
    g[k].g3 = args.nextDouble(gNames[k][2]);
    g[k].g4 = args.nextDouble(gNames[k][3]);
    g[k].limit = args.nextDouble(gNames[k][4]);
  }
  const double gE = args.nextDouble("gE");
  const std::string type = args.nextString("dmgType");
  args.expectEnd();
  if (type != "cycle" && type != "energy") args.fail("dmgType must be 'cycle' or 'energy', got '" + type + "'");

  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? 1.0 : -1.0;
    double previous = 0.0;
    for (int i = 0; i < 4; ++i) {
      const double d = sign * sides[s].strain[i];
      if (!(d > previous) || !std::isfinite(d))
        args.fail(std::string(names[s][i][1]) + " must be " + (s == 0 ? "positive" : "negative") +
                  " and beyond the point before it, got " + std::to_string(sides[s].strain[i]));
      previous = d;
      const double f = sign * sides[s].stress[i];
      if (!(i == 0 ? f > 0.0 : f >= 0.0) || !std::isfinite(f))
        args.fail(std::string(names[s][i][0]) + " must be " + (s == 0 ? "positive" : "negative") +
                  (i == 0 ? "" : " or zero") + ", got " + std::to_string(sides[s].stress[i]));
    }
    const char* sideName = s == 0 ? "P" : "N";
    if (!(sides[s].rDisp >= 0.0 && sides[s].rDisp < 1.0))
      args.fail(std::string("rDisp") + sideName + " must lie in [0, 1), got " + std::to_string(sides[s].rDisp));
    if (!std::isfinite(sides[s].rForce))
      args.fail(std::string("rForce") + sideName + " must be a finite number");
    if (!std::isfinite(sides[s].uForce))
      args.fail(std::string("uForce") + sideName + " must be a finite number");
  }
  for (int k = 0; k < 3; ++k) {
    const double values[5] = {g[k].g1, g[k].g2, g[k].g3, g[k].g4, g[k].limit};
    for (int j = 0; j < 5; ++j)
      if (!(values[j] >= 0.0) || !std::isfinite(values[j]))
        args.fail(std::string(gNames[k][j]) + " must not be negative, got " + std::to_string(values[j]));
  }
  // A full loss of unloading stiffness or strength would leave a zero stiffness to divide by.
  if (!(g[0].limit < 1.0)) args.fail("gKLim must be below 1, got " + std::to_string(g[0].limit));
  if (!(g[2].limit < 1.0)) args.fail("gFLim must be below 1, got " + std::to_string(g[2].limit));
  const bool energyTerms = g[0].g2 != 0.0 || g[1].g2 != 0.0 || g[2].g2 != 0.0;
  if (!(gE >= 0.0) || !std::isfinite(gE)) args.fail("gE must not be negative, got " + std::to_string(gE));
  if (type == "energy" && energyTerms && !(gE > 0.0))
    args.fail("gE must be positive when gK2, gD2 or gF2 is nonzero with dmgType 'energy' (the energy capacity "
              "is gE times the monotonic energy)");
  return std::make_unique<Pinching4Material>(tag, sides[0], sides[1], g[0], g[1], g[2], gE, type == "cycle");
}

void registerPinching4(Registry& r) { r.uniaxialMaterials.add("Pinching4", &buildPinching4); }

}  // namespace

BEAMSOLID_REGISTER(registerPinching4);

}  // namespace beamsolid
