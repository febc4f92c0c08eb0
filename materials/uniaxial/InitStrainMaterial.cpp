#include "materials/uniaxial/InitStrainMaterial.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

InitStrainMaterial::InitStrainMaterial(int tag, const UniaxialMaterial& other, double initialStrain)
    : UniaxialMaterial(tag), other_(other), initialStrain_(initialStrain) {
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> InitStrainMaterial::clone() const {
  return std::make_unique<InitStrainMaterial>(*this);
}

void InitStrainMaterial::setTrialStrain(double strain, double strainRate) {
  strain_ = strain;
  other_->setTrialStrain(strain + initialStrain_, strainRate);
}

void InitStrainMaterial::commitState() {
  committedStrain_ = strain_;
  other_->commitState();
}

void InitStrainMaterial::revertToLastCommit() {
  strain_ = committedStrain_;
  other_->revertToLastCommit();
}

void InitStrainMaterial::revertToStart() {
  strain_ = committedStrain_ = 0.0;
  other_->revertToStart();
  other_->setTrialStrain(initialStrain_);
  other_->commitState();
}

bool InitStrainMaterial::setParameter(const std::vector<std::string>& args, double value) {
  if (args.size() == 1 && (args[0] == "initStrain" || args[0] == "eps0")) {
    initialStrain_ = value;
    other_->setTrialStrain(strain_ + initialStrain_);
    return true;
  }
  return other_->setParameter(args, value);
}

void InitStrainMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type InitStrainMaterial material " << other_->tag() << " eps0 "
     << initialStrain_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildInitStrain(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext(args.command() + " InitStrainMaterial " + std::to_string(tag));
  const int otherTag = args.nextInt("otherTag");
  const double eps0 = args.nextDouble("initStrain");
  args.expectEnd();
  return std::make_unique<InitStrainMaterial>(tag, domain.uniaxialMaterials.get(otherTag, args.context()), eps0);
}

void registerInitStrain(Registry& r) {
  r.uniaxialMaterials.add("InitStrainMaterial", &buildInitStrain);
  r.uniaxialMaterials.add("InitStrain", &buildInitStrain);
}

}  // namespace

BEAMSOLID_REGISTER(registerInitStrain);

}  // namespace beamsolid
