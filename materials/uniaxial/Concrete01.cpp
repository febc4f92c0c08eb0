#include "materials/uniaxial/Concrete01.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

Concrete01::Concrete01(int tag, double fpc, double epsc0, double fpcu, double epsU)
    : UniaxialMaterial(tag), envelope_{fpc, epsc0, fpcu, epsU} {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> Concrete01::clone() const { return std::make_unique<Concrete01>(*this); }

void Concrete01::revertToStart() {
  committed_ = State{};
  committed_.tangent = envelope_.initialTangent();
  trial_ = committed_;
}

void Concrete01::unloadingLine(double minStrain, double& slope, double& zeroStressStrain) const {
  const double Ec = envelope_.initialTangent();
  if (minStrain >= 0.0) {
    slope = Ec;
    zeroStressStrain = 0.0;
    return;
  }
  const double ratio = std::max(minStrain, envelope_.epsU) / envelope_.epsc0;
  const double plasticStrain = envelope_.epsc0 * (ratio < 2.0 ? (0.145 * ratio + 0.13) * ratio
                                                              : 0.707 * (ratio - 2.0) + 0.834);
  const double minStress = envelope_.stressAt(minStrain);
  if (minStress >= 0.0) {
    // Crushed with no residual strength (fpcu = 0): nothing to unload.
    slope = 0.0;
    zeroStressStrain = -std::numeric_limits<double>::infinity();
    return;
  }
  slope = std::min(Ec, minStress / (minStrain - plasticStrain));
  zeroStressStrain = minStrain - minStress / slope;
}

void Concrete01::setTrialStrain(double strain, double) {
  const State& c = committed_;
  trial_ = c;
  // A change below machine epsilon is no change (as OpenSees, found by running it): the
  // committed state, strain and tangent stay, so round-off in a fiber's strain cannot pick a
  // branch, nor can such changes add up.
  if (std::fabs(strain - c.strain) < std::numeric_limits<double>::epsilon()) return;
  trial_.strain = strain;

  if (strain < c.minStrain) {
    envelope_.evaluate(strain, trial_.stress, trial_.tangent);
    trial_.minStrain = strain;
    return;
  }
  double slope, zeroStressStrain;
  unloadingLine(c.minStrain, slope, zeroStressStrain);
  if (strain < zeroStressStrain) {
    trial_.stress = slope * (strain - zeroStressStrain);
    trial_.tangent = slope;
  } else {
    trial_.stress = 0.0;  // open crack: no tensile strength
    trial_.tangent = 0.0;
  }
}

void Concrete01::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Concrete01 fpc " << envelope_.fpc << " epsc0 " << envelope_.epsc0
     << " fpcu " << envelope_.fpcu << " epsU " << envelope_.epsU << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildConcrete01(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Concrete01 " + std::to_string(tag));
  // Compression is negative; like OpenSees, positive input means compression too.
  const double fpc = -std::abs(args.nextDouble("fpc"));
  const double epsc0 = -std::abs(args.nextDouble("epsc0"));
  const double fpcu = -std::abs(args.nextDouble("fpcu"));
  const double epsU = -std::abs(args.nextDouble("epsU"));
  args.expectEnd();
  if (!(fpc < 0.0)) args.fail("fpc must be nonzero (compressive strength)");
  if (!(epsc0 < 0.0)) args.fail("epsc0 must be nonzero (strain at the compressive strength)");
  if (!(epsU < epsc0))
    args.fail("|epsU| must exceed |epsc0| (crushing after the peak), got epsc0 " + std::to_string(epsc0) +
              ", epsU " + std::to_string(epsU));
  if (!(fpcu >= fpc))
    args.fail("|fpcu| must not exceed |fpc| (residual strength), got fpc " + std::to_string(fpc) + ", fpcu " +
              std::to_string(fpcu));
  return std::make_unique<Concrete01>(tag, fpc, epsc0, fpcu, epsU);
}

void registerConcrete01(Registry& r) { r.uniaxialMaterials.add("Concrete01", &buildConcrete01); }

}  // namespace

BEAMSOLID_REGISTER(registerConcrete01);

}  // namespace beamsolid
