#include "materials/uniaxial/HystereticMaterial.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

HystereticMaterial::HystereticMaterial(int tag, std::vector<Point> positive, std::vector<Point> negative,
                                       double pinchX, double pinchY, double damage1, double damage2, double beta)
    : UniaxialMaterial(tag), pinchX_(pinchX), pinchY_(pinchY), damage1_(damage1), damage2_(damage2), beta_(beta) {
  for (Point& p : negative) p = {-p.strain, -p.stress};
  side_[0].points = std::move(positive);
  side_[1].points = std::move(negative);
  for (Side& s : side_) {
    s.E1 = s.points[0].stress / s.points[0].strain;
    // Area under the envelope up to its last point.
    double previousStrain = 0.0, previousStress = 0.0;
    for (const Point& p : s.points) {
      energyUlt_ += 0.5 * (previousStress + p.stress) * (p.strain - previousStrain);
      previousStrain = p.strain;
      previousStress = p.stress;
    }
  }
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> HystereticMaterial::clone() const {
  return std::make_unique<HystereticMaterial>(*this);
}

void HystereticMaterial::revertToStart() {
  committed_ = State{};
  committed_.tangent = side_[0].E1;
  trial_ = committed_;
}

void HystereticMaterial::envelope(int side, double strain, double& stress, double& tangent) const {
  const std::vector<Point>& pts = side_[side].points;
  double previousStrain = 0.0, previousStress = 0.0;
  for (const Point& p : pts) {
    if (strain <= p.strain) {
      tangent = (p.stress - previousStress) / (p.strain - previousStrain);
      stress = previousStress + tangent * (strain - previousStrain);
      return;
    }
    previousStrain = p.strain;
    previousStress = p.stress;
  }
  // Past the last point: the last slope if it rises, else a plateau.
  const Point& a = pts[pts.size() - 2];
  const Point& b = pts.back();
  const double slope = (b.stress - a.stress) / (b.strain - a.strain);
  if (slope > 0.0) {
    tangent = slope;
    stress = b.stress + slope * (strain - b.strain);
  } else {
    tangent = 1.0e-9 * side_[side].E1;
    stress = b.stress;
  }
}

double HystereticMaterial::unloadingStiffness(int side, double extreme) const {
  const Side& s = side_[side];
  const double mu = std::max(extreme / s.points[0].strain, 1.0);
  return s.E1 * std::pow(mu, -beta_);
}

void HystereticMaterial::hysteretic(int side, const State& c, State& t) const {
  // Everything in the frame of `side` (the side moved towards): strains and
  // stresses of the negative side are negated.
  const int other = 1 - side;
  const double sign = side == 0 ? 1.0 : -1.0;
  const double strain = sign * t.strain;
  const double committedStrain = sign * c.strain;
  const double committedStress = sign * c.stress;
  const double increment = strain - committedStrain;
  // Unloading stiffnesses from the committed extremes.
  const double kAhead = unloadingStiffness(side, c.extreme[side]);
  const double kBehind = unloadingStiffness(other, c.extreme[other]);

  // A reversal with the stress still on the side left: damage the extreme
  // strain ahead and remember where the unloading branch reaches zero.
  if (c.direction == -static_cast<int>(sign) && committedStress < 0.0) {
    const double mu = std::max(c.extreme[other] / side_[other].points[0].strain, 1.0);
    const double dissipated = c.energy - 0.5 * c.stress * c.stress / kBehind;
    const double damage = damage1_ * (mu - 1.0) + damage2_ * dissipated / energyUlt_;
    t.extreme[side] = c.extreme[side] * (1.0 + damage);
    t.zeroStrain[side] = committedStrain - committedStress / kBehind;
  }
  t.extreme[0] = std::max(t.extreme[0], side_[0].points[0].strain);
  t.extreme[1] = std::max(t.extreme[1], side_[1].points[0].strain);

  double stress, tangent;
  const double unloaded = committedStress + kBehind * increment;
  if (committedStress < 0.0 && unloaded <= 0.0) {
    // Still unloading from the other side.
    stress = unloaded;
    tangent = kBehind;
  } else {
    // Reloading towards the target through the pinch point.
    const double targetStrain = t.extreme[side];
    double targetStress, unused;
    envelope(side, targetStrain, targetStress, unused);
    const double zero = t.zeroStrain[side];
    const double pinchStress = pinchY_ * targetStress;
    const double pinchRef = targetStrain - (1.0 - pinchY_) * targetStress / kAhead;
    const double pinchStrain = zero + pinchX_ * (pinchRef - zero);
    double path;
    if (strain <= pinchStrain && pinchStrain != zero) {
      tangent = pinchStress / (pinchStrain - zero);
      path = tangent * (strain - zero);
    } else {
      tangent = (targetStress - pinchStress) / (targetStrain - pinchStrain);
      path = pinchStress + tangent * (strain - pinchStrain);
    }
    const double elastic = committedStress + kAhead * increment;
    if (elastic <= path) {
      stress = elastic;
      tangent = kAhead;
    } else {
      stress = path;
    }
  }
  t.stress = sign * stress;
  t.tangent = tangent;
}

void HystereticMaterial::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  const double increment = strain - c.strain;
  // A change below machine epsilon is no change (as OpenSees, found by running it): the
  // committed state, strain and tangent stay, so round-off in a fiber's strain cannot pick a
  // branch, nor can such changes add up.
  if (std::fabs(increment) < std::numeric_limits<double>::epsilon()) return;
  State& t = trial_;
  t.strain = strain;
  t.direction = increment > 0.0 ? 1 : -1;
  if (strain >= c.extreme[0]) {
    t.extreme[0] = strain;
    envelope(0, strain, t.stress, t.tangent);
  } else if (-strain >= c.extreme[1]) {
    t.extreme[1] = -strain;
    envelope(1, -strain, t.stress, t.tangent);
    t.stress = -t.stress;
  } else {
    hysteretic(increment > 0.0 ? 0 : 1, c, t);
  }
  t.energy = c.energy + 0.5 * (c.stress + t.stress) * increment;
}

void HystereticMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Hysteretic";
  for (int s = 0; s < 2; ++s) {
    os << (s == 0 ? " positive" : " negative");
    for (const Point& p : side_[s].points)
      os << " (" << (s == 0 ? p.strain : -p.strain) << ", " << (s == 0 ? p.stress : -p.stress) << ')';
  }
  os << " pinchX " << pinchX_ << " pinchY " << pinchY_ << " damage1 " << damage1_ << " damage2 " << damage2_
     << " beta " << beta_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildHysteretic(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Hysteretic " + std::to_string(tag));
  // 12 or 13 numbers with two points per side, 16 or 17 with three.
  const std::size_t n = args.remaining();
  if (n != 12 && n != 13 && n != 16 && n != 17)
    args.fail("expected s1p e1p s2p e2p <s3p e3p> s1n e1n s2n e2n <s3n e3n> pinchX pinchY damage1 damage2 <beta>: "
              "12, 13, 16 or 17 numbers after the tag, got " + std::to_string(n));
  const int points = n >= 16 ? 3 : 2;
  static const char* names[2][3][2] = {{{"s1p", "e1p"}, {"s2p", "e2p"}, {"s3p", "e3p"}},
                                       {{"s1n", "e1n"}, {"s2n", "e2n"}, {"s3n", "e3n"}}};
  std::vector<HystereticMaterial::Point> sides[2];
  for (int s = 0; s < 2; ++s)
    for (int i = 0; i < points; ++i) {
      const double stress = args.nextDouble(names[s][i][0]);
      const double strain = args.nextDouble(names[s][i][1]);
      sides[s].push_back({strain, stress});
    }
  const double pinchX = args.nextDouble("pinchX");
  const double pinchY = args.nextDouble("pinchY");
  const double damage1 = args.nextDouble("damage1");
  const double damage2 = args.nextDouble("damage2");
  const double beta = args.done() ? 0.0 : args.nextDouble("beta");
  args.expectEnd();
  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? 1.0 : -1.0;
    double previous = 0.0;
    for (int i = 0; i < points; ++i) {
      const double e = sign * sides[s][i].strain;
      if (!(e > previous))
        args.fail(std::string(names[s][i][1]) + " must be " + (s == 0 ? "positive" : "negative") +
                  " and beyond the point before it, got " + std::to_string(sides[s][i].strain));
      previous = e;
    }
    if (!(sign * sides[s][0].stress > 0.0))
      args.fail(std::string(names[s][0][0]) + " must be " + (s == 0 ? "positive" : "negative") + ", got " +
                std::to_string(sides[s][0].stress));
  }
  if (!(damage1 >= 0.0 && damage2 >= 0.0)) args.fail("damage1 and damage2 must not be negative");
  return std::make_unique<HystereticMaterial>(tag, std::move(sides[0]), std::move(sides[1]), pinchX, pinchY,
                                              damage1, damage2, beta);
}

void registerHysteretic(Registry& r) { r.uniaxialMaterials.add("Hysteretic", &buildHysteretic); }

}  // namespace

BEAMSOLID_REGISTER(registerHysteretic);

}  // namespace beamsolid
