#include "analysis/ArcLength.h"

#include <cmath>
#include <memory>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

ArcLength::ArcLength(double arcLength, double alpha) : arcLength_(arcLength), alpha2_(alpha * alpha) {}

void ArcLength::domainChanged(AnalysisModel& model) {
  // The last step's increment is in the old numbering: forget it.
  hasPrevious_ = false;
  stepDisp_ = Vector::Zero(model.numEquations());
  stepLambda_ = 0.0;
}

int ArcLength::newStep(AnalysisModel& model) {
  lastError_.clear();
  complexRoots_ = 0;
  const int n = model.numEquations();
  if (previousDisp_.size() != n) hasPrevious_ = false;
  model.formReferenceLoad(referenceLoad_);
  if (referenceLoad_.lpNorm<Eigen::Infinity>() == 0.0)
    throw OpenSeesError("integrator ArcLength: the reference load is zero at time " +
                        std::to_string(model.domain().currentTime()) +
                        ": define a load pattern with nodal loads whose time series grows with time (e.g. Linear)");
  model.formTangent(AnalysisModel::Stiffness::Current);
  if (!model.factor(AnalysisModel::Stiffness::Current))
    return fail("the tangent is singular at the start of the step: " + model.describeFactorFailure());
  if (!referenceDisplacement(model)) return fail("the reference displacement K^-1 P_ref is not finite");

  // Direction: continue along the last step (its inner product with the
  // tangent direction in the arc-length metric); at the start, follow the
  // sign of the current stiffness parameter P.K^-1 P.
  const double along = hasPrevious_ ? previousDisp_.dot(referenceDisp_) + alpha2_ * previousLambda_
                                    : referenceLoad_.dot(referenceDisp_);
  const double sign = along < 0.0 ? -1.0 : 1.0;
  const double dLambda = sign * arcLength_ / std::sqrt(referenceDisp_.squaredNorm() + alpha2_);
  stepDisp_ = dLambda * referenceDisp_;
  stepLambda_ = dLambda;
  applyLoadIncrement(model, dLambda, stepDisp_);
  return 0;
}

int ArcLength::update(AnalysisModel& model, const Vector& dU) {
  LinearSystem& system = model.system();
  if (!system.isFactored()) return fail("update without a factored tangent");
  const Vector residualDisp = dU;  // dU may alias system.x(), rewritten below
  if (!referenceDisplacement(model)) return fail("the reference displacement K^-1 P_ref is not finite");

  // (w + d dU_p).(w + d dU_p) + alpha^2 (DLambda + d)^2 = s^2, w = DU + dU_r.
  const Vector w = stepDisp_ + residualDisp;
  const double a = referenceDisp_.squaredNorm() + alpha2_;
  const double b = 2.0 * (referenceDisp_.dot(w) + alpha2_ * stepLambda_);
  const double c = w.squaredNorm() + alpha2_ * stepLambda_ * stepLambda_ - arcLength_ * arcLength_;
  const double discriminant = b * b - 4.0 * a * c;
  double dLambda;
  if (discriminant < 0.0) {
    // The corrected line misses the sphere: take its closest point and let
    // the next iterations come back to the constraint.
    ++complexRoots_;
    dLambda = -b / (2.0 * a);
  } else {
    // Numerically stable pair of roots.
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    const double r1 = q / a;
    const double r2 = q != 0.0 ? c / q : r1;
    // Forward: the root whose new step increment is closest in direction to
    // the current one (largest inner product in the arc metric).
    auto alignment = [&](double d) {
      return (w + d * referenceDisp_).dot(stepDisp_) + alpha2_ * (stepLambda_ + d) * stepLambda_;
    };
    dLambda = alignment(r1) >= alignment(r2) ? r1 : r2;
  }
  if (!std::isfinite(dLambda)) return fail("the load factor correction is not finite");
  system.x() = residualDisp + dLambda * referenceDisp_;
  stepDisp_ += system.x();
  stepLambda_ += dLambda;
  applyLoadIncrement(model, dLambda, system.x());
  return 0;
}

void ArcLength::commit(AnalysisModel&, int) {
  previousDisp_ = stepDisp_;
  previousLambda_ = stepLambda_;
  hasPrevious_ = true;
}

void ArcLength::revert(AnalysisModel&) {
  // The Domain is back at its last commit; the failed step leaves nothing
  // here, the direction of the last converged step is kept.
  stepDisp_.setZero();
  stepLambda_ = 0.0;
}

namespace {
std::unique_ptr<Integrator> buildArcLength(CommandArgs& args, Domain&) {
  const double s = args.nextDouble("s");
  const double alpha = args.nextDouble("alpha");
  args.expectEnd();
  if (!(s > 0.0)) args.fail("the arc length s must be positive, got " + std::to_string(s));
  if (alpha < 0.0) args.fail("alpha must be non-negative, got " + std::to_string(alpha));
  return std::make_unique<ArcLength>(s, alpha);
}
void registerArcLength(Registry& r) { r.integrators.add("ArcLength", &buildArcLength); }
}  // namespace
BEAMSOLID_REGISTER(registerArcLength);

}  // namespace beamsolid
