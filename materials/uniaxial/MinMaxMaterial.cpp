#include "materials/uniaxial/MinMaxMaterial.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

MinMaxMaterial::MinMaxMaterial(int tag, const UniaxialMaterial& other, double minStrain, double maxStrain)
    : UniaxialMaterial(tag), other_(other), minStrain_(minStrain), maxStrain_(maxStrain) {}

std::unique_ptr<UniaxialMaterial> MinMaxMaterial::clone() const { return std::make_unique<MinMaxMaterial>(*this); }

void MinMaxMaterial::setTrialStrain(double strain, double strainRate) {
  strain_ = strain;
  trialFailed_ = committedFailed_ || strain <= minStrain_ || strain >= maxStrain_;
  if (!trialFailed_) other_->setTrialStrain(strain, strainRate);
}

double MinMaxMaterial::stress() const { return trialFailed_ ? 0.0 : other_->stress(); }

double MinMaxMaterial::tangent() const {
  return trialFailed_ ? 1.0e-8 * other_->initialTangent() : other_->tangent();
}

void MinMaxMaterial::commitState() {
  committedStrain_ = strain_;
  committedFailed_ = trialFailed_;
  if (!committedFailed_) other_->commitState();
}

void MinMaxMaterial::revertToLastCommit() {
  strain_ = committedStrain_;
  trialFailed_ = committedFailed_;
  other_->revertToLastCommit();
}

void MinMaxMaterial::revertToStart() {
  strain_ = committedStrain_ = 0.0;
  trialFailed_ = committedFailed_ = false;
  other_->revertToStart();
}

bool MinMaxMaterial::setParameter(const std::vector<std::string>& args, double value) {
  return other_->setParameter(args, value);
}

void MinMaxMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type MinMax material " << other_->tag() << " min " << minStrain_
     << " max " << maxStrain_ << (trialFailed_ ? " (failed)" : "") << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildMinMax(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial MinMax " + std::to_string(tag));
  const int otherTag = args.nextInt("otherTag");
  double minStrain = -1.0e16, maxStrain = 1.0e16;
  while (!args.done()) {
    if (args.nextFlag("-min"))
      minStrain = args.nextDouble("minStrain");
    else if (args.nextFlag("-max"))
      maxStrain = args.nextDouble("maxStrain");
    else
      args.failAt(args.position(), "option", "'-min' or '-max'");
  }
  if (!(minStrain < maxStrain))
    args.fail("minStrain (" + std::to_string(minStrain) + ") must be below maxStrain (" + std::to_string(maxStrain) +
              ")");
  return std::make_unique<MinMaxMaterial>(tag, domain.uniaxialMaterials.get(otherTag, args.context()), minStrain,
                                          maxStrain);
}

void registerMinMax(Registry& r) { r.uniaxialMaterials.add("MinMax", &buildMinMax); }

}  // namespace

BEAMSOLID_REGISTER(registerMinMax);

}  // namespace beamsolid
