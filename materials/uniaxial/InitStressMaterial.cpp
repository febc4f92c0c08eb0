#include "materials/uniaxial/InitStressMaterial.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

InitStressMaterial::InitStressMaterial(int tag, const UniaxialMaterial& other, double initialStress,
                                       const std::string& context)
    : UniaxialMaterial(tag), other_(other), initialStress_(initialStress) {
  other_->revertToStart();
  // Newton on the trial strain, every trial from the virgin state.
  double eps = 0.0;
  other_->setTrialStrain(eps);
  const double scale = std::max(std::abs(initialStress), 1.0e-300);
  bool converged = std::abs(other_->stress() - initialStress) <= 1.0e-14 * scale;
  for (int k = 0; k < 100 && !converged; ++k) {
    const double k_t = other_->tangent() != 0.0 ? other_->tangent() : other_->initialTangent();
    if (k_t == 0.0) break;
    eps += (initialStress - other_->stress()) / k_t;
    other_->setTrialStrain(eps);
    converged = std::abs(other_->stress() - initialStress) <= 1.0e-14 * scale;
  }
  if (!converged)
    throw OpenSeesError(context + ": material " + std::to_string(other.tag()) + " reaches no strain with stress " +
                        std::to_string(initialStress));
  initialStrain_ = eps;
  other_->commitState();
}

std::unique_ptr<UniaxialMaterial> InitStressMaterial::clone() const {
  return std::make_unique<InitStressMaterial>(*this);
}

void InitStressMaterial::setTrialStrain(double strain, double strainRate) {
  strain_ = strain;
  other_->setTrialStrain(strain + initialStrain_, strainRate);
}

void InitStressMaterial::commitState() {
  committedStrain_ = strain_;
  other_->commitState();
}

void InitStressMaterial::revertToLastCommit() {
  strain_ = committedStrain_;
  other_->revertToLastCommit();
}

void InitStressMaterial::revertToStart() {
  strain_ = committedStrain_ = 0.0;
  other_->revertToStart();
  other_->setTrialStrain(initialStrain_);
  other_->commitState();
}

void InitStressMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type InitStressMaterial material " << other_->tag() << " sigma0 "
     << initialStress_ << " eps0 " << initialStrain_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildInitStress(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial InitStressMaterial " + std::to_string(tag));
  const int otherTag = args.nextInt("otherTag");
  const double sigma0 = args.nextDouble("initStress");
  args.expectEnd();
  return std::make_unique<InitStressMaterial>(tag, domain.uniaxialMaterials.get(otherTag, args.context()), sigma0,
                                              args.context());
}

void registerInitStress(Registry& r) { r.uniaxialMaterials.add("InitStressMaterial", &buildInitStress); }

}  // namespace

BEAMSOLID_REGISTER(registerInitStress);

}  // namespace beamsolid
