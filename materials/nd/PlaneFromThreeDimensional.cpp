#include "materials/nd/PlaneFromThreeDimensional.h"

#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {

// Voigt slots of the in-plane [11, 22, 12] and out-of-plane [33, 23, 13]
// components in the 3D order [11, 22, 33, 12, 23, 13].
constexpr int kInPlane[3] = {0, 1, 3};
constexpr int kOutOfPlane[3] = {2, 4, 5};

}  // namespace

PlaneFromThreeDimensional::PlaneFromThreeDimensional(std::unique_ptr<NDMaterial> threeDimensional, Plane plane)
    : NDMaterial(threeDimensional->tag()), inner_(std::move(threeDimensional)), plane_(plane) {
  formInitialTangent();
  evaluate();
}

PlaneFromThreeDimensional::PlaneFromThreeDimensional(const PlaneFromThreeDimensional& other)
    : NDMaterial(other.tag()),
      inner_(other.inner_->clone("ThreeDimensional")),
      plane_(other.plane_),
      strain_(other.strain_),
      stress_(other.stress_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_),
      strain3D_(other.strain3D_),
      outOfPlane_(other.outOfPlane_),
      outOfPlaneCommitted_(other.outOfPlaneCommitted_),
      strainCommitted_(other.strainCommitted_) {}

std::string PlaneFromThreeDimensional::className() const {
  return inner_->className() + (plane_ == Plane::Strain ? "PlaneStrain" : "PlaneStress");
}

std::unique_ptr<NDMaterial> PlaneFromThreeDimensional::clone(const std::string& kind) const {
  if ((kind == "PlaneStrain" && plane_ == Plane::Strain) || (kind == "PlaneStress" && plane_ == Plane::Stress))
    return std::make_unique<PlaneFromThreeDimensional>(*this);
  if (kind == "ThreeDimensional") return inner_->clone(kind);
  return nullptr;
}

void PlaneFromThreeDimensional::formInitialTangent() {
  const Eigen::MatrixXd D = inner_->initialTangent();
  Matrix3 pp, pz, zp, zz;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      pp(i, j) = D(kInPlane[i], kInPlane[j]);
      pz(i, j) = D(kInPlane[i], kOutOfPlane[j]);
      zp(i, j) = D(kOutOfPlane[i], kInPlane[j]);
      zz(i, j) = D(kOutOfPlane[i], kOutOfPlane[j]);
    }
  initialTangent_ = plane_ == Plane::Strain ? pp : Matrix3(pp - pz * zz.partialPivLu().solve(zp));
}

void PlaneFromThreeDimensional::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 3)
    throw OpenSeesError("nDMaterial " + std::to_string(tag()) + " (" + className() +
                        "): expected a plane strain vector [e11, e22, g12] of size 3, got size " +
                        std::to_string(strain.size()));
  strain_ = strain;
  evaluate();
}

void PlaneFromThreeDimensional::evaluate() {
  for (int i = 0; i < 3; ++i) strain3D_(kInPlane[i]) = strain_(i);
  if (plane_ == Plane::Strain) outOfPlane_.setZero();
  for (int i = 0; i < 3; ++i) strain3D_(kOutOfPlane[i]) = outOfPlane_(i);
  inner_->setTrialStrain(strain3D_);

  Matrix3 pp, pz, zp, zz;
  auto blocks = [&] {
    const MatrixView D = inner_->tangent();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        pp(i, j) = D(kInPlane[i], kInPlane[j]);
        pz(i, j) = D(kInPlane[i], kOutOfPlane[j]);
        zp(i, j) = D(kOutOfPlane[i], kInPlane[j]);
        zz(i, j) = D(kOutOfPlane[i], kOutOfPlane[j]);
      }
  };
  blocks();
  if (plane_ == Plane::Stress) {
    // Newton on z for sigma_z(z) = 0; the scale is the elastic stress of the strain.
    const double scale = initialTangent_.norm() * (strain_.norm() + outOfPlane_.norm()) + 1e-300;
    bool converged = false;
    for (int it = 0; it < 50; ++it) {
      Vector3 residual;
      const VectorView s = inner_->stress();
      for (int i = 0; i < 3; ++i) residual(i) = s(kOutOfPlane[i]);
      if (residual.norm() <= 1e-13 * scale) {
        converged = true;
        break;
      }
      outOfPlane_ -= zz.partialPivLu().solve(residual);
      for (int i = 0; i < 3; ++i) strain3D_(kOutOfPlane[i]) = outOfPlane_(i);
      inner_->setTrialStrain(strain3D_);
      blocks();
    }
    if (!converged)
      throw ElementStateError("nDMaterial " + std::to_string(tag()) + " (" + className() +
                              "): the plane-stress condition sigma_33 = 0 did not converge");
  }
  const VectorView s = inner_->stress();
  for (int i = 0; i < 3; ++i) stress_(i) = s(kInPlane[i]);
  tangent_ = plane_ == Plane::Strain ? pp : Matrix3(pp - pz * zz.partialPivLu().solve(zp));
}

void PlaneFromThreeDimensional::commitState() {
  inner_->commitState();
  outOfPlaneCommitted_ = outOfPlane_;
  strainCommitted_ = strain_;
}

void PlaneFromThreeDimensional::revertToLastCommit() {
  inner_->revertToLastCommit();
  outOfPlane_ = outOfPlaneCommitted_;
  strain_ = strainCommitted_;
  evaluate();
}

void PlaneFromThreeDimensional::revertToStart() {
  inner_->revertToStart();
  outOfPlane_.setZero();
  outOfPlaneCommitted_.setZero();
  strain_.setZero();
  strainCommitted_.setZero();
  evaluate();
}

void PlaneFromThreeDimensional::updateStage(int stage) {
  inner_->updateStage(stage);
  evaluate();
}

bool PlaneFromThreeDimensional::setParameter(const std::vector<std::string>& args, double value) {
  const bool accepted = inner_->setParameter(args, value);
  if (accepted) {
    formInitialTangent();
    evaluate();
  }
  return accepted;
}

Response PlaneFromThreeDimensional::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "stress" || what == "stresses")
    return Response::named({"sigma11", "sigma22", "sigma12"}, [this] { return Vector(stress_); });
  if (what == "strain" || what == "strains")
    return Response::named({"eta11", "eta22", "eta12"}, [this] { return Vector(strain_); });
  if (what == "tangent") return NDMaterial::setResponse(args);
  if (what == "stress3D") return inner_->setResponse({"stress"});
  if (what == "strain3D") return inner_->setResponse({"strain"});
  return inner_->setResponse(args);
}

void PlaneFromThreeDimensional::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " (" << (plane_ == Plane::Strain ? "PlaneStrain" : "PlaneStress")
     << " form) of:\n  ";
  inner_->print(os);
}

}  // namespace beamsolid
