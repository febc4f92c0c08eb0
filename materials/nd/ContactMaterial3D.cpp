#include "materials/nd/ContactMaterial3D.h"

#include <algorithm>
#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

// Returns an empty string when the parameters describe a friction law.
std::string checkParameters(double mu, double G, double c, double t) {
  if (!(mu >= 0.0) || !std::isfinite(mu)) return "mu must be a number >= 0, got " + std::to_string(mu);
  if (!(G > 0.0) || !std::isfinite(G)) return "G must be positive, got " + std::to_string(G);
  if (!(c >= 0.0) || !std::isfinite(c)) return "c must be a number >= 0, got " + std::to_string(c);
  if (!(t >= 0.0) || !std::isfinite(t)) return "t must be a number >= 0, got " + std::to_string(t);
  return {};
}

}  // namespace

ContactMaterial3D::ContactMaterial3D(int tag, double mu, double G, double c, double t)
    : NDMaterial(tag), mu_(mu), G_(G), c_(c), t_(t) {
  const std::string problem = checkParameters(mu, G, c, t);
  if (!problem.empty()) throw OpenSeesError(context() + ": " + problem);
  initialTangent23_.leftCols<2>() = G_ * metric_;
}

std::string ContactMaterial3D::context() const { return "nDMaterial ContactMaterial3D " + std::to_string(tag()); }

std::unique_ptr<NDMaterial> ContactMaterial3D::clone(const std::string& kind) const {
  if (kind != "ContactMaterial3D") return nullptr;
  return std::make_unique<ContactMaterial3D>(*this);
}

double ContactMaterial3D::tensileStrength() const {
  // The apex of the Coulomb cone, |T| = 0 at t_n = -c/mu, bounds the tension.
  if (mu_ > 0.0) return std::min(t_, c_ / mu_);
  return t_;
}

double ContactMaterial3D::tractionNorm() const {
  const double q = traction_.dot(metric_.inverse() * traction_);
  return std::sqrt(std::max(q, 0.0));
}

void ContactMaterial3D::setMetric(const Matrix2& metric) {
  metric_ = metric;
  initialTangent23_.leftCols<2>() = G_ * metric_;
}

void ContactMaterial3D::setTrialState(double gap, const Vector2& slip, double normalForce, const Matrix2& metric) {
  metric_ = metric;
  sliding_ = false;
  const double mu = frictional_ ? mu_ : 0.0;
  const double c = frictional_ ? c_ : 0.0;
  const double t = frictional_ ? tensileStrength() : 0.0;
  const Vector2 trialSlip = committedElasticSlip_ + slip;  // (C13)

  if (!frictional_ || normalForce <= -t) {
    // Frictionless stage, or the interface has let go in tension: no
    // traction and the elastic slip starts afresh. In the frictionless stage
    // the whole slip is free sliding that dissipates nothing (T = 0).
    elasticSlip_.setZero();
    plasticSlip_ = trialSlip;
    traction_.setZero();
    tangentSlip_.setZero();
    tangentNormal_.setZero();
    slipResistance_ = 0.0;
    fillGeneric(gap, slip, normalForce);
    return;
  }

  slipResistance_ = mu * normalForce + c;
  const Vector2 mSlip = metric_ * trialSlip;
  const double slipNorm = std::sqrt(std::max(trialSlip.dot(mSlip), 0.0));  // |s_e|_m
  const double f = G_ * slipNorm - slipResistance_;                         // (C14)
  if (f <= 0.0) {
    elasticSlip_ = trialSlip;
    plasticSlip_.setZero();
    traction_ = G_ * mSlip;
    tangentSlip_ = G_ * metric_;
    tangentNormal_.setZero();
  } else {
    // Radial return (C15): |T| lands on mu t_n + c, along the trial direction.
    sliding_ = true;
    const double scale = slipResistance_ / (G_ * slipNorm);  // 1 - gamma/|s_e|_m
    elasticSlip_ = scale * trialSlip;
    plasticSlip_ = trialSlip - elasticSlip_;  // gamma r
    traction_ = scale * G_ * mSlip;
    const Vector2 mr = mSlip / slipNorm;  // m r with r = s_e/|s_e|_m
    tangentSlip_ = G_ * scale * (metric_ - mr * mr.transpose());  // (C16)
    tangentNormal_ = mu * mr;
  }
  fillGeneric(gap, slip, normalForce);
}

void ContactMaterial3D::setIterate(double gap, const Vector2& slip, double normalForce, const Matrix2& metric) {
  if (!haveLast_ || slip != lastSlip_ || normalForce != lastNormalForce_) {
    // A new iterate: the last call's outcome becomes the previous iterate.
    previousSliding_ = haveLast_ && lastSliding_;
    previousDirection_ = lastDirection_;
    ++iterates_;
  }
  setTrialState(gap, slip, normalForce, metric);
  held_ = false;
  if (iterates_ == 1 && committedSliding_ && !sliding_ && slipResistance_ > 0.0) {
    // The step's first iterate of a node that slid at the last commit and has
    // not moved since: its state is the converged one, on the slip surface up
    // to the drift of the re-projection (the new projection's metric), and the
    // return map may find it a hair inside and give the stick tangent. It is
    // held on the surface with the sliding tangent (C15-C16, gamma = 0), the
    // state it converged to: a steady slide then converges in one iteration
    // instead of restarting each step from stick. Only the predictor changes;
    // the next iterate is the return map's again.
    const Vector2 mSlip = metric_ * elasticSlip_;
    const double slipNorm = std::sqrt(std::max(elasticSlip_.dot(mSlip), 0.0));
    const double moved = std::sqrt(std::max(slip.dot(metric_ * slip), 0.0));
    if (slipNorm > 0.0 && moved <= kUnmoved * slipNorm) {
      sliding_ = true;
      const double scale = slipResistance_ / (G_ * slipNorm);
      elasticSlip_ *= scale;
      traction_ = scale * G_ * mSlip;
      const Vector2 mr = mSlip / slipNorm;
      tangentSlip_ = G_ * scale * (metric_ - mr * mr.transpose());
      tangentNormal_ = mu_ * mr;
      fillGeneric(gap, slip, normalForce);
    }
  }
  if (sliding_ && previousSliding_ && slipResistance_ > 0.0 && previousDirection_.squaredNorm() > 0.0) {
    // Plastic multiplier of the trial state along the previous traction
    // direction t (unit in m^-1): t . G s_e - (mu t_n + c) (C14 projected).
    const Vector2 trialSlip = committedElasticSlip_ + slip;
    if (G_ * previousDirection_.dot(trialSlip) <= slipResistance_) {
      held_ = true;
      sliding_ = false;
      elasticSlip_ = trialSlip;
      plasticSlip_.setZero();
      traction_ = G_ * metric_ * trialSlip;
      tangentSlip_ = G_ * metric_;
      tangentNormal_.setZero();
      fillGeneric(gap, slip, normalForce);
    }
  }
  haveLast_ = true;
  lastSlip_ = slip;
  lastNormalForce_ = normalForce;
  lastSliding_ = sliding_;
  const double norm = tractionNorm();
  lastDirection_ = sliding_ && norm > 0.0 ? Vector2(traction_ / norm) : Vector2::Zero();
}

void ContactMaterial3D::forgetIterates() {
  held_ = haveLast_ = lastSliding_ = previousSliding_ = false;
  iterates_ = 0;
  lastDirection_.setZero();
  previousDirection_.setZero();
}

void ContactMaterial3D::release() {
  forgetIterates();
  sliding_ = committedSliding_ = false;
  elasticSlip_.setZero();
  plasticSlip_.setZero();
  traction_.setZero();
  tangentSlip_.setZero();
  tangentNormal_.setZero();
  slipResistance_ = 0.0;
  strain_.setZero();
  stress_.setZero();
  tangent23_.setZero();
}

void ContactMaterial3D::fillGeneric(double gap, const Vector2& slip, double normalForce) {
  strain_ << gap, slip(0), slip(1), normalForce;
  stress_ << normalForce, traction_(0), traction_(1);
  tangent23_.leftCols<2>() = tangentSlip_;
  tangent23_.col(2) = tangentNormal_;
}

void ContactMaterial3D::setTrialStrain(const Eigen::Ref<const Vector>& strain) {
  if (strain.size() != 4)
    throw OpenSeesError(context() + ": expected [gap, slip1, slip2, normalForce] (size 4), got size " +
                        std::to_string(strain.size()));
  setTrialState(strain(0), Vector2(strain(1), strain(2)), strain(3), metric_);
}

void ContactMaterial3D::commitState() {
  committedElasticSlip_ = elasticSlip_;
  committedSliding_ = sliding_;
  forgetIterates();
}

void ContactMaterial3D::revertToLastCommit() {
  forgetIterates();
  sliding_ = false;
  elasticSlip_ = committedElasticSlip_;
  plasticSlip_.setZero();
  traction_ = frictional_ ? Vector2(G_ * metric_ * elasticSlip_) : Vector2::Zero();
  tangentSlip_ = frictional_ ? Matrix2(G_ * metric_) : Matrix2::Zero();
  tangentNormal_.setZero();
}

void ContactMaterial3D::changeSurfaceCoordinates(const Matrix2& map, const Matrix2& newMetric) {
  committedElasticSlip_ = map * committedElasticSlip_;
  metric_ = newMetric;
  revertToLastCommit();
}

void ContactMaterial3D::revertToStart() {
  committedElasticSlip_.setZero();
  release();
}

void ContactMaterial3D::setFrictional(double flag) {
  if (flag != 0.0 && flag != 1.0)
    throw OpenSeesError(context() + ": the frictional state must be 0 (frictionless) or 1 (frictional), got " +
                        std::to_string(flag));
  frictional_ = flag == 1.0;
}

void ContactMaterial3D::updateStage(int stage) { setFrictional(stage); }

bool ContactMaterial3D::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  const std::string& name = args[0];
  if (name == "friction" || name == "frictionalState") {
    setFrictional(value);
    return true;
  }
  double mu = mu_, G = G_, c = c_, t = t_;
  if (name == "mu" || name == "frictionCoefficient") mu = value;
  else if (name == "G" || name == "stiffness") G = value;
  else if (name == "c" || name == "cohesion") c = value;
  else if (name == "t" || name == "tensileStrength") t = value;
  else return false;
  const std::string problem = checkParameters(mu, G, c, t);
  if (!problem.empty()) throw OpenSeesError(context() + ": " + problem);
  mu_ = mu;
  G_ = G;
  c_ = c;
  t_ = t;
  initialTangent23_.leftCols<2>() = G_ * metric_;
  return true;
}

void ContactMaterial3D::print(std::ostream& os) const {
  os << "NDMaterial " << tag() << " type ContactMaterial3D mu " << mu_ << " G " << G_ << " c " << c_ << " t " << t_;
  if (tensileStrength() < t_) os << " (tensile strength bounded by c/mu = " << tensileStrength() << ")";
  os << (frictional_ ? " frictional" : " frictionless") << '\n';
}

namespace {

std::unique_ptr<NDMaterial> buildContactMaterial3D(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial ContactMaterial3D " + std::to_string(tag));
  const double mu = args.nextDouble("mu");
  const double G = args.nextDouble("G");
  const double c = args.nextDouble("c");
  const double t = args.nextDouble("t");
  args.expectEnd();
  const std::string problem = checkParameters(mu, G, c, t);
  if (!problem.empty()) args.fail(problem);
  return std::make_unique<ContactMaterial3D>(tag, mu, G, c, t);
}

void registerContactMaterial3D(Registry& r) { r.ndMaterials.add("ContactMaterial3D", &buildContactMaterial3D); }

}  // namespace

BEAMSOLID_REGISTER(registerContactMaterial3D);

}  // namespace beamsolid
