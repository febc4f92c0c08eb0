#include "materials/nd/J2Plasticity.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "materials/nd/PlaneFromThreeDimensional.h"

namespace beamsolid {

namespace {

const double kSqrt23 = std::sqrt(2.0 / 3.0);

std::string checkParameters(const J2Plasticity::Parameters& p) {
  if (!(p.K > 0.0)) return "K must be positive, got " + std::to_string(p.K);
  if (!(p.G > 0.0)) return "G must be positive, got " + std::to_string(p.G);
  if (!(p.sig0 > 0.0)) return "sig0 must be positive, got " + std::to_string(p.sig0);
  if (!(p.sigInf > 0.0)) return "sigInf must be positive, got " + std::to_string(p.sigInf);
  if (!(p.delta >= 0.0)) return "delta must be >= 0, got " + std::to_string(p.delta);
  if (!(p.H >= 0.0)) return "H must be >= 0, got " + std::to_string(p.H);
  if (!(p.kinematicH >= 0.0)) return "-kinematic Hkin must be >= 0, got " + std::to_string(p.kinematicH);
  return {};
}

}  // namespace

J2Plasticity::J2Plasticity(int tag, const Parameters& p) : NDMaterial(tag), p_(p) {
  const std::string problem = checkParameters(p_);
  if (!problem.empty()) throw OpenSeesError("nDMaterial J2Plasticity " + std::to_string(tag) + ": " + problem);
  elastic_ = voigt::isotropicElasticity(p_.K, p_.G);
  tangent_ = elastic_;
  tangentCommitted_ = elastic_;
}

std::unique_ptr<NDMaterial> J2Plasticity::clone(const std::string& kind) const {
  if (kind == "ThreeDimensional") return std::make_unique<J2Plasticity>(*this);
  if (kind == "PlaneStrain" || kind == "PlaneStress")
    return std::make_unique<PlaneFromThreeDimensional>(
        std::make_unique<J2Plasticity>(*this),
        kind == "PlaneStrain" ? PlaneFromThreeDimensional::Plane::Strain : PlaneFromThreeDimensional::Plane::Stress);
  return nullptr;
}

double J2Plasticity::yieldStress(double xi) const {
  return p_.sig0 + (p_.sigInf - p_.sig0) * (1.0 - std::exp(-p_.delta * xi)) + p_.H * xi;
}

double J2Plasticity::hardeningModulus(double xi) const {
  return (p_.sigInf - p_.sig0) * p_.delta * std::exp(-p_.delta * xi) + p_.H;
}

void J2Plasticity::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 6)
    throw OpenSeesError("nDMaterial J2Plasticity " + std::to_string(tag()) +
                        ": expected a strain vector of size 6, got " + std::to_string(strain.size()));
  strain_ = strain;
  integrate();
}

// Radial return from the committed state (docs/soil_materials.md, J2).
void J2Plasticity::integrate() {
  plasticStrainTrial_ = plasticStrainCommitted_;
  backStressTrial_ = backStressCommitted_;
  xiTrial_ = xiCommitted_;

  const Vector6 one = voigt::identity();
  const double pressure = p_.K * voigt::trace(strain_);
  const Vector6 deviatoricTrial = 2.0 * p_.G * (voigt::strainDeviatorAsTensor(strain_) - plasticStrainCommitted_);
  tangent_ = elastic_;
  stress_ = deviatoricTrial + pressure * one;
  if (stage_ == 0) return;

  const Vector6 relative = deviatoricTrial - backStressCommitted_;
  const double relativeNorm = voigt::norm(relative);
  const double radius = kSqrt23 * yieldStress(xiCommitted_);
  if (!std::isfinite(relativeNorm))
    throw ElementStateError("nDMaterial J2Plasticity " + std::to_string(tag()) +
                            ": the trial strain is not finite (the Newton iteration diverged)");
  // Round-off on the surface (a converged plastic state re-evaluated) stays elastic.
  if (relativeNorm - radius <= 1e-12 * radius) return;

  // Scalar consistency g(dgamma) = 0, decreasing in dgamma: safeguarded Newton.
  const double twoG = 2.0 * p_.G;
  const double kin = 2.0 / 3.0 * p_.kinematicH;
  auto g = [&](double dg) { return relativeNorm - (twoG + kin) * dg - kSqrt23 * yieldStress(xiCommitted_ + kSqrt23 * dg); };
  double lower = 0.0, upper = relativeNorm / (twoG + kin);
  double dgamma = (relativeNorm - radius) / (twoG + kin + 2.0 / 3.0 * hardeningModulus(xiCommitted_));
  bool converged = false;
  for (int it = 0; it < 100; ++it) {
    if (!(dgamma > lower && dgamma < upper)) dgamma = 0.5 * (lower + upper);
    const double r = g(dgamma);
    if (r > 0.0) lower = dgamma;
    else upper = dgamma;
    const double slope = -(twoG + kin) - 2.0 / 3.0 * hardeningModulus(xiCommitted_ + kSqrt23 * dgamma);
    const double step = -r / slope;
    dgamma += step;
    if (std::abs(step) <= 1e-15 * dgamma || std::abs(r) <= 1e-15 * relativeNorm) {
      converged = true;
      break;
    }
  }
  if (!converged || !(dgamma > 0.0))
    throw ElementStateError("nDMaterial J2Plasticity " + std::to_string(tag()) +
                            ": the radial return did not converge (softening beyond the elastic stiffness?)");

  const Vector6 n = relative / relativeNorm;
  plasticStrainTrial_ += dgamma * n;
  backStressTrial_ += kin * dgamma * n;
  xiTrial_ = xiCommitted_ + kSqrt23 * dgamma;
  stress_ -= twoG * dgamma * n;

  // Consistent tangent: C = K 1(x)1 + 2G theta P_dev - 2G thetaBar n(x)n.
  const double theta = 1.0 - twoG * dgamma / relativeNorm;
  const double thetaBar = 1.0 / (1.0 + (hardeningModulus(xiTrial_) + p_.kinematicH) / (3.0 * p_.G)) - (1.0 - theta);
  tangent_ = p_.K * one * one.transpose() + twoG * theta * voigt::deviatoricProjector() -
             twoG * thetaBar * n * n.transpose();
}

void J2Plasticity::commitState() {
  plasticStrainCommitted_ = plasticStrainTrial_;
  backStressCommitted_ = backStressTrial_;
  xiCommitted_ = xiTrial_;
  strainCommitted_ = strain_;
  stressCommitted_ = stress_;
  tangentCommitted_ = tangent_;
  committedAnswerValid_ = true;
}

void J2Plasticity::revertToLastCommit() {
  strain_ = strainCommitted_;
  if (!committedAnswerValid_) {
    integrate();
    return;
  }
  stress_ = stressCommitted_;
  tangent_ = tangentCommitted_;
  plasticStrainTrial_ = plasticStrainCommitted_;
  backStressTrial_ = backStressCommitted_;
  xiTrial_ = xiCommitted_;
}

void J2Plasticity::revertToStart() {
  plasticStrainCommitted_.setZero();
  backStressCommitted_.setZero();
  xiCommitted_ = 0.0;
  strainCommitted_.setZero();
  strain_.setZero();
  integrate();
  stressCommitted_ = stress_;
  tangentCommitted_ = tangent_;
  committedAnswerValid_ = true;
}

void J2Plasticity::updateStage(int stage) {
  if (stage != 0 && stage != 1)
    throw OpenSeesError("updateMaterialStage: nDMaterial J2Plasticity " + std::to_string(tag()) +
                        ": stage must be 0 (elastic) or 1 (plastic), got " + std::to_string(stage));
  stage_ = stage;
  committedAnswerValid_ = false;
  integrate();
}

bool J2Plasticity::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  const std::string& name = args[0];
  if (name == "materialState" || name == "updateMaterialStage") {
    updateStage(static_cast<int>(std::lround(value)));
    return true;
  }
  Parameters p = p_;
  if (name == "K") p.K = value;
  else if (name == "G") p.G = value;
  else if (name == "sig0") p.sig0 = value;
  else if (name == "sigInf") p.sigInf = value;
  else if (name == "delta") p.delta = value;
  else if (name == "H") p.H = value;
  else return false;
  const std::string problem = checkParameters(p);
  if (!problem.empty()) throw OpenSeesError("setParameter: nDMaterial J2Plasticity " + std::to_string(tag()) + ": " + problem);
  p_ = p;
  committedAnswerValid_ = false;
  elastic_ = voigt::isotropicElasticity(p_.K, p_.G);
  integrate();
  return true;
}

Response J2Plasticity::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "plasticStrain" || what == "plasticStrains")
    return Response::named({"epsP11", "epsP22", "epsP33", "epsP12", "epsP23", "epsP13"},
                           [this] { return Vector(plasticStrain()); });
  if (what == "equivalentPlasticStrain")
    return Response::named({"xi"}, [this] { return Vector::Constant(1, xiTrial_); });
  if (what == "backStress")
    return Response::named({"beta11", "beta22", "beta33", "beta12", "beta23", "beta13"},
                           [this] { return Vector(backStressTrial_); });
  return NDMaterial::setResponse(args);
}

void J2Plasticity::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type J2Plasticity K " << p_.K << " G " << p_.G << " sig0 " << p_.sig0
     << " sigInf " << p_.sigInf << " delta " << p_.delta << " H " << p_.H << " kinematic " << p_.kinematicH
     << " stage " << stage_ << '\n';
}

namespace {

std::unique_ptr<NDMaterial> buildJ2Plasticity(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial J2Plasticity " + std::to_string(tag));
  J2Plasticity::Parameters p;
  p.K = args.nextDouble("K");
  p.G = args.nextDouble("G");
  p.sig0 = args.nextDouble("sig0");
  p.sigInf = args.nextDouble("sigInf");
  p.delta = args.nextDouble("delta");
  p.H = args.nextDouble("H");
  if (args.nextIsNumber()) {
    const std::size_t at = args.position();
    const double eta = args.nextDouble("eta");
    // OpenSees' viscosity enters as phi = (eta / dt) dgamma with the analysis
    // step dt (black-box runs of OpenSeesPy 3.7.1); the manual does not say
    // so, and BeamSolid's materials do not see dt: refuse rather than differ.
    if (eta != 0.0)
      args.failAt(at, "eta",
                  "0 (rate-dependent J2Plasticity, eta != 0, is not implemented: OpenSees scales it by the "
                  "analysis time step, which its manual does not document)");
  }
  while (!args.done()) {
    const std::size_t at = args.position();
    const std::string flag = args.nextString("option");
    if (flag == "-kinematic") p.kinematicH = args.nextDouble("Hkin");
    else args.failAt(at, "option", "'-kinematic' Hkin (BeamSolid's linear kinematic hardening)");
  }
  const std::string problem = checkParameters(p);
  if (!problem.empty()) args.fail(problem);
  return std::make_unique<J2Plasticity>(tag, p);
}

void registerJ2Plasticity(Registry& r) { r.ndMaterials.add("J2Plasticity", &buildJ2Plasticity); }

}  // namespace

BEAMSOLID_REGISTER(registerJ2Plasticity);

}  // namespace beamsolid
