#include "materials/nd/ElasticIsotropic2D.h"

#include "core/OpenSeesError.h"

namespace beamsolid {

ElasticIsotropic2D::ElasticIsotropic2D(int tag, Plane plane, double E, double nu, double rho)
    : NDMaterial(tag), plane_(plane), E_(E), nu_(nu), rho_(rho) {
  formTangent();
}

std::string ElasticIsotropic2D::className() const {
  return plane_ == Plane::Strain ? "ElasticIsotropicPlaneStrain2D" : "ElasticIsotropicPlaneStress2D";
}

void ElasticIsotropic2D::formTangent() {
  D_.setZero();
  if (plane_ == Plane::Strain) {
    const double c = E_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
    D_(0, 0) = D_(1, 1) = c * (1.0 - nu_);
    D_(0, 1) = D_(1, 0) = c * nu_;
    D_(2, 2) = c * 0.5 * (1.0 - 2.0 * nu_);  // = G
  } else {
    const double c = E_ / (1.0 - nu_ * nu_);
    D_(0, 0) = D_(1, 1) = c;
    D_(0, 1) = D_(1, 0) = c * nu_;
    D_(2, 2) = c * 0.5 * (1.0 - nu_);  // = G
  }
  trialStress_.noalias() = D_ * trialStrain_;
}

std::unique_ptr<NDMaterial> ElasticIsotropic2D::clone(const std::string& kind) const {
  const Plane wanted = kind == "PlaneStrain" ? Plane::Strain : Plane::Stress;
  if ((kind != "PlaneStrain" && kind != "PlaneStress") || wanted != plane_) return nullptr;
  return std::make_unique<ElasticIsotropic2D>(*this);
}

void ElasticIsotropic2D::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 3)
    throw OpenSeesError("nDMaterial ElasticIsotropic " + std::to_string(tag()) +
                        ": expected a plane strain vector [e11, e22, g12] of size 3, got size " +
                        std::to_string(strain.size()));
  trialStrain_ = strain;
  trialStress_.noalias() = D_ * trialStrain_;
}

void ElasticIsotropic2D::commitState() { committedStrain_ = trialStrain_; }

void ElasticIsotropic2D::revertToLastCommit() {
  trialStrain_ = committedStrain_;
  trialStress_.noalias() = D_ * trialStrain_;
}

void ElasticIsotropic2D::revertToStart() {
  trialStrain_.setZero();
  committedStrain_.setZero();
  trialStress_.setZero();
}

bool ElasticIsotropic2D::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  const std::string context = "nDMaterial ElasticIsotropic " + std::to_string(tag()) + ": ";
  if (args[0] == "E" || args[0] == "nu") {
    const double E = args[0] == "E" ? value : E_;
    const double nu = args[0] == "nu" ? value : nu_;
    if (!(E > 0.0)) throw OpenSeesError(context + "E must be positive, got " + std::to_string(E));
    if (!(nu > -1.0 && nu < 0.5))
      throw OpenSeesError(context + "nu must satisfy -1 < nu < 0.5, got " + std::to_string(nu));
    E_ = E;
    nu_ = nu;
    formTangent();
    return true;
  }
  if (args[0] == "rho") {
    rho_ = value;
    return true;
  }
  return false;
}

Response ElasticIsotropic2D::setResponse(const std::vector<std::string>& args) {
  if (!args.empty() && (args[0] == "stress" || args[0] == "stresses"))
    return Response::named({"sigma11", "sigma22", "sigma12"}, [this] { return Vector(trialStress_); });
  if (!args.empty() && (args[0] == "strain" || args[0] == "strains"))
    return Response::named({"eta11", "eta22", "eta12"}, [this] { return Vector(trialStrain_); });
  return NDMaterial::setResponse(args);
}

void ElasticIsotropic2D::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type ElasticIsotropic (" << (plane_ == Plane::Strain ? "PlaneStrain" : "PlaneStress")
     << ") E " << E_ << " nu " << nu_ << " rho " << rho_ << '\n';
}

}  // namespace beamsolid
