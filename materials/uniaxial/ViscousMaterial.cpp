#include "materials/uniaxial/ViscousMaterial.h"

#include <algorithm>
#include <cmath>

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {
constexpr double kMinRate = 1e-11;
}

ViscousMaterial::ViscousMaterial(int tag, double C, double alpha) : UniaxialMaterial(tag), C_(C), alpha_(alpha) {}

std::unique_ptr<UniaxialMaterial> ViscousMaterial::clone() const { return std::make_unique<ViscousMaterial>(*this); }

void ViscousMaterial::setTrialStrain(double strain, double strainRate) {
  trialStrain_ = strain;
  trialRate_ = strainRate;
}

double ViscousMaterial::stress() const {
  if (trialRate_ == 0.0) return 0.0;
  return std::copysign(C_ * std::pow(std::fabs(trialRate_), alpha_), trialRate_);
}

double ViscousMaterial::dampingTangent() const {
  if (alpha_ == 1.0) return C_;
  return alpha_ * C_ * std::pow(std::max(std::fabs(trialRate_), kMinRate), alpha_ - 1.0);
}

void ViscousMaterial::commitState() {
  committedStrain_ = trialStrain_;
  committedRate_ = trialRate_;
}

void ViscousMaterial::revertToLastCommit() {
  trialStrain_ = committedStrain_;
  trialRate_ = committedRate_;
}

void ViscousMaterial::revertToStart() {
  trialStrain_ = trialRate_ = committedStrain_ = committedRate_ = 0.0;
}

void ViscousMaterial::print(std::ostream& os) const {
  os << "Viscous tag: " << tag() << " C: " << C_ << " alpha: " << alpha_ << "\n";
}

namespace {
std::unique_ptr<UniaxialMaterial> buildViscousMaterial(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Viscous " + std::to_string(tag));
  const double C = args.nextDouble("C");
  const double alpha = args.nextDouble("alpha");
  args.expectEnd();
  if (!(C >= 0.0)) args.fail("C must be non-negative, got " + std::to_string(C));
  if (!(alpha > 0.0)) args.fail("alpha must be positive, got " + std::to_string(alpha));
  return std::make_unique<ViscousMaterial>(tag, C, alpha);
}
void registerViscousMaterial(Registry& r) { r.uniaxialMaterials.add("Viscous", &buildViscousMaterial); }
}  // namespace
BEAMSOLID_REGISTER(registerViscousMaterial);

}  // namespace beamsolid
