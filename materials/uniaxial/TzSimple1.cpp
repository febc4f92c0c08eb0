#include "materials/uniaxial/TzSimple1.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/CommandArgs.h"
#include "core/Registry.h"
#include "materials/uniaxial/IncreasingRoot.h"
#include "materials/uniaxial/SoilDashpot.h"

namespace beamsolid {

namespace {
struct Backbone {
  double c, n, Ce;
};
// OpenSees' rounded Ce: 0.5 / (1 - c (2^(1/n) - 1)) is 0.707915 and 2.050348.
Backbone backbone(int tzType) { return tzType == 1 ? Backbone{0.5, 1.5, 0.70791} : Backbone{0.6, 0.85, 2.0504}; }
constexpr double kNearFieldFloor = 1.0e-4;  // smallest near-field tangent reported, tult / z50
}  // namespace

TzSimple1::TzSimple1(int tag, int tzType, double tult, double z50, double c)
    : UniaxialMaterial(tag), tzType_(tzType), tult_(tult), z50_(z50), dashpot_(c) {
  const Backbone b = backbone(tzType);
  farStiffness_ = b.Ce * tult / z50;
  nearField_ = SoilNearField(tult, b.c * z50, b.n, 0.0, std::numeric_limits<double>::infinity(),
                             SoilNearField::Range::TzSimple1);
  initialTangent_ = 1.0 / (1.0 / farStiffness_ + b.c * z50 / (b.n * tult));
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> TzSimple1::clone() const { return std::make_unique<TzSimple1>(*this); }

void TzSimple1::revertToStart() {
  nearField_.revertToStart();
  committed_ = State{};
  committed_.tangent = initialTangent_;
  trial_ = committed_;
}

double TzSimple1::seriesTangent(double nearTangent) const {
  return 1.0 / (1.0 / farStiffness_ + 1.0 / std::max(nearTangent, kNearFieldFloor * tult_ / z50_));
}

void TzSimple1::setTrialStrain(double z, double rate) {
  if (z == committed_.z) {
    nearField_.setTrialToCommitted();
    trial_ = committed_;
    trial_.rate = rate;
    trial_.tangent = seriesTangent(nearField_.tangent());
    return;
  }
  auto displacement = [&](double t) {
    const SoilNearField::Trial near = nearField_.at(t);
    return std::pair{t / farStiffness_ + near.y - z, 1.0 / farStiffness_ + nearField_.flexibility(t, near)};
  };
  const double guess = committed_.t + (z - committed_.z) * committed_.tangent;
  const double t = increasingRoot(displacement, -tult_, tult_, guess);
  nearField_.setTrial(t);
  trial_ = {z, rate, t, seriesTangent(nearField_.tangent())};
}

double TzSimple1::farFieldShare() const {
  return soildashpot::farFieldShare(trial_.z, committed_.z, trial_.t, committed_.t, trial_.tangent, farStiffness_);
}

double TzSimple1::stress() const {
  return soildashpot::stress(trial_.t, dashpot_, farFieldShare(), trial_.rate, tult_);
}

void TzSimple1::commitState() {
  committed_ = trial_;
  nearField_.commit();
}

void TzSimple1::revertToLastCommit() {
  trial_ = committed_;
  nearField_.revert();
}

void TzSimple1::print(std::ostream& os) const {
  os << "TzSimple1 tag: " << tag() << " tzType: " << tzType_ << " tult: " << tult_ << " z50: " << z50_
     << " c: " << dashpot_ << "\n";
}

namespace {

std::unique_ptr<UniaxialMaterial> buildTzSimple1(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial TzSimple1 " + std::to_string(tag));
  const int tzType = args.nextInt("tzType");
  const double tult = args.nextDouble("tult");
  const double z50 = args.nextDouble("z50");
  const double c = args.done() ? 0.0 : args.nextDouble("c");
  args.expectEnd();
  if (tzType != 1 && tzType != 2)
    args.fail("tzType must be 1 (Reese & O'Neill 1987) or 2 (Mosher 1984), got " + std::to_string(tzType));
  if (!(tult > 0.0)) args.fail("tult must be positive, got " + std::to_string(tult));
  if (!(z50 > 0.0)) args.fail("z50 must be positive, got " + std::to_string(z50));
  if (!(c >= 0.0)) args.fail("c (dashpot) must not be negative, got " + std::to_string(c));
  return std::make_unique<TzSimple1>(tag, tzType, tult, z50, c);
}

void registerTzSimple1(Registry& r) { r.uniaxialMaterials.add("TzSimple1", &buildTzSimple1); }

}  // namespace

BEAMSOLID_REGISTER(registerTzSimple1);

}  // namespace beamsolid
