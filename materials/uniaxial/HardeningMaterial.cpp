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
  sensitivity_.clear();
  committed_ = State{};
  committed_.tangent = E_;
  trial_ = committed_;
}

void HardeningMaterial::setTrialStrain(double strain, double) {
  // Every trial starts from the committed plastic state (no accumulation
  // over the iterations of one step).
  const State& c = committed_;
  trial_ = c;
  trial_.branch = Branch::Unchanged;
  // A change below machine epsilon is no change (as OpenSees, found by running it): the
  // committed state, strain and tangent stay, so round-off in a fiber's strain cannot pick a
  // branch, nor can such changes add up.
  if (std::fabs(strain - c.strain) < std::numeric_limits<double>::epsilon()) return;
  trial_.strain = strain;
  trial_.branch = Branch::Elastic;
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
  trial_.branch = Branch::Plastic;
  trial_.dGamma = dGamma;
  trial_.sign = sign;
}

bool HardeningMaterial::setParameter(const std::vector<std::string>& args, double value) {
  switch (sensitivityParameter(args)) {
    case 1: E_ = value; return true;
    case 2: sigmaY_ = value; return true;
    case 3: Hiso_ = value; return true;
    case 4: Hkin_ = value; return true;
    default: return false;
  }
}

int HardeningMaterial::sensitivityParameter(const std::vector<std::string>& args) {
  if (args.empty()) return 0;
  const std::string& n = args[0];
  if (n == "E") return 1;
  if (n == "sigmaY" || n == "Fy" || n == "fy") return 2;
  if (n == "H_iso" || n == "Hiso") return 3;
  if (n == "H_kin" || n == "Hkin") return 4;
  return 0;
}

// The return map of setTrialStrain differentiated with respect to theta,
// the branch it took held fixed (Kleiber et al., Parameter Sensitivity in
// Nonlinear Mechanics, 1997: the direct differentiation method).
HardeningMaterial::Sensitivity HardeningMaterial::trialSensitivity(double dStrain, int gradient,
                                                                   int parameterId) const {
  const Sensitivity dc = gradient < static_cast<int>(sensitivity_.size()) ? sensitivity_[gradient] : Sensitivity{};
  if (trial_.branch == Branch::Unchanged) return dc;
  const double dE = parameterId == 1 ? 1.0 : 0.0, dSigmaY = parameterId == 2 ? 1.0 : 0.0;
  const double dHiso = parameterId == 3 ? 1.0 : 0.0, dHkin = parameterId == 4 ? 1.0 : 0.0;
  const State& c = committed_;
  Sensitivity d = dc;
  const double dPredictor = dE * (trial_.strain - c.plasticStrain) + E_ * (dStrain - dc.plasticStrain);
  if (trial_.branch == Branch::Elastic) {
    d.stress = dPredictor;
    return d;
  }
  const double sign = trial_.sign, dGamma = trial_.dGamma;
  const double H = Hiso_ + Hkin_;
  const double dF = sign * (dPredictor - dc.backStress) - (dSigmaY + dHiso * c.alpha + Hiso_ * dc.alpha);
  const double dDGamma = (dF - dGamma * (dE + dHiso + dHkin)) / (E_ + H);
  d.stress = dPredictor - (dDGamma * E_ + dGamma * dE) * sign;
  d.plasticStrain = dc.plasticStrain + dDGamma * sign;
  d.backStress = dc.backStress + (dDGamma * Hkin_ + dGamma * dHkin) * sign;
  d.alpha = dc.alpha + dDGamma;
  return d;
}

double HardeningMaterial::stressSensitivity(int gradient, int parameterId) {
  return trialSensitivity(0.0, gradient, parameterId).stress;
}

void HardeningMaterial::commitSensitivity(double strainSensitivity, int gradient, int parameterId,
                                          int numGradients) {
  const Sensitivity d = trialSensitivity(strainSensitivity, gradient, parameterId);
  if (static_cast<int>(sensitivity_.size()) < numGradients) sensitivity_.resize(numGradients);
  sensitivity_.at(gradient) = d;
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
