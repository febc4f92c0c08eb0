#include "materials/nd/DruckerPrager.h"

#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "materials/nd/PlaneFromThreeDimensional.h"

namespace beamsolid {

namespace {

const double kSqrt23 = std::sqrt(2.0 / 3.0);

std::string checkParameters(const DruckerPrager::Parameters& p) {
  auto positive = [](const char* name, double v) {
    return v > 0.0 ? std::string() : std::string(name) + " must be positive, got " + std::to_string(v);
  };
  auto nonNegative = [](const char* name, double v) {
    return v >= 0.0 ? std::string() : std::string(name) + " must be >= 0, got " + std::to_string(v);
  };
  for (const std::string& s : {positive("K", p.K), positive("G", p.G), positive("sigmaY", p.sigmaY),
                               nonNegative("rho", p.rho), nonNegative("rhoBar", p.rhoBar), nonNegative("Kinf", p.Kinf),
                               nonNegative("Ko", p.Ko), nonNegative("delta1", p.delta1),
                               nonNegative("delta2", p.delta2), nonNegative("H", p.H),
                               nonNegative("density", p.density), positive("atmPressure", p.atmPressure)})
    if (!s.empty()) return s;
  if (p.rhoBar > p.rho)
    return "rhoBar must satisfy 0 <= rhoBar <= rho, got rhoBar " + std::to_string(p.rhoBar) + " > rho " +
           std::to_string(p.rho);
  if (!(p.theta >= 0.0 && p.theta <= 1.0)) return "theta must satisfy 0 <= theta <= 1, got " + std::to_string(p.theta);
  return {};
}

// Tensor norm metric on stress-like Voigt vectors: ||t||^2 = t^T M t.
voigt::Vector6 metric(const voigt::Vector6& t) {
  voigt::Vector6 m = t;
  m.tail<3>() *= 2.0;
  return m;
}

}  // namespace

// The elastic trial from the committed state.
struct DruckerPrager::Trial {
  double I1 = 0.0;
  Vector6 relative = Vector6::Zero();  // s_trial - beta_n
  double relativeNorm = 0.0;
  Vector6 normal = Vector6::Zero();  // relative / ||relative|| (0 at the axis)
};

DruckerPrager::DruckerPrager(int tag, const Parameters& p) : NDMaterial(tag), p_(p) {
  const std::string problem = checkParameters(p_);
  if (!problem.empty()) throw OpenSeesError("nDMaterial DruckerPrager " + std::to_string(tag) + ": " + problem);
  // rho = 0 is von Mises with no cutoff (OpenSees accepts it too).
  T0_ = p_.rho > 0.0 ? kSqrt23 * p_.sigmaY / p_.rho : std::numeric_limits<double>::infinity();
  elastic_ = voigt::isotropicElasticity(p_.K, p_.G);
  tangent_ = elastic_;
  tangentCommitted_ = elastic_;
}

std::unique_ptr<NDMaterial> DruckerPrager::clone(const std::string& kind) const {
  if (kind == "ThreeDimensional") return std::make_unique<DruckerPrager>(*this);
  if (kind == "PlaneStrain")
    return std::make_unique<PlaneFromThreeDimensional>(std::make_unique<DruckerPrager>(*this),
                                                       PlaneFromThreeDimensional::Plane::Strain);
  return nullptr;
}

double DruckerPrager::Y(double a) const {
  return p_.sigmaY + p_.theta * p_.H * a + (p_.Kinf - p_.Ko) * (1.0 - std::exp(-p_.delta1 * a));
}
double DruckerPrager::dY(double a) const {
  return p_.theta * p_.H + (p_.Kinf - p_.Ko) * p_.delta1 * std::exp(-p_.delta1 * a);
}
double DruckerPrager::T(double aT) const { return T0_ * std::exp(-p_.delta2 * aT); }
double DruckerPrager::dT(double aT) const {
  return p_.delta2 == 0.0 ? 0.0 : -p_.delta2 * T0_ * std::exp(-p_.delta2 * aT);
}

void DruckerPrager::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 6)
    throw OpenSeesError("nDMaterial DruckerPrager " + std::to_string(tag()) +
                        ": expected a strain vector of size 6, got " + std::to_string(strain.size()));
  strain_ = strain;
  integrate();
}

// F = (f1, f2) of the active surfaces and J = dF/d(dgamma1, dgamma2); an
// inactive surface has F = 0 and a unit diagonal so that J stays regular.
void DruckerPrager::residuals(const Trial& t, bool cone, bool cutoff, double dg1, double dg2, Eigen::Vector2d& F,
                              Eigen::Matrix2d& J) const {
  const double kin = 2.0 / 3.0 * (1.0 - p_.theta) * p_.H;
  const double a = alphaCommitted_ + kSqrt23 * dg1;
  const double I1 = t.I1 - 9.0 * p_.K * (p_.rhoBar * dg1 + dg2);
  const double deviatoric = t.relativeNorm - (2.0 * p_.G + kin) * dg1;
  const bool apex = deviatoric <= 0.0;
  F.setZero();
  J.setIdentity();
  if (cone) {
    F(0) = (apex ? 0.0 : deviatoric) + p_.rho * I1 - kSqrt23 * Y(a);
    J(0, 0) = (apex ? 0.0 : -(2.0 * p_.G + kin)) - 9.0 * p_.K * p_.rho * p_.rhoBar - 2.0 / 3.0 * dY(a);
    J(0, 1) = cutoff ? -9.0 * p_.K * p_.rho : 0.0;
  }
  if (cutoff) {
    F(1) = I1 - T(alphaTensionCommitted_ + dg2);
    J(1, 0) = cone ? -9.0 * p_.K * p_.rhoBar : 0.0;
    J(1, 1) = -9.0 * p_.K - dT(alphaTensionCommitted_ + dg2);
  }
}

bool DruckerPrager::solve(const Trial& t, bool cone, bool cutoff, double& dg1, double& dg2) const {
  const double scale = std::max(std::abs(t.I1) + t.relativeNorm, p_.sigmaY);
  dg1 = 0.0;
  dg2 = 0.0;
  Eigen::Vector2d F;
  Eigen::Matrix2d J;
  if (cone != cutoff) {
    // One surface: F is decreasing in its multiplier; bracket it and use a
    // safeguarded Newton (the cone's F has a kink at the apex).
    double& x = cone ? dg1 : dg2;
    const int i = cone ? 0 : 1;
    auto value = [&](double v) {
      (cone ? dg1 : dg2) = v;
      residuals(t, cone, cutoff, dg1, dg2, F, J);
      return F(i);
    };
    double lower = 0.0, upper = 1e-12;
    const double elasticStiffness = 2.0 * p_.G + 9.0 * p_.K;
    upper = std::max(upper, 2.0 * scale / elasticStiffness);
    int grow = 0;
    while (value(upper) > 0.0) {
      lower = upper;
      upper *= 4.0;
      if (++grow > 60) return false;  // no root: this surface alone cannot return
    }
    x = 0.5 * (lower + upper);
    for (int it = 0; it < 200; ++it) {
      const double r = value(x);
      if (r > 0.0) lower = x;
      else upper = x;
      if (std::abs(r) <= 1e-14 * scale || upper - lower <= 1e-16 * upper) return true;
      const double slope = J(i, i);
      double next = slope < 0.0 ? x - r / slope : 0.5 * (lower + upper);
      if (!(next > lower && next < upper)) next = 0.5 * (lower + upper);
      x = next;
    }
    return true;
  }
  // Both surfaces: Newton on the 2x2 system from the one-surface answers.
  double start1 = 0.0, start2 = 0.0, unused = 0.0;
  if (!solve(t, true, false, start1, unused)) start1 = t.relativeNorm / (2.0 * p_.G);
  if (!solve(t, false, true, unused, start2)) start2 = 0.0;
  dg1 = start1;
  dg2 = start2;
  for (int it = 0; it < 100; ++it) {
    residuals(t, true, true, dg1, dg2, F, J);
    if (F.cwiseAbs().maxCoeff() <= 1e-14 * scale) return dg1 >= 0.0 && dg2 >= 0.0;
    if (std::abs(J.determinant()) <= 1e-14 * J.cwiseAbs().maxCoeff() * J.cwiseAbs().maxCoeff()) {
      // The apex with nothing that depends on dgamma1 (rhoBar = 0, no
      // hardening): dgamma1 only clears the deviator; the cutoff sets I1.
      dg1 = std::max(dg1, t.relativeNorm / (2.0 * p_.G + 2.0 / 3.0 * (1.0 - p_.theta) * p_.H));
      double only = 0.0;
      if (!solve(t, false, true, unused, only)) return false;
      dg2 = only;
      return true;
    }
    const Eigen::Vector2d step = J.partialPivLu().solve(F);
    dg1 -= step(0);
    dg2 -= step(1);
    if (dg1 < 0.0) dg1 = 0.0;
    if (dg2 < 0.0) dg2 = 0.0;
  }
  return false;
}

void DruckerPrager::integrate() {
  plasticStrainTrial_ = plasticStrainCommitted_;
  backStressTrial_ = backStressCommitted_;
  alphaTrial_ = alphaCommitted_;
  alphaTensionTrial_ = alphaTensionCommitted_;
  lastReturn_ = 0;

  const Vector6 one = voigt::identity();
  Trial t;
  const Vector6 elasticStrain = strain_ - voigt::tensorToStrain(plasticStrainCommitted_);
  t.I1 = 3.0 * p_.K * voigt::trace(elasticStrain);
  const Vector6 sTrial = 2.0 * p_.G * voigt::strainDeviatorAsTensor(elasticStrain);
  t.relative = sTrial - backStressCommitted_;
  t.relativeNorm = voigt::norm(t.relative);
  if (t.relativeNorm > 0.0) t.normal = t.relative / t.relativeNorm;
  stress_ = sTrial + t.I1 / 3.0 * one;
  tangent_ = elastic_;
  if (stage_ == 0) return;

  const double scale = std::max(std::abs(t.I1) + t.relativeNorm, p_.sigmaY);
  const double f1 = t.relativeNorm + p_.rho * t.I1 - kSqrt23 * Y(alphaCommitted_);
  const double f2 = t.I1 - T(alphaTensionCommitted_);
  const double tol = 1e-12 * scale;
  if (f1 <= tol && f2 <= tol) return;

  // Active set: the cone (or apex) alone, the cutoff alone, then both.
  double dg1 = 0.0, dg2 = 0.0;
  bool cone = false, cutoff = false;
  Eigen::Vector2d F;
  Eigen::Matrix2d J;
  if (f1 > tol && solve(t, true, false, dg1, dg2)) {
    residuals(t, false, true, dg1, 0.0, F, J);
    if (F(1) <= tol) cone = true;
  }
  if (!cone && f2 > tol && solve(t, false, true, dg1, dg2)) {
    residuals(t, true, false, 0.0, dg2, F, J);
    if (F(0) <= tol) cutoff = true;
  }
  if (!cone && !cutoff) {
    if (!solve(t, true, true, dg1, dg2))
      throw ElementStateError("nDMaterial DruckerPrager " + std::to_string(tag()) +
                              ": the return to the cone and tension cutoff did not converge");
    cone = cutoff = true;
  }
  if (!cone) dg1 = 0.0;
  if (!cutoff) dg2 = 0.0;

  const double kin = 2.0 / 3.0 * (1.0 - p_.theta) * p_.H;
  const bool apex = cone && t.relativeNorm - (2.0 * p_.G + kin) * dg1 <= 0.0;
  lastReturn_ = cone && cutoff ? (apex ? 5 : 4) : cutoff ? 3 : apex ? 2 : 1;

  // Updated state. At the apex the deviatoric plastic strain is the part of
  // the trial deviator the hardened back stress does not take.
  const Vector6 deviatoricFlow = apex ? Vector6(t.relative / (2.0 * p_.G + kin)) : Vector6(dg1 * t.normal);
  plasticStrainTrial_ += deviatoricFlow + (p_.rhoBar * dg1 + dg2) * one;
  backStressTrial_ += kin * deviatoricFlow;
  alphaTrial_ = alphaCommitted_ + kSqrt23 * dg1;
  alphaTensionTrial_ = alphaTensionCommitted_ + dg2;
  const double I1 = t.I1 - 9.0 * p_.K * (p_.rhoBar * dg1 + dg2);
  const Vector6 s = sTrial - 2.0 * p_.G * deviatoricFlow;
  stress_ = s + I1 / 3.0 * one;

  // Consistent tangent D = dsigma/deps - dsigma/ddgamma J^-1 dF/deps over
  // the active multipliers (docs/soil_materials.md).
  const Matrix6 P = voigt::deviatoricProjector();
  Matrix6 dSigma = p_.K * one * one.transpose();
  Eigen::Matrix<double, 6, 2> dSigmaDgamma = Eigen::Matrix<double, 6, 2>::Zero();
  Eigen::Matrix<double, 2, 6> dFdEps = Eigen::Matrix<double, 2, 6>::Zero();
  if (apex) {
    dSigma += kin / (2.0 * p_.G + kin) * 2.0 * p_.G * P;
  } else if (cone) {
    const Matrix6 dNormal =
        (Matrix6::Identity() - t.normal * metric(t.normal).transpose()) * (2.0 * p_.G / t.relativeNorm) * P;
    dSigma += 2.0 * p_.G * P - 2.0 * p_.G * dg1 * dNormal;
    dSigmaDgamma.col(0) -= 2.0 * p_.G * t.normal;
    dFdEps.row(0) += 2.0 * p_.G * (metric(t.normal).transpose() * P);
  } else {
    dSigma += 2.0 * p_.G * P;
  }
  if (cone) {
    dSigmaDgamma.col(0) -= 3.0 * p_.K * p_.rhoBar * one;
    dFdEps.row(0) += 3.0 * p_.K * p_.rho * one.transpose();
  }
  if (cutoff) {
    dSigmaDgamma.col(1) -= 3.0 * p_.K * one;
    dFdEps.row(1) += 3.0 * p_.K * one.transpose();
  }
  residuals(t, cone, cutoff, dg1, dg2, F, J);
  const bool singularApex = apex && cutoff && std::abs(J.determinant()) <= 1e-14 * J.cwiseAbs().maxCoeff() * J.cwiseAbs().maxCoeff();
  if (singularApex) {
    // dgamma1 is free there and nothing depends on it (see solve()).
    dSigmaDgamma.col(0).setZero();
    dFdEps.row(0).setZero();
    J(0, 0) = 1.0;
    J(0, 1) = J(1, 0) = 0.0;
  }
  tangent_ = dSigma - dSigmaDgamma * J.partialPivLu().solve(dFdEps);
}

void DruckerPrager::commitState() {
  plasticStrainCommitted_ = plasticStrainTrial_;
  backStressCommitted_ = backStressTrial_;
  alphaCommitted_ = alphaTrial_;
  alphaTensionCommitted_ = alphaTensionTrial_;
  strainCommitted_ = strain_;
  stressCommitted_ = stress_;
  tangentCommitted_ = tangent_;
  committedAnswerValid_ = true;
}

void DruckerPrager::revertToLastCommit() {
  strain_ = strainCommitted_;
  if (!committedAnswerValid_) {
    integrate();
    return;
  }
  stress_ = stressCommitted_;
  tangent_ = tangentCommitted_;
  plasticStrainTrial_ = plasticStrainCommitted_;
  backStressTrial_ = backStressCommitted_;
  alphaTrial_ = alphaCommitted_;
  alphaTensionTrial_ = alphaTensionCommitted_;
}

void DruckerPrager::revertToStart() {
  plasticStrainCommitted_.setZero();
  backStressCommitted_.setZero();
  alphaCommitted_ = alphaTensionCommitted_ = 0.0;
  strainCommitted_.setZero();
  strain_.setZero();
  integrate();
  stressCommitted_ = stress_;
  tangentCommitted_ = tangent_;
  committedAnswerValid_ = true;
}

void DruckerPrager::updateStage(int stage) {
  if (stage != 0 && stage != 1)
    throw OpenSeesError("updateMaterialStage: nDMaterial DruckerPrager " + std::to_string(tag()) +
                        ": stage must be 0 (elastic) or 1 (plastic), got " + std::to_string(stage));
  stage_ = stage;
  committedAnswerValid_ = false;
  integrate();
}

bool DruckerPrager::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  const std::string& name = args[0];
  const std::string context = "setParameter: nDMaterial DruckerPrager " + std::to_string(tag()) + ": ";
  if (name == "materialState") {
    const long v = std::lround(value);
    committedAnswerValid_ = false;
    if (v == 0) stage_ = 0;
    else if (v == 2) stage_ = 1;
    else
      throw OpenSeesError(context + "materialState must be 0 (elastic) or 2 (plastic), got " + std::to_string(value) +
                          " (OpenSees' 1, elastic with pressure-dependent moduli, is not implemented)");
    integrate();
    return true;
  }
  if (name == "updateMaterialStage") {
    updateStage(static_cast<int>(std::lround(value)));
    return true;
  }
  Parameters p = p_;
  if (name == "frictionAngle" || name == "cohesion") return false;
  if (name == "shearModulus" || name == "G") p.G = value;
  else if (name == "bulkModulus" || name == "K") p.K = value;
  else if (name == "rho") p.rho = value;
  else if (name == "rhoBar") p.rhoBar = value;
  else if (name == "sigmaY") p.sigmaY = value;
  else return false;
  const std::string problem = checkParameters(p);
  if (!problem.empty()) throw OpenSeesError(context + problem);
  p_ = p;
  committedAnswerValid_ = false;
  T0_ = p_.rho > 0.0 ? kSqrt23 * p_.sigmaY / p_.rho : std::numeric_limits<double>::infinity();
  elastic_ = voigt::isotropicElasticity(p_.K, p_.G);
  integrate();
  return true;
}

Response DruckerPrager::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "state")
    return Response::named({"I1", "normS", "trEpsP", "normEpsPdev", "normEpsP"}, [this] {
      Vector out(5);
      out(0) = voigt::trace(stress_);
      out(1) = voigt::norm(voigt::deviator(stress_) - backStressTrial_);
      out(2) = voigt::trace(plasticStrainTrial_);
      out(3) = voigt::norm(voigt::deviator(plasticStrainTrial_));
      out(4) = voigt::norm(plasticStrainTrial_);
      return out;
    });
  if (what == "plasticStrain" || what == "plasticStrains")
    return Response::named({"epsP11", "epsP22", "epsP33", "epsP12", "epsP23", "epsP13"},
                           [this] { return Vector(plasticStrain()); });
  if (what == "equivalentPlasticStrain")
    return Response::named({"alpha"}, [this] { return Vector::Constant(1, alphaTrial_); });
  return NDMaterial::setResponse(args);
}

void DruckerPrager::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type DruckerPrager K " << p_.K << " G " << p_.G << " sigmaY " << p_.sigmaY
     << " rho " << p_.rho << " rhoBar " << p_.rhoBar << " Kinf " << p_.Kinf << " Ko " << p_.Ko << " delta1 "
     << p_.delta1 << " delta2 " << p_.delta2 << " H " << p_.H << " theta " << p_.theta << " density "
     << p_.density << " stage " << stage_ << '\n';
}

namespace {

std::unique_ptr<NDMaterial> buildDruckerPrager(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial DruckerPrager " + std::to_string(tag));
  DruckerPrager::Parameters p;
  p.K = args.nextDouble("K");
  p.G = args.nextDouble("G");
  p.sigmaY = args.nextDouble("sigmaY");
  p.rho = args.nextDouble("rho");
  p.rhoBar = args.nextDouble("rhoBar");
  p.Kinf = args.nextDouble("Kinf");
  p.Ko = args.nextDouble("Ko");
  p.delta1 = args.nextDouble("delta1");
  p.delta2 = args.nextDouble("delta2");
  p.H = args.nextDouble("H");
  p.theta = args.nextDouble("theta");
  p.density = args.nextDouble("density");
  if (!args.done()) p.atmPressure = args.nextDouble("atmPressure");
  args.expectEnd();
  const std::string problem = checkParameters(p);
  if (!problem.empty()) args.fail(problem);
  return std::make_unique<DruckerPrager>(tag, p);
}

void registerDruckerPrager(Registry& r) { r.ndMaterials.add("DruckerPrager", &buildDruckerPrager); }

}  // namespace

BEAMSOLID_REGISTER(registerDruckerPrager);

}  // namespace beamsolid
