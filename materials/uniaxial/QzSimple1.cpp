#include "materials/uniaxial/QzSimple1.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "core/CommandArgs.h"
#include "core/Registry.h"
#include "materials/uniaxial/IncreasingRoot.h"
#include "materials/uniaxial/SoilDashpot.h"

namespace beamsolid {

namespace {
struct Backbone {
  double c, n, Cr, Ce;
};
// c, n, Cr from the OpenSees manual; Ce read off OpenSees' tangents.
Backbone backbone(int qzType) {
  return qzType == 1 ? Backbone{0.35, 1.2, 0.2, 0.525} : Backbone{12.3, 5.5, 0.3, 1.39};
}
constexpr double kNearFieldElastic = 1.0e4;  // qult / z50
constexpr double kClosed = 1000.0;           // closure in bearing, qult / z50
constexpr double kOpen = 1.000002e-6;        // closure in uplift, qult / z50 (measured)
constexpr double kAtRest = 100.0;            // the closure in OpenSees' initial tangent
constexpr double kTangentFloor = 1.0e-4;  // smallest near-field / drag tangent reported, qult / z50
}  // namespace

QzSimple1::QzSimple1(int tag, int qzType, double qult, double z50, double suction, double c)
    : UniaxialMaterial(tag), qzType_(qzType), qult_(qult), z50_(z50), suction_(suction), dashpot_(c) {
  const Backbone b = backbone(qzType);
  farStiffness_ = b.Ce * qult / z50;
  closedStiffness_ = kClosed * qult / z50;
  openStiffness_ = kOpen * qult / z50;
  nearField_ = SoilNearField(qult, b.c * z50, b.n, b.Cr, kNearFieldElastic * qult / z50,
                             SoilNearField::Range::QzSimple1);
  drag_ = SoilDrag(suction * qult, z50);
  initialTangent_ = 1.0 / (1.0 / farStiffness_ + z50 / (kNearFieldElastic * qult) +
                           z50 / ((kAtRest + 2.0 * suction) * qult));
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> QzSimple1::clone() const { return std::make_unique<QzSimple1>(*this); }

void QzSimple1::revertToStart() {
  nearField_.revertToStart();
  drag_.revertToStart();
  committed_ = State{};
  committed_.tangent = initialTangent_;
  trial_ = committed_;
}

std::pair<double, double> QzSimple1::gapForce(double gap) const {
  const double k = gap > 0.0 ? openStiffness_ : closedStiffness_;
  const SoilDrag::Cycle cycle = drag_.cycle(gap);
  return {k * gap + drag_.force(gap, cycle), k + drag_.tangent(gap, cycle)};
}

double QzSimple1::gapAt(double q, double guess) const {
  auto f = [&](double g) {
    const auto [force, slope] = gapForce(g);
    return std::pair{force - q, slope};
  };
  auto [value, slope] = f(guess);
  if (value == 0.0) return guess;
  double step = std::max(std::abs(value) / slope, 1e-12 * z50_);
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

double QzSimple1::seriesTangent(double nearTangent, double gap) const {
  // As OpenSees reports it: the near-field and drag tangents are kept above
  // 1e-4 qult / z50 (the open closure's 1e-6 is not; no suction, no drag).
  const double floor = kTangentFloor * qult_ / z50_;
  const SoilDrag::Cycle cycle = drag_.cycle(gap);
  const double closure = gap > 0.0 ? openStiffness_ : closedStiffness_;
  const double drag = suction_ > 0.0 ? std::max(drag_.tangent(gap, cycle), floor) : 0.0;
  return 1.0 / (1.0 / farStiffness_ + 1.0 / std::max(nearTangent, floor) + 1.0 / (closure + drag));
}

void QzSimple1::setTrialStrain(double z, double rate) {
  if (z == committed_.z) {
    nearField_.setTrialToCommitted();
    drag_.setTrialToCommitted();
    trial_ = committed_;
    trial_.rate = rate;
    trial_.tangent = seriesTangent(nearField_.tangent(), committed_.gap);
    return;
  }
  double gapGuess = committed_.gap;
  auto displacement = [&](double q) {
    const SoilNearField::Trial near = nearField_.at(q);
    const double g = gapAt(q, gapGuess);
    gapGuess = g;
    return std::pair{q / farStiffness_ + near.y + g - z,
                     1.0 / farStiffness_ + nearField_.flexibility(q, near) + 1.0 / gapForce(g).second};
  };
  const double guess = committed_.q + (z - committed_.z) * committed_.tangent;
  const double q = increasingRoot(displacement, -qult_, qult_, guess);
  nearField_.setTrial(q);
  const double g = gapAt(q, gapGuess);
  drag_.setTrial(g);
  trial_ = {z, rate, q, seriesTangent(nearField_.tangent(), g), g};
}

double QzSimple1::farFieldShare() const {
  return soildashpot::farFieldShare(trial_.z, committed_.z, trial_.q, committed_.q, trial_.tangent, farStiffness_);
}

double QzSimple1::stress() const {
  return soildashpot::stress(trial_.q, dashpot_, farFieldShare(), trial_.rate, qult_);
}

void QzSimple1::commitState() {
  committed_ = trial_;
  nearField_.commit();
  drag_.commit();
}

void QzSimple1::revertToLastCommit() {
  trial_ = committed_;
  nearField_.revert();
  drag_.revert();
}

void QzSimple1::print(std::ostream& os) const {
  os << "QzSimple1 tag: " << tag() << " qzType: " << qzType_ << " qult: " << qult_ << " z50: " << z50_
     << " suction: " << suction_ << " c: " << dashpot_ << "\n";
}

namespace {

std::unique_ptr<UniaxialMaterial> buildQzSimple1(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial QzSimple1 " + std::to_string(tag));
  const int qzType = args.nextInt("qzType");
  const double qult = args.nextDouble("qult");
  const double z50 = args.nextDouble("Z50");
  double suction = args.done() ? 0.0 : args.nextDouble("suction");
  const double c = args.done() ? 0.0 : args.nextDouble("c");
  args.expectEnd();
  if (qzType != 1 && qzType != 2)
    args.fail("qzType must be 1 (Reese & O'Neill 1987, clay) or 2 (Vijayvergiya 1977, sand), got " +
              std::to_string(qzType));
  if (!(qult > 0.0)) args.fail("qult must be positive, got " + std::to_string(qult));
  if (!(z50 > 0.0)) args.fail("Z50 must be positive, got " + std::to_string(z50));
  // OpenSees documents 0 <= suction <= 0.1; OpenSeesPy takes a larger value as 0.1 with a
  // warning (and a script that passes one must run here too), a negative one as none.
  if (std::isnan(suction)) args.fail("suction must be a number in [0, 0.1], got nan");
  if (suction > 0.1) {
    std::cerr << "WARNING uniaxialMaterial QzSimple1 " << tag << ": suction " << suction
              << " is more than 0.1; 0.1 is used\n";
    suction = 0.1;
  }
  if (suction < 0.0) suction = 0.0;
  if (!(c >= 0.0)) args.fail("c (dashpot) must not be negative, got " + std::to_string(c));
  return std::make_unique<QzSimple1>(tag, qzType, qult, z50, suction, c);
}

void registerQzSimple1(Registry& r) { r.uniaxialMaterials.add("QzSimple1", &buildQzSimple1); }

}  // namespace

BEAMSOLID_REGISTER(registerQzSimple1);

}  // namespace beamsolid
