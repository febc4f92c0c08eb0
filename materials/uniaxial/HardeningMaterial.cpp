#include "materials/uniaxial/HardeningMaterial.h"

#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

HardeningMaterial::HardeningMaterial(int tag, double E, double sigmaY, double Hiso, double Hkin)
    : UniaxialMaterial(tag), E_(E), sigmaY_(sigmaY), Hiso_(Hiso), Hkin_(Hkin) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> HardeningMaterial::clone() const {
  return std::make_unique<HardeningMaterial>(*this);
}

void HardeningMaterial::revertToStart() {
  committed_ = State{};
  committed_.tangent = E_;
  trial_ = committed_;
}

void HardeningMaterial::setTrialStrain(double strain, double) {
  // Every trial starts from the committed plastic state (no accumulation
  // over the iterations of one step).
  const State& c = committed_;
  trial_ = c;
  // A change below machine epsilon is no change (as OpenSees, found by running it): the
  // committed state, strain and tangent stay, so round-off in a fiber's strain cannot pick a
  // branch, nor can such changes add up.
  if (std::fabs(strain - c.strain) < std::numeric_limits<double>::epsilon()) return;
  trial_.strain = strain;
  const double predictor = E_ * (strain - c.plasticStrain);
  const double relative = predictor - c.backStress;
  const double f = std::abs(relative) - (sigmaY_ + Hiso_ * c.alpha);
  // On the yield surface, within round-off, OpenSees already reports the
  // plastic tangent (checked against OpenSeesPy at turning points).
  if (f <= -std::numeric_limits<double>::epsilon() * E_) {
    trial_.stress = predictor;
    trial_.tangent = E_;
    return;
  }
  const double H = Hiso_ + Hkin_;
  const double dGamma = f / (E_ + H);
  const double sign = relative < 0.0 ? -1.0 : 1.0;
  trial_.stress = predictor - dGamma * E_ * sign;
  trial_.plasticStrain = c.plasticStrain + dGamma * sign;
  trial_.backStress = c.backStress + dGamma * Hkin_ * sign;
  trial_.alpha = c.alpha + dGamma;
  trial_.tangent = E_ * H / (E_ + H);
}

void HardeningMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Hardening E " << E_ << " sigmaY " << sigmaY_ << " Hiso " << Hiso_
     << " Hkin " << Hkin_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildHardening(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Hardening " + std::to_string(tag));
  const double E = args.nextDouble("E");
  const double sigmaY = args.nextDouble("sigmaY");
  const double Hiso = args.nextDouble("H_iso");
  const double Hkin = args.nextDouble("H_kin");
  if (!args.done()) args.nextDouble("eta");  // accepted and unused, as in OpenSees
  args.expectEnd();
  if (!(E > 0.0)) args.fail("E must be positive, got " + std::to_string(E));
  if (!(sigmaY >= 0.0)) args.fail("sigmaY must not be negative, got " + std::to_string(sigmaY));
  if (!(E + Hiso + Hkin > 0.0)) args.fail("E + H_iso + H_kin must be positive");
  return std::make_unique<HardeningMaterial>(tag, E, sigmaY, Hiso, Hkin);
}

void registerHardening(Registry& r) { r.uniaxialMaterials.add("Hardening", &buildHardening); }

}  // namespace

BEAMSOLID_REGISTER(registerHardening);

}  // namespace beamsolid
