#include "analysis/MinUnbalDispNorm.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

MinUnbalDispNorm::MinUnbalDispNorm(double dLambda1, int desiredIterations, double minLambda, double maxLambda,
                                   bool byDeterminant)
    : dLambda1_(dLambda1),
      desiredIterations_(desiredIterations),
      minLambda_(std::min(minLambda, maxLambda)),
      maxLambda_(std::max(minLambda, maxLambda)),
      byDeterminant_(byDeterminant) {}

int MinUnbalDispNorm::newStep(AnalysisModel& model) {
  lastError_.clear();
  model.formTangent(AnalysisModel::Stiffness::Current);
  if (!model.factor(AnalysisModel::Stiffness::Current))
    return fail("the tangent is singular at the start of the step: " + model.describeFactorFailure());
  if (!referenceDisplacement(model)) return fail("the reference displacement K^-1 P_ref is not finite");
  if (referenceLoad_.lpNorm<Eigen::Infinity>() == 0.0)
    throw OpenSeesError("integrator MinUnbalDispNorm: the reference load is zero at time " +
                        std::to_string(model.domain().currentTime()) +
                        ": define a load pattern with nodal loads whose time series grows with time (e.g. Linear)");
  if (lastIterations_ > 0 && desiredIterations_ > 0)
    dLambda1_ = std::clamp(dLambda1_ * double(desiredIterations_) / double(lastIterations_), minLambda_, maxLambda_);
  if (byDeterminant_) {
    const int determinant = model.system().solver() ? model.system().solver()->determinantSign() : 0;
    if (determinant == 0)
      return fail("'-det': the solver cannot give the sign of the determinant (use system('UmfPack'))");
    if (lastDeterminantSign_ != 0 && determinant != lastDeterminantSign_) sign_ = -sign_;
    lastDeterminantSign_ = determinant;
  } else if (previousStepLambda_ != 0.0) {
    sign_ = previousStepLambda_ < 0.0 ? -1.0 : 1.0;
  }
  const double dLambda = sign_ * dLambda1_;
  stepLambda_ = dLambda;
  applyLoadIncrement(model, dLambda, dLambda * referenceDisp_);
  return 0;
}

int MinUnbalDispNorm::update(AnalysisModel& model, const Vector& dU) {
  LinearSystem& system = model.system();
  if (!system.isFactored()) return fail("update without a factored tangent");
  const Vector residualDisp = dU;  // dU may alias system.x(), rewritten below
  if (!referenceDisplacement(model)) return fail("the reference displacement K^-1 P_ref is not finite");
  const double dLambda = -referenceDisp_.dot(residualDisp) / referenceDisp_.squaredNorm();
  if (!std::isfinite(dLambda)) return fail("the load factor correction is not finite");
  system.x() = residualDisp + dLambda * referenceDisp_;
  stepLambda_ += dLambda;
  applyLoadIncrement(model, dLambda, system.x());
  return 0;
}

void MinUnbalDispNorm::commit(AnalysisModel&, int iterations) {
  lastIterations_ = iterations;
  previousStepLambda_ = stepLambda_;
}

void MinUnbalDispNorm::revert(AnalysisModel&) { stepLambda_ = 0.0; }

namespace {
std::unique_ptr<Integrator> buildMinUnbalDispNorm(CommandArgs& args, Domain&) {
  const double dLambda1 = args.nextDouble("dlambda1");
  if (!(dLambda1 > 0.0)) args.fail("dlambda1 must be positive, got " + std::to_string(dLambda1));
  int jd = 1;
  double minLambda = dLambda1, maxLambda = dLambda1;
  if (!args.done() && !args.nextIsString()) {
    jd = args.nextInt("Jd");
    if (jd < 0) args.fail("Jd must be >= 0, got " + std::to_string(jd));
    if (!args.done() && !args.nextIsString()) {
      minLambda = args.nextDouble("minLambda");
      maxLambda = args.nextDouble("maxLambda");
      if (!(minLambda > 0.0) || !(maxLambda > 0.0)) args.fail("minLambda and maxLambda must be positive");
    }
  }
  bool byDeterminant = false;
  while (!args.done()) {
    if (args.nextFlag("-det")) byDeterminant = true;
    else args.fail("unknown option '" + (args.nextIsString() ? *args.peekString() : std::string("?")) +
                   "' (expected '-det')");
  }
  return std::make_unique<MinUnbalDispNorm>(dLambda1, jd, minLambda, maxLambda, byDeterminant);
}
void registerMinUnbalDispNorm(Registry& r) { r.integrators.add("MinUnbalDispNorm", &buildMinUnbalDispNorm); }
}  // namespace
BEAMSOLID_REGISTER(registerMinUnbalDispNorm);

}  // namespace beamsolid
