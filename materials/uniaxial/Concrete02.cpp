#include "materials/uniaxial/Concrete02.h"

#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

Concrete02::Concrete02(int tag, double fpc, double epsc0, double fpcu, double epsU, double lambda, double ft,
                       double Ets)
    : UniaxialMaterial(tag), envelope_{fpc, epsc0, fpcu, epsU}, lambda_(lambda), ft_(ft), Ets_(Ets) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Concrete02::clone() const { return std::make_unique<Concrete02>(*this); }

void Concrete02::revertToStart() {
  committed_ = State{};
  committed_.tangent = envelope_.initialTangent();
  trial_ = committed_;
}

void Concrete02::reloadingLine(double minStrain, double& slope, double& zeroStressStrain) const {
  const double Ec = envelope_.initialTangent();
  const double focalStrain = (envelope_.fpcu - lambda_ * Ec * envelope_.epsU) / (Ec * (1.0 - lambda_));
  const double focalStress = Ec * focalStrain;
  const double minStress = envelope_.stressAt(minStrain);
  slope = (minStress - focalStress) / (minStrain - focalStrain);
  zeroStressStrain = minStrain - minStress / slope;
}

void Concrete02::tensionEnvelope(double opening, double& stress, double& tangent) const {
  const double Ec = envelope_.initialTangent();
  if (opening <= ft_ / Ec) {
    stress = Ec * opening;
    tangent = Ec;
    return;
  }
  stress = ft_ - Ets_ * (opening - ft_ / Ec);
  tangent = -Ets_;
  if (stress <= 0.0) {
    stress = 0.0;  // fully open crack
    tangent = 0.0;
  }
}

void Concrete02::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  trial_.strain = strain;
  const double step = strain - c.strain;
  // A change below machine epsilon keeps the committed stress and tangent (as OpenSees, found
  // by running it), so round-off in a fiber's strain cannot pick a branch; unlike Concrete01
  // the new strain is kept, and the next change counts from it.
  if (std::fabs(step) < std::numeric_limits<double>::epsilon()) return;

  if (strain < c.minStrain) {
    envelope_.evaluate(strain, trial_.stress, trial_.tangent);
    trial_.minStrain = strain;
    return;
  }

  const double Ec = envelope_.initialTangent();
  double reloadSlope, crackStrain;
  reloadingLine(c.minStrain, reloadSlope, crackStrain);
  if (strain <= crackStrain) {
    // Bounded elastic move between the reloading and unloading lines.
    const double minStress = envelope_.stressAt(c.minStrain);
    const double lowerBound = minStress + reloadSlope * (strain - c.minStrain);
    const double upperBound = 0.5 * reloadSlope * (strain - crackStrain);
    trial_.stress = c.stress + Ec * step;
    trial_.tangent = Ec;
    if (trial_.stress <= lowerBound) {
      trial_.stress = lowerBound;
      trial_.tangent = reloadSlope;
    }
    if (trial_.stress >= upperBound) {
      trial_.stress = upperBound;
      trial_.tangent = 0.5 * reloadSlope;
    }
    return;
  }

  const double opening = strain - crackStrain;
  if (opening > c.maxCrackOpening) {
    tensionEnvelope(opening, trial_.stress, trial_.tangent);
    trial_.maxCrackOpening = opening;
  } else {
    // Inside the tension envelope: secant to the crack-closing point.
    double peakStress, peakTangent;
    tensionEnvelope(c.maxCrackOpening, peakStress, peakTangent);
    const double secant = peakStress / c.maxCrackOpening;
    trial_.stress = secant * opening;
    trial_.tangent = secant;
  }
}

void Concrete02::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Concrete02 fpc " << envelope_.fpc << " epsc0 " << envelope_.epsc0
     << " fpcu " << envelope_.fpcu << " epsU " << envelope_.epsU << " lambda " << lambda_ << " ft " << ft_
     << " Ets " << Ets_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildConcrete02(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Concrete02 " + std::to_string(tag));
  // Compression is negative; like OpenSees, positive input means compression too.
  const double fpc = -std::abs(args.nextDouble("fpc"));
  const double epsc0 = -std::abs(args.nextDouble("epsc0"));
  const double fpcu = -std::abs(args.nextDouble("fpcu"));
  const double epsU = -std::abs(args.nextDouble("epsU"));
  // OpenSees' defaults when the tension parameters are left out.
  double lambda = 0.1, ft = 0.1 * std::abs(fpc), Ets = 0.1 * std::abs(fpc / epsc0);
  if (!args.done()) {
    if (args.remaining() != 3)
      args.fail("lambda, ft and Ets come together (got " + std::to_string(args.remaining()) +
                " of them); the Popovics variant with an initial slope is not supported");
    lambda = args.nextDouble("lambda");
    ft = args.nextDouble("ft");
    Ets = args.nextDouble("Ets");
  }
  args.expectEnd();
  if (!(fpc < 0.0)) args.fail("fpc must be nonzero (compressive strength)");
  if (!(epsc0 < 0.0)) args.fail("epsc0 must be nonzero (strain at the compressive strength)");
  if (!(epsU < epsc0))
    args.fail("|epsU| must exceed |epsc0| (crushing after the peak), got epsc0 " + std::to_string(epsc0) +
              ", epsU " + std::to_string(epsU));
  if (!(fpcu >= fpc))
    args.fail("|fpcu| must not exceed |fpc| (residual strength), got fpc " + std::to_string(fpc) + ", fpcu " +
              std::to_string(fpcu));
  if (!(lambda >= 0.0 && lambda < 1.0))
    args.fail("lambda must lie in [0, 1) (unloading slope at epsU over the initial slope), got " +
              std::to_string(lambda));
  if (!(ft >= 0.0)) args.fail("ft must not be negative (tensile strength), got " + std::to_string(ft));
  if (!(Ets >= 0.0)) args.fail("Ets must not be negative (softening stiffness, absolute value), got " + std::to_string(Ets));
  return std::make_unique<Concrete02>(tag, fpc, epsc0, fpcu, epsU, lambda, ft, Ets);
}

void registerConcrete02(Registry& r) { r.uniaxialMaterials.add("Concrete02", &buildConcrete02); }

}  // namespace

BEAMSOLID_REGISTER(registerConcrete02);

}  // namespace beamsolid
