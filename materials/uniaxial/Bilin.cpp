#include "materials/uniaxial/Bilin.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {
constexpr double kResidualSlope = ImkBackbone::kResidualSlope;
constexpr double kFailedStress = ImkBackbone::kFailedStress;
constexpr auto kHardening = ImkBackbone::kHardening;
constexpr auto kResidual = ImkBackbone::kResidual;
}  // namespace

Bilin::Bilin(int tag, double K0, const SideInput& positive, const SideInput& negative, const DeteriorationInput& det,
             double nFactor)
    : UniaxialMaterial(tag), backbone_(K0, nFactor, positive, negative), det_(det), energyCapacity_(positive.My) {
  for (int s = 0; s < 2; ++s) static_cast<ImkBackbone::Lines&>(initial_[s]) = backbone_.initial(s);
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Bilin::clone() const { return std::make_unique<Bilin>(*this); }

void Bilin::revertToStart() {
  committed_ = State{};
  committed_.tangent = backbone_.Ke();
  committed_.K = backbone_.Ke();
  committed_.side = initial_;
  trial_ = committed_;
}

void Bilin::setTrialStrain(double strain, double) {
  const State& c = committed_;
  const double Ke_ = backbone_.Ke(), nFactor_ = backbone_.nFactor();
  trial_ = c;
  const double step = strain - c.strain;
  // A change below machine epsilon is no change (as OpenSees, found by running it).
  if (std::fabs(step) < std::numeric_limits<double>::epsilon()) return;
  State& t = trial_;
  t.strain = strain;
  const int dir = step > 0.0 ? 1 : -1;
  const int side = step > 0.0 ? 0 : 1;

  // Beyond theta_u the spring carries (next to) nothing; back inside, it goes on from there.
  if (strain >= backbone_.input(0).thetaU || strain <= -backbone_.input(1).thetaU) {
    t.stress = dir * kFailedStress;
    t.tangent = kResidualSlope;
    t.direction = dir;
    return;
  }

  // Unloading stiffness deterioration at a reversal, from the energy of the excursion so far
  // less the elastic energy that unloading gives back.
  if (c.direction != 0 && dir != c.direction && det_.lambdaK > 0.0 && c.loadedOnBound) {
    const double energy = c.work - c.workAtCrossing - c.stress * c.stress / (2.0 * c.K);
    const double b =
        ImkBackbone::beta(energy, 2.0 * det_.lambdaK * energyCapacity_ - c.workAtCrossing - energy, det_.cK);
    // With nFactor the loss applies to the member and reaches the spring scaled (as for as).
    t.stiffnessRatio = c.stiffnessRatio * (1.0 - b);
    t.K = Ke_ * t.stiffnessRatio / (1.0 + nFactor_ * (1.0 - t.stiffnessRatio));
  }
  // The elastic line starts at the last reversal (the origin before any): OpenSees evaluates
  // it from there, not step by step (visible in round-off at the corners).
  if (c.direction != 0 && dir != c.direction) {
    t.loadedOnBound = false;
    t.refStrain = c.strain;
    t.refStress = c.stress;
  }
  const double K = t.K;
  const double predictor = t.refStress + K * (strain - t.refStrain);
  const bool crossing = c.stress * predictor < 0.0;
  SideState& s = t.side[side];
  if (crossing) {
    // The excursion ends: its energy deteriorates the side being entered.
    const double work = c.work + 0.5 * (c.stress + predictor) * step;
    const double energy = work - c.workAtCrossing;
    // Only an excursion that reached a bound deteriorates anything (OpenSees: elastic
    // cycles leave the model as it was).
    t.yielded = false;
    if (c.yieldedOnce && det_.lambdaS > 0.0) {
      const double b = ImkBackbone::beta(energy, det_.lambdaS * energyCapacity_ - work, det_.cS);
      backbone_.scaleStrength(s, 1.0 - backbone_.input(side).D * b);
    }
    if (c.yieldedOnce && det_.lambdaC > 0.0) {
      const double b = ImkBackbone::beta(energy, det_.lambdaC * energyCapacity_ - work, det_.cC);
      s.capFactor *= 1.0 - backbone_.input(side).D * b;
    }
    if (c.yieldedOnce && (det_.lambdaS > 0.0 || det_.lambdaC > 0.0)) {
      // The post-capping line as OpenSees rebuilds it (found by running it): the original
      // line moved towards the origin (intercept times the product of the (1 - D beta_C)),
      // then turned about its meeting point with the current hardening line to the slope
      // of the original one scaled with My - Res*|My0|.
      const SideState& o = initial_[side];
      const double movedIntercept = o.capIntercept * s.capFactor;
      const double drop = o.My - backbone_.residual(side);
      if (drop != 0.0) {
        s.ac = o.ac * (s.My - backbone_.residual(side)) / drop;
        s.capSlope = backbone_.modified(s.ac) * Ke_;
      }
      const double hardeningIntercept = s.My - s.hardening * s.My / Ke_;
      const double pivot = (movedIntercept - hardeningIntercept) / (s.hardening - o.capSlope);
      s.capIntercept = movedIntercept + (o.capSlope - s.capSlope) * pivot;
      // Where the post-capping line now meets the elastic line before the yield point, that
      // meeting point becomes the yield point (the hardening line moves with it; My itself,
      // which scales the post-capping slope, does not).
      const double meet = s.capIntercept / (Ke_ - s.capSlope);
      const bool cut = backbone_.sign(side) * meet < backbone_.sign(side) * s.My / Ke_;
      s.yield = cut ? Ke_ * meet : s.My;
      // The residual follows a cut yield point (Res times it), not My's deterioration.
      s.residual = cut ? backbone_.input(side).res * s.yield : backbone_.residual(side);
    }
  }

  const double sg = backbone_.sign(side);
  Bound b = backbone_.bound(s, side, strain);
  if (sg * predictor > sg * b.stress) {
    if (crossing) {
      // Where the zero-stress point lies beyond the origin and the unloading line meets the
      // hardening line where that is the bound, OpenSees stops at the meeting point.
      const double zeroStress = c.strain - c.stress / K;
      if (sg * zeroStress < 0.0) {
        const double intercept = s.yield - s.hardening * s.yield / Ke_;
        const double x = (intercept - c.stress + K * c.strain) / (K - s.hardening);
        if (std::isfinite(x) && sg * (x - c.strain) >= 0.0 && sg * (x - strain) <= 0.0) {
          const Bound at = backbone_.bound(s, side, x);
          if (at.branch == kHardening) b = at;
        }
      }
    }
    // The step that enters the residual gives (Res times the current yield point) + 1e-7 theta,
    // the steps on it Res*|My0| (as OpenSees).
    if (b.branch == kResidual)
      b.stress = s.lastBound != kResidual ? s.residual + kResidualSlope * strain : backbone_.residual(side);
    t.stress = b.stress;
    t.tangent = b.slope;
    s.lastBound = b.branch;
    t.yielded = t.yieldedOnce = t.loadedOnBound = true;
  } else {
    t.stress = predictor;
    t.tangent = K;
    if (crossing) {
      const double thetaY = s.yield / Ke_;
      const bool insideElasticRange = sg * strain >= 0.0 && sg * (strain - thetaY) <= 0.0;
      if (!insideElasticRange || (c.yieldedOnce && det_.lambdaS > 0.0))
        t.tangent = sg * (s.extreme - thetaY) <= 0.0 ? Ke_ : backbone_.bound(s, side, s.extreme).slope;
    }
  }
  t.work = c.work + 0.5 * (c.stress + t.stress) * step;
  if (crossing && c.yieldedOnce) t.workAtCrossing = t.work;
  t.direction = dir;
  SideState& reached = t.side[strain > 0.0 ? 0 : 1];
  if (std::fabs(strain) > std::fabs(reached.extreme)) reached.extreme = strain;
}

void Bilin::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Bilin K0 " << backbone_.K0() << " nFactor " << backbone_.nFactor()
     << " My+ " << backbone_.input(0).My << " My- " << backbone_.input(1).My << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildBilin(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Bilin " + std::to_string(tag));
  const ImkArguments a = readImkArguments(args, false);
  double nFactor = 0.0;
  if (!args.done()) nFactor = args.nextDouble("nFactor");
  args.expectEnd();
  checkImkArguments(args, a, false);
  if (!(nFactor >= 0.0) || !std::isfinite(nFactor))
    args.fail("nFactor must be zero or positive, got " + std::to_string(nFactor));
  return std::make_unique<Bilin>(tag, a.K0, a.positive, a.negative, a.deterioration, nFactor);
}

void registerBilin(Registry& r) { r.uniaxialMaterials.add("Bilin", &buildBilin); }

}  // namespace

BEAMSOLID_REGISTER(registerBilin);

}  // namespace beamsolid
