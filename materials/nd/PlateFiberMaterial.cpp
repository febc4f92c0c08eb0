#include "materials/nd/PlateFiberMaterial.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {
// Voigt slots of the fiber's [11, 22, 12, 23, 31] in the 3D order
// [11, 22, 33, 12, 23, 13]; the normal 33 is solved for.
constexpr int kFiber[5] = {0, 1, 3, 4, 5};
constexpr int kNormal = 2;
}  // namespace

PlateFiberMaterial::PlateFiberMaterial(int tag, std::unique_ptr<NDMaterial> threeDimensional)
    : NDMaterial(tag), inner_(std::move(threeDimensional)) {
  const Eigen::MatrixXd D = inner_->initialTangent();
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      initialTangent_(i, j) = D(kFiber[i], kFiber[j]) - D(kFiber[i], kNormal) * D(kNormal, kFiber[j]) / D(kNormal, kNormal);
  evaluate();
}

PlateFiberMaterial::PlateFiberMaterial(const PlateFiberMaterial& other)
    : NDMaterial(other.tag()),
      inner_(other.inner_->clone("ThreeDimensional")),
      strain_(other.strain_),
      stress_(other.stress_),
      strainCommitted_(other.strainCommitted_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_),
      e33_(other.e33_),
      e33Committed_(other.e33Committed_),
      strain3D_(other.strain3D_) {}

std::unique_ptr<NDMaterial> PlateFiberMaterial::clone(const std::string& kind) const {
  if (kind == "PlateFiber") return std::make_unique<PlateFiberMaterial>(*this);
  if (kind == "ThreeDimensional") return inner_->clone(kind);
  return nullptr;
}

void PlateFiberMaterial::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 5)
    throw OpenSeesError("nDMaterial PlateFiber " + std::to_string(tag()) +
                        ": expected a plate fiber strain [e11, e22, g12, g23, g31] of size 5, got size " +
                        std::to_string(strain.size()));
  strain_ = strain;
  evaluate();
}

void PlateFiberMaterial::evaluate() {
  for (int i = 0; i < 5; ++i) strain3D_(kFiber[i]) = strain_(i);
  strain3D_(kNormal) = e33_;
  inner_->setTrialStrain(strain3D_);
  // Newton on e33 for s33 = 0; the scale is the elastic stress of the strain.
  const double scale = initialTangent_.norm() * (strain_.norm() + std::fabs(e33_)) + 1e-300;
  bool converged = false;
  for (int it = 0; it < 50; ++it) {
    const double residual = inner_->stress()(kNormal);
    if (std::fabs(residual) <= 1e-13 * scale) {
      converged = true;
      break;
    }
    e33_ -= residual / inner_->tangent()(kNormal, kNormal);
    strain3D_(kNormal) = e33_;
    inner_->setTrialStrain(strain3D_);
  }
  if (!converged)
    throw ElementStateError("nDMaterial PlateFiber " + std::to_string(tag()) +
                            ": the plate condition sigma_33 = 0 did not converge");
  const VectorView s = inner_->stress();
  const MatrixView D = inner_->tangent();
  for (int i = 0; i < 5; ++i) {
    stress_(i) = s(kFiber[i]);
    for (int j = 0; j < 5; ++j)
      tangent_(i, j) = D(kFiber[i], kFiber[j]) - D(kFiber[i], kNormal) * D(kNormal, kFiber[j]) / D(kNormal, kNormal);
  }
}

void PlateFiberMaterial::commitState() {
  inner_->commitState();
  e33Committed_ = e33_;
  strainCommitted_ = strain_;
}

void PlateFiberMaterial::revertToLastCommit() {
  inner_->revertToLastCommit();
  e33_ = e33Committed_;
  strain_ = strainCommitted_;
  evaluate();
}

void PlateFiberMaterial::revertToStart() {
  inner_->revertToStart();
  e33_ = e33Committed_ = 0.0;
  strain_.setZero();
  strainCommitted_.setZero();
  evaluate();
}

void PlateFiberMaterial::updateStage(int stage) {
  inner_->updateStage(stage);
  evaluate();
}

Response PlateFiberMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  if (args[0] == "stress" || args[0] == "stresses")
    return Response::named({"sigma11", "sigma22", "sigma12", "sigma23", "sigma31"}, [this] { return Vector(stress_); });
  if (args[0] == "strain" || args[0] == "strains")
    return Response::named({"eps11", "eps22", "gamma12", "gamma23", "gamma31"}, [this] { return Vector(strain_); });
  return inner_->setResponse(args);
}

namespace {

std::unique_ptr<NDMaterial> buildPlateFiber(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial PlateFiber " + std::to_string(tag));
  const int inner = args.nextInt("mat3DTag");
  args.expectEnd();
  const NDMaterial& threeDimensional = domain.ndMaterials.get(inner, args.context());
  auto copy = threeDimensional.clone("ThreeDimensional");
  if (!copy)
    args.fail("nDMaterial " + std::to_string(inner) + " (" + threeDimensional.className() +
              ") is not a three-dimensional material");
  return std::make_unique<PlateFiberMaterial>(tag, std::move(copy));
}

void registerPlateFiber(Registry& r) { r.ndMaterials.add("PlateFiber", &buildPlateFiber); }

}  // namespace

BEAMSOLID_REGISTER(registerPlateFiber);

}  // namespace beamsolid
