#include "materials/nd/ElasticIsotropic3D.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "materials/nd/ElasticIsotropic2D.h"

namespace beamsolid {

namespace {

// Returns an empty string when (E, nu) describe a stable isotropic solid.
std::string checkElasticConstants(double E, double nu) {
  if (!(E > 0.0)) return "E must be positive, got " + std::to_string(E);
  if (!(nu > -1.0 && nu < 0.5)) return "nu must satisfy -1 < nu < 0.5, got " + std::to_string(nu);
  return {};
}

}  // namespace

ElasticIsotropic3D::ElasticIsotropic3D(int tag, double E, double nu, double rho)
    : NDMaterial(tag), E_(E), nu_(nu), rho_(rho) {
  const std::string problem = checkElasticConstants(E, nu);
  if (!problem.empty())
    throw OpenSeesError("nDMaterial ElasticIsotropic " + std::to_string(tag) + ": " + problem);
  formTangent();
}

void ElasticIsotropic3D::formTangent() {
  const double G = E_ / (2.0 * (1.0 + nu_));
  const double lambda = E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  D_.setZero();
  D_.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) {
    D_(i, i) = lambda + 2.0 * G;
    D_(i + 3, i + 3) = G;
  }
  trialStress_.noalias() = D_ * trialStrain_;
}

std::unique_ptr<NDMaterial> ElasticIsotropic3D::clone(const std::string& kind) const {
  if (kind == "ThreeDimensional") return std::make_unique<ElasticIsotropic3D>(*this);
  // Quad elements ask for the plane forms, as in OpenSees.
  if (kind == "PlaneStrain")
    return std::make_unique<ElasticIsotropic2D>(tag(), ElasticIsotropic2D::Plane::Strain, E_, nu_, rho_);
  if (kind == "PlaneStress")
    return std::make_unique<ElasticIsotropic2D>(tag(), ElasticIsotropic2D::Plane::Stress, E_, nu_, rho_);
  return nullptr;
}

void ElasticIsotropic3D::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 6)
    throw OpenSeesError("nDMaterial ElasticIsotropic " + std::to_string(tag()) +
                        ": expected a strain vector of size 6, got " + std::to_string(strain.size()));
  trialStrain_ = strain;
  trialStress_.noalias() = D_ * trialStrain_;
}

void ElasticIsotropic3D::commitState() { committedStrain_ = trialStrain_; }

void ElasticIsotropic3D::revertToLastCommit() {
  trialStrain_ = committedStrain_;
  trialStress_.noalias() = D_ * trialStrain_;
}

void ElasticIsotropic3D::revertToStart() {
  trialStrain_.setZero();
  committedStrain_.setZero();
  trialStress_.setZero();
}

bool ElasticIsotropic3D::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  const std::string context = "nDMaterial ElasticIsotropic " + std::to_string(tag()) + ": ";
  if (args[0] == "E" || args[0] == "nu") {
    const double E = args[0] == "E" ? value : E_;
    const double nu = args[0] == "nu" ? value : nu_;
    const std::string problem = checkElasticConstants(E, nu);
    if (!problem.empty()) throw OpenSeesError(context + problem);
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

void ElasticIsotropic3D::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type ElasticIsotropic E " << E_ << " nu " << nu_ << " rho " << rho_ << '\n';
}

namespace {

std::unique_ptr<NDMaterial> buildElasticIsotropic(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial ElasticIsotropic " + std::to_string(tag));
  const double E = args.nextDouble("E");
  const double nu = args.nextDouble("nu");
  const double rho = args.done() ? 0.0 : args.nextDouble("rho");
  args.expectEnd();
  const std::string problem = checkElasticConstants(E, nu);
  if (!problem.empty()) args.fail(problem);
  return std::make_unique<ElasticIsotropic3D>(tag, E, nu, rho);
}

void registerElasticIsotropic(Registry& r) {
  r.ndMaterials.add("ElasticIsotropic", &buildElasticIsotropic);
  // Older scripts name the three-dimensional form directly.
  r.ndMaterials.add("ElasticIsotropic3D", &buildElasticIsotropic);
}

}  // namespace

BEAMSOLID_REGISTER(registerElasticIsotropic);

}  // namespace beamsolid
