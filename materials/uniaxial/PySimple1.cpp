#include "materials/uniaxial/PySimple1.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/CommandArgs.h"
#include "core/Registry.h"
#include "materials/uniaxial/IncreasingRoot.h"
#include "materials/uniaxial/SoilDashpot.h"

namespace beamsolid {

namespace {
// Backbone constants per soil type (Boulanger et al. 1999; OpenSees manual):
// c, n, Cr of the near field and Ce = Kf y50 / pult of the far field. The
// far-field constants were read off OpenSees' initial tangents and dashpot
// forces (1/Ce = 0.98 and 1/0.542 y50/pult; docs/pile_springs.md).
struct Backbone {
  double c, n, Cr, Ce;
};
Backbone backbone(int soilType) {
  return soilType == 1 ? Backbone{10.0, 5.0, 0.35, 1.0 / 0.98} : Backbone{0.5, 2.0, 0.2, 0.542};
}
constexpr double kNearFieldElastic = 50.0;  // near-field stiffness in the rigid range, pult / y50
constexpr double kTangentFloor = 0.01;  // smallest component tangent reported, pult / y50
}  // namespace

PySimple1::PySimple1(int tag, int soilType, double pult, double y50, double Cd, double c)
    : UniaxialMaterial(tag), soilType_(soilType), pult_(pult), y50_(y50), Cd_(Cd), dashpot_(c) {
  const Backbone b = backbone(soilType);
  farStiffness_ = b.Ce * pult / y50;
  nearField_ = SoilNearField(pult, b.c * y50, b.n, b.Cr, kNearFieldElastic * pult / y50,
                             SoilNearField::Range::PySimple1);
  drag_ = SoilDrag(Cd * pult, y50);
  // At rest the closure tangent is 80 pult / y50 and the drag's 2 Cd pult / y50.
  initialTangent_ = 1.0 / (1.0 / farStiffness_ + y50 / (kNearFieldElastic * pult) + y50 / ((80.0 + 2.0 * Cd) * pult));
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> PySimple1::clone() const { return std::make_unique<PySimple1>(*this); }

void PySimple1::revertToStart() {
  nearField_.revertToStart();
  drag_.revertToStart();
  committed_ = State{};
  committed_.closeRight = y50_ / 100.0;
  committed_.closeLeft = -y50_ / 100.0;
  committed_.tangent = initialTangent_;
  trial_ = committed_;
}

double PySimple1::closure(double b, double right, double left) const {
  return 1.8 * pult_ * (y50_ / (y50_ + 50.0 * (right - b)) - y50_ / (y50_ - 50.0 * (left - b)));
}

double PySimple1::closureTangent(double b, double right, double left) const {
  const double r = y50_ + 50.0 * (right - b), l = y50_ - 50.0 * (left - b);
  return 1.8 * pult_ * 50.0 * y50_ * (1.0 / (r * r) + 1.0 / (l * l));
}

PySimple1::GapForce PySimple1::gapForce(double gap, double nearDisplacement) const {
  // The memory terms follow the trial: plastic plus gap displacement beyond
  // 1.5 y50 on one side opens the other side.
  const double reach = nearDisplacement + gap;
  const double right = std::max(committed_.closeRight, -1.5 * y50_ - reach);
  const double left = std::min(committed_.closeLeft, 1.5 * y50_ - reach);
  const double b = std::clamp(gap, left, right);
  const SoilDrag::Cycle cycle = drag_.cycle(b);
  const double kClosure = closureTangent(b, right, left), kDrag = drag_.tangent(b, cycle);
  const double k = kClosure + kDrag;
  return {closure(b, right, left) + drag_.force(b, cycle) + k * (gap - b), k, kClosure, kDrag, b, right, left, cycle};
}

double PySimple1::gapAt(double p, double nearDisplacement, double guess) const {
  // The gap force increases with the gap without bound (linear beyond the
  // memory terms): walk out from the guess to a bracket, then solve.
  auto f = [&](double g) {
    const GapForce gf = gapForce(g, nearDisplacement);
    return std::pair{gf.force - p, gf.slope};
  };
  auto [value, slope] = f(guess);
  if (value == 0.0) return guess;
  double step = std::max(std::abs(value) / slope, 1e-12 * y50_);
  double lo = guess, hi = guess;
  if (value < 0.0) {
    for (hi = guess + step; f(hi).first < 0.0; step *= 2.0) {
      lo = hi;
      hi += step;
    }
  } else {
    for (lo = guess - step; f(lo).first > 0.0; step *= 2.0) {
      hi = lo;
      lo -= step;
    }
  }
  return increasingRoot(f, lo, hi, guess - value / slope);
}

double PySimple1::seriesTangent(double nearTangent, const GapForce& gap) const {
  // As OpenSees reports it: the near-field, closure and drag tangents are
  // each kept above 0.01 pult / y50 (a drag with Cd = 0 stays out).
  const double floor = kTangentFloor * pult_ / y50_;
  const double gapTangent = std::max(gap.closureTangent, floor) + (Cd_ > 0.0 ? std::max(gap.dragTangent, floor) : 0.0);
  return 1.0 / (1.0 / farStiffness_ + 1.0 / std::max(nearTangent, floor) + 1.0 / gapTangent);
}

void PySimple1::setTrialStrain(double y, double rate) {
  if (y == committed_.y) {
    // No movement: the committed state, with its tangent re-evaluated there.
    nearField_.setTrialToCommitted();
    drag_.setTrialToCommitted();
    trial_ = committed_;
    trial_.rate = rate;
    const GapForce gf = gapForce(committed_.gap, nearField_.committed().y);
    trial_.tangent = seriesTangent(nearField_.tangent(), gf);
    return;
  }
  // The common force p of the three components: y(p) = p / Kf + yp(p) + yg(p)
  // increases from -infinity to +infinity on (-pult, pult).
  double gapGuess = committed_.gap;
  auto displacement = [&](double p) {
    const SoilNearField::Trial near = nearField_.at(p);
    const double g = gapAt(p, near.y, gapGuess);
    gapGuess = g;
    const double gapSlope = gapForce(g, near.y).slope;
    return std::pair{p / farStiffness_ + near.y + g - y,
                     1.0 / farStiffness_ + nearField_.flexibility(p, near) + 1.0 / gapSlope};
  };
  const double guess = committed_.p + (y - committed_.y) * committed_.tangent;
  const double p = increasingRoot(displacement, -pult_, pult_, guess);

  nearField_.setTrial(p);
  const double nearY = nearField_.trial().y;
  const double g = gapAt(p, nearY, gapGuess);
  const GapForce gf = gapForce(g, nearY);
  drag_.setTrial(gf.clipped);
  trial_.y = y;
  trial_.rate = rate;
  trial_.p = p;
  trial_.gap = g;
  trial_.closeRight = gf.closeRight;
  trial_.closeLeft = gf.closeLeft;
  trial_.tangent = seriesTangent(nearField_.tangent(), gf);
}

double PySimple1::farFieldShare() const {
  return soildashpot::farFieldShare(trial_.y, committed_.y, trial_.p, committed_.p, trial_.tangent, farStiffness_);
}

double PySimple1::stress() const {
  return soildashpot::stress(trial_.p, dashpot_, farFieldShare(), trial_.rate, pult_);
}


void PySimple1::commitState() {
  committed_ = trial_;
  nearField_.commit();
  drag_.commit();
}

void PySimple1::revertToLastCommit() {
  trial_ = committed_;
  nearField_.revert();
  drag_.revert();
}

void PySimple1::print(std::ostream& os) const {
  os << "PySimple1 tag: " << tag() << " soilType: " << soilType_ << " pult: " << pult_ << " y50: " << y50_
     << " Cd: " << Cd_ << " c: " << dashpot_ << "\n";
}

namespace {

std::unique_ptr<UniaxialMaterial> buildPySimple1(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial PySimple1 " + std::to_string(tag));
  const int soilType = args.nextInt("soilType");
  const double pult = args.nextDouble("pult");
  const double y50 = args.nextDouble("Y50");
  const double Cd = args.nextDouble("Cd");
  const double c = args.done() ? 0.0 : args.nextDouble("c");
  args.expectEnd();
  if (soilType != 1 && soilType != 2)
    args.fail("soilType must be 1 (Matlock soft clay) or 2 (API sand), got " + std::to_string(soilType));
  if (!(pult > 0.0)) args.fail("pult must be positive, got " + std::to_string(pult));
  if (!(y50 > 0.0)) args.fail("Y50 must be positive, got " + std::to_string(y50));
  if (!(Cd >= 0.0)) args.fail("Cd must not be negative, got " + std::to_string(Cd));
  if (!(c >= 0.0)) args.fail("c (dashpot) must not be negative, got " + std::to_string(c));
  return std::make_unique<PySimple1>(tag, soilType, pult, y50, Cd, c);
}

void registerPySimple1(Registry& r) { r.uniaxialMaterials.add("PySimple1", &buildPySimple1); }

}  // namespace

BEAMSOLID_REGISTER(registerPySimple1);

}  // namespace beamsolid
