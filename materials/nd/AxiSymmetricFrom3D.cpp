#include "materials/nd/AxiSymmetricFrom3D.h"

#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {
// The Voigt rows of the 3D vector [11 22 33 12 23 13] that the AxiSymmetric
// vector [11 22 33 12] keeps.
constexpr int kRows[4] = {0, 1, 2, 3};
}  // namespace

AxiSymmetricFrom3D::AxiSymmetricFrom3D(std::unique_ptr<NDMaterial> threeDimensional)
    : NDMaterial(threeDimensional->tag()), solid_(std::move(threeDimensional)) {
  readBack();
}

std::unique_ptr<NDMaterial> AxiSymmetricFrom3D::copyOf(const NDMaterial& material) {
  if (auto own = material.clone("AxiSymmetric")) return own;
  if (auto solid = material.clone("ThreeDimensional")) return std::make_unique<AxiSymmetricFrom3D>(std::move(solid));
  return nullptr;
}

AxiSymmetricFrom3D::AxiSymmetricFrom3D(const AxiSymmetricFrom3D& other)
    : NDMaterial(other.tag()),
      solid_(other.solid_->clone("ThreeDimensional")),
      strain_(other.strain_),
      stress_(other.stress_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_) {}

std::unique_ptr<NDMaterial> AxiSymmetricFrom3D::clone(const std::string& kind) const {
  if (kind == "AxiSymmetric") return std::make_unique<AxiSymmetricFrom3D>(*this);
  return solid_->clone(kind);
}

void AxiSymmetricFrom3D::readBack() {
  const VectorView s = solid_->stress();
  const MatrixView D = solid_->tangent();
  const MatrixView D0 = solid_->initialTangent();
  for (int i = 0; i < 4; ++i) {
    stress_(i) = s(kRows[i]);
    for (int j = 0; j < 4; ++j) {
      tangent_(i, j) = D(kRows[i], kRows[j]);
      initialTangent_(i, j) = D0(kRows[i], kRows[j]);
    }
  }
}

void AxiSymmetricFrom3D::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 4)
    throw OpenSeesError("nDMaterial " + std::to_string(tag()) + " (" + className() +
                        ", AxiSymmetric form): expected a strain [e11, e22, e33, g12] of size 4, got size " +
                        std::to_string(strain.size()));
  strain_ = strain;
  Eigen::Matrix<double, 6, 1> full = Eigen::Matrix<double, 6, 1>::Zero();
  for (int i = 0; i < 4; ++i) full(kRows[i]) = strain_(i);
  solid_->setTrialStrain(full);
  readBack();
}

void AxiSymmetricFrom3D::revertToLastCommit() {
  solid_->revertToLastCommit();
  const VectorView e = solid_->strain();
  for (int i = 0; i < 4; ++i) strain_(i) = e(kRows[i]);
  readBack();
}

void AxiSymmetricFrom3D::revertToStart() {
  solid_->revertToStart();
  strain_.setZero();
  readBack();
}

void AxiSymmetricFrom3D::updateStage(int stage) {
  solid_->updateStage(stage);
  readBack();
}

void AxiSymmetricFrom3D::initialStateAnalysis(bool on) {
  solid_->initialStateAnalysis(on);
  readBack();
}

bool AxiSymmetricFrom3D::setParameter(const std::vector<std::string>& args, double value) {
  const bool accepted = solid_->setParameter(args, value);
  if (accepted) {
    // A new modulus changes the stress at the same strain.
    Eigen::Matrix<double, 6, 1> full = Eigen::Matrix<double, 6, 1>::Zero();
    for (int i = 0; i < 4; ++i) full(kRows[i]) = strain_(i);
    solid_->setTrialStrain(full);
    readBack();
  }
  return accepted;
}

Response AxiSymmetricFrom3D::setResponse(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "stress" || args[0] == "stresses"))
    return Response::named({"sigma11", "sigma22", "sigma33", "sigma12"}, [this] { return Vector(stress_); });
  if (!args.empty() && (args[0] == "strain" || args[0] == "strains"))
    return Response::named({"eta11", "eta22", "eta33", "eta12"}, [this] { return Vector(strain_); });
  if (!args.empty() && args[0] == "tangent") return NDMaterial::setResponse(args);
  return solid_->setResponse(args);
}

}  // namespace beamsolid
