#include "materials/nd/InitialStateAnalysisWrapper.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

InitialStateAnalysisWrapper::InitialStateAnalysisWrapper(int tag, std::unique_ptr<NDMaterial> inner)
    : NDMaterial(tag),
      inner_(std::move(inner)),
      initialStrain_(Vector::Zero(inner_->strain().size())),
      totalStrain_(initialStrain_) {}

std::unique_ptr<NDMaterial> InitialStateAnalysisWrapper::clone(const std::string& kind) const {
  if (kind != "ThreeDimensional") return nullptr;
  std::unique_ptr<NDMaterial> inner = inner_->clone(kind);
  if (!inner) return nullptr;
  auto copy = std::make_unique<InitialStateAnalysisWrapper>(tag(), std::move(inner));
  copy->initialStrain_ = initialStrain_;
  return copy;
}

void InitialStateAnalysisWrapper::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != initialStrain_.size())
    throw OpenSeesError("nDMaterial InitialStateAnalysisWrapper " + std::to_string(tag()) +
                        ": expected a strain vector of size " + std::to_string(initialStrain_.size()) + ", got " +
                        std::to_string(strain.size()));
  totalStrain_.noalias() = strain + initialStrain_;
  inner_->setTrialStrain(totalStrain_);
}

void InitialStateAnalysisWrapper::revertToStart() {
  inner_->revertToStart();
  initialStrain_.setZero();
}

void InitialStateAnalysisWrapper::initialStateAnalysis(bool on) {
  // 'off' comes after a converged (committed) stage: its strain becomes the
  // reference the zeroed displacements are measured from.
  if (!on) initialStrain_ = inner_->strain();
  inner_->initialStateAnalysis(on);
}

void InitialStateAnalysisWrapper::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type InitialStateAnalysisWrapper of:\n  ";
  inner_->print(os);
}

namespace {

std::unique_ptr<NDMaterial> buildInitialStateAnalysisWrapper(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial InitialStateAnalysisWrapper " + std::to_string(tag));
  const int innerTag = args.nextInt("nDMatTag");
  const int nDim = args.nextInt("nDim");
  args.expectEnd();
  if (nDim != 3) args.fail("nDim must be 3 (three-dimensional solids), got " + std::to_string(nDim));
  if (innerTag == tag) args.fail("nDMatTag must name another material, got its own tag " + std::to_string(tag));
  const NDMaterial* inner = domain.ndMaterials.find(innerTag);
  if (!inner) args.fail("nDMatTag: nDMaterial " + std::to_string(innerTag) + " does not exist");
  std::unique_ptr<NDMaterial> copy = inner->clone("ThreeDimensional");
  if (!copy)
    args.fail("nDMatTag: nDMaterial " + std::to_string(innerTag) + " (" + inner->className() +
              ") has no three-dimensional form");
  return std::make_unique<InitialStateAnalysisWrapper>(tag, std::move(copy));
}

void registerInitialStateAnalysisWrapper(Registry& r) {
  r.ndMaterials.add("InitialStateAnalysisWrapper", &buildInitialStateAnalysisWrapper);
}

}  // namespace

BEAMSOLID_REGISTER(registerInitialStateAnalysisWrapper);

}  // namespace beamsolid
