#include "materials/uniaxial/ModIMKPeakOriented.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ModIMKPeakOriented::ModIMKPeakOriented(int tag, double K0, const SideInput& positive, const SideInput& negative,
                                       const DeteriorationInput& det, std::optional<Pinching> pinching)
    : UniaxialMaterial(tag),
      backbone_(K0, 0.0, positive, negative),
      det_(det),
      energyCapacity_(positive.My),
      pinching_(pinching) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> ModIMKPeakOriented::clone() const {
  return std::make_unique<ModIMKPeakOriented>(*this);
}

void ModIMKPeakOriented::revertToStart() {
  committed_ = State{};
  committed_.tangent = committed_.K = backbone_.Ke();
  for (int s = 0; s < 2; ++s) {
    SideState& st = committed_.side[s];
    static_cast<ImkBackbone::Lines&>(st) = backbone_.initial(s);
    st.peak = st.My / backbone_.Ke();
    st.maxReached = {st.peak, st.My};
  }
  trial_ = committed_;
}

ImkBackbone::Bound ModIMKPeakOriented::backboneAt(const SideState& s, int side, double strain) const {
  const double sg = backbone_.sign(side);
  // Past theta_u (a peak moved out by Lamda_A) the backbone has failed: OpenSees aims at +-1e-10.
  if (sg * strain >= backbone_.input(side).thetaU)
    return {sg * ImkBackbone::kFailedStress, ImkBackbone::kResidualSlope, ImkBackbone::kResidual};
  ImkBackbone::Bound b = backbone_.bound(s, side, strain);
  // On the residual OpenSees gives Res*|My0| + 1e-7 theta.
  if (b.branch == ImkBackbone::kResidual) b.stress = s.residual + ImkBackbone::kResidualSlope * strain;
  return b;
}

ModIMKPeakOriented::Candidate ModIMKPeakOriented::reloading(const SideState& s, int side, double strain,
                                                              double K) const {
  const double sg = backbone_.sign(side);
  const ImkBackbone::Bound b = backboneAt(s, side, strain);
  if (sg * strain > sg * s.peak) return {b.stress, b.slope, true};
  const Point peak{s.peak, backboneAt(s, side, s.peak).stress};
  Point from{s.zero, 0.0}, to = peak;
  if (pinching_) {
    // ModIMKPinching: towards (peak strain, Fpr times the peak stress) up to the break strain
    // A_pinch times the peak's zero-stress point under unloading with K, then on to the peak
    // (straight to the peak when reloading starts beyond the break strain).
    const double breakStrain = pinching_->aPinch * (s.peak - peak.stress / K);
    if (sg * s.zero < sg * breakStrain) {
      const double pinched = pinching_->fpr[side] * peak.stress / (s.peak - s.zero);
      const Point breakPoint{breakStrain, pinched * (breakStrain - s.zero)};
      if (sg * strain < sg * breakStrain)
        to = {s.peak, pinching_->fpr[side] * peak.stress};
      else if (sg * strain >= sg * s.peak)
        return {b.stress, b.slope, true};  // after a break, OpenSees reports the backbone at the peak itself
      else
        from = breakPoint;
    }
  } else if (s.turned && sg * s.turn.strain < sg * s.maxReached.strain && sg * s.turn.strain > sg * s.zero &&
             sg * s.turn.stress > sg * peak.stress * (s.turn.strain - s.zero) / (s.peak - s.zero) &&
             sg * s.turn.stress <= sg * peak.stress) {
    // The side last turned back from a point outside the line to the peak: reloading aims there
    // first (decided step by step: the peak moves with deterioration).
    if (sg * strain < sg * s.turn.strain)
      to = s.turn;
    else
      from = s.turn;
  } else {
    const bool yielded = sg * s.maxReached.strain > sg * backbone_.initial(side).My / backbone_.Ke();
    if (sg * s.peak > sg * s.maxReached.strain && sg * peak.stress > sg * s.maxReached.stress &&
        (!yielded || (s.turned && s.turn.strain == s.maxReached.strain))) {
      // Lamda_A moved the peak out to where the backbone is stronger than where the side last
      // turned back at its largest strain (or than the yield point): OpenSees aims at that point
      // first (1e-10 beyond it once the side has yielded), then along the line to the peak.
      const Point reached{s.maxReached.strain + (yielded ? sg * 1e-10 : 0.0), s.maxReached.stress};
      if (sg * strain <= sg * reached.strain)
        to = reached;
      else
        from = reached;
    }
  }
  const double slope = (to.stress - from.stress) / (to.strain - from.strain);
  const double line = from.stress + slope * (strain - from.strain);
  // The line goes on past the peak; the backbone bounds it (as OpenSees: at the peak itself the
  // line's slope is reported).
  if (sg * b.stress < sg * line) return {b.stress, b.slope, true};
  return {line, slope, false};
}

void ModIMKPeakOriented::deteriorate(SideState& s, int side, double energy, double work) const {
  const double D = backbone_.input(side).D;
  if (det_.lambdaS > 0.0) {
    const double b = ImkBackbone::beta(energy, det_.lambdaS * energyCapacity_ - work, det_.cS);
    backbone_.scaleStrength(s, 1.0 - D * b);
    s.yield = s.My;
  }
  if (det_.lambdaC > 0.0) {
    const double b = ImkBackbone::beta(energy, det_.lambdaC * energyCapacity_ - work, det_.cC);
    s.capFactor *= 1.0 - D * b;
    s.capIntercept = backbone_.initial(side).capIntercept * s.capFactor;
  }
  // Accelerated reloading stiffness deterioration: the peak moves out.
  if (det_.lambdaA > 0.0) {
    const double b = ImkBackbone::beta(energy, det_.lambdaA * energyCapacity_ - work, det_.cA);
    s.peak *= 1.0 + b;
  }
}

void ModIMKPeakOriented::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  const double step = strain - c.strain;
  // A change below machine epsilon is no change.
  if (std::fabs(step) < std::numeric_limits<double>::epsilon()) return;
  State& t = trial_;
  t.strain = strain;
  const int dir = step > 0.0 ? 1 : -1;
  const int side = step > 0.0 ? 0 : 1;
  const double sg = backbone_.sign(side);

  // Beyond theta_u the spring fails for good: one step of +1e-10 (on either side, as
  // OpenSees), then nothing.
  if (c.failed || strain >= backbone_.input(0).thetaU || strain <= -backbone_.input(1).thetaU) {
    t.failed = true;
    t.stress = c.failed ? 0.0 : ImkBackbone::kFailedStress;
    t.tangent = c.failed ? 0.0 : ImkBackbone::kResidualSlope;
    t.direction = dir;
    return;
  }

  if (c.direction != 0 && dir != c.direction) {
    // Unloading stiffness deterioration, from the energy of the excursion so far less the
    // elastic energy that unloading gives back.
    if (det_.lambdaK > 0.0 && c.yieldedOnce) {
      const double energy = c.work - c.workAtCrossing - c.stress * c.stress / (2.0 * c.K);
      const double b =
          ImkBackbone::beta(energy, 2.0 * det_.lambdaK * energyCapacity_ - c.workAtCrossing - energy, det_.cK);
      t.stiffnessRatio = c.stiffnessRatio * (1.0 - b);
      t.K = backbone_.Ke() * t.stiffnessRatio;
    }
    // A side remembers where loading on it turned back.
    if (c.stress != 0.0 && (c.stress > 0.0) == (c.direction > 0)) {
      SideState& turned = t.side[c.stress > 0.0 ? 0 : 1];
      turned.turn = {c.strain, c.stress};
      turned.turned = true;
    }
    t.refStrain = c.strain;
    t.refStress = c.stress;
  }
  const double K = t.K;
  const double unloading = t.refStress + K * (strain - t.refStrain);
  SideState& s = t.side[side];
  const bool crossing = sg * c.stress < 0.0 && sg * unloading > 0.0;
  if (crossing) {
    // A new reloading line into this side, from where unloading reaches zero stress.
    s.zero = t.refStrain - t.refStress / K;
  }
  bool onBound = false;
  if (sg * unloading <= 0.0) {
    t.stress = unloading;
    t.tangent = K;
  } else {
    const Candidate r = reloading(s, side, strain, K);
    if (sg * unloading < sg * r.stress) {
      t.stress = unloading;
      t.tangent = K;
    } else {
      t.stress = r.stress;
      t.tangent = r.slope;
      onBound = r.onBound;
    }
  }
  if (onBound) {
    t.yieldedOnce = true;
    if (sg * strain > sg * s.maxReached.strain) s.maxReached = {strain, t.stress};
    if (sg * strain > sg * s.peak) s.peak = strain;
  }
  t.work = c.work + 0.5 * (c.stress + t.stress) * step;
  if (crossing && c.yieldedOnce) {
    // The excursion ends: its energy deteriorates the side being entered (from the next step).
    deteriorate(s, side, t.work - c.workAtCrossing, t.work);
    t.workAtCrossing = t.work;
  }
  t.direction = dir;
}

void ModIMKPeakOriented::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type " << className() << " K0 " << backbone_.K0() << " My+ "
     << backbone_.input(0).My << " My- " << backbone_.input(1).My << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildModIMKPeakOriented(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ModIMKPeakOriented " + std::to_string(tag));
  const ImkArguments a = readImkArguments(args, false);
  args.expectEnd();
  checkImkArguments(args, a, false);
  return std::make_unique<ModIMKPeakOriented>(tag, a.K0, a.positive, a.negative, a.deterioration);
}

void registerModIMKPeakOriented(Registry& r) {
  r.uniaxialMaterials.add("ModIMKPeakOriented", &buildModIMKPeakOriented);
}

}  // namespace

BEAMSOLID_REGISTER(registerModIMKPeakOriented);

}  // namespace beamsolid
