#include "analysis/LoadControl.h"

#include <algorithm>
#include <memory>

#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

LoadControl::LoadControl(double increment, int desiredIterations, double minIncrement, double maxIncrement)
    : increment_(increment),
      desiredIterations_(desiredIterations),
      minIncrement_(minIncrement),
      maxIncrement_(maxIncrement) {}

int LoadControl::newStep(AnalysisModel& model) {
  if (lastIterations_ > 0 && desiredIterations_ > 0) {
    const double factor = double(desiredIterations_) / double(lastIterations_);
    const double lo = std::min(minIncrement_, maxIncrement_), hi = std::max(minIncrement_, maxIncrement_);
    increment_ = std::clamp(increment_ * factor, lo, hi);
  }
  Domain& domain = model.domain();
  domain.applyLoad(domain.currentTime() + increment_);
  model.enforcePrescribed();
  domain.update();
  return 0;
}

int LoadControl::update(AnalysisModel& model, const Vector& dU) {
  model.applyIncrement(dU);
  return 0;
}

void LoadControl::commit(AnalysisModel&, int iterations) { lastIterations_ = iterations; }

namespace {
std::unique_ptr<Integrator> buildLoadControl(CommandArgs& args, Domain&) {
  const double dLambda = args.nextDouble("dLambda");
  int numIter = 1;
  double minLambda = dLambda, maxLambda = dLambda;
  if (!args.done()) {
    numIter = args.nextInt("numIter");
    minLambda = args.nextDouble("minLambda");
    maxLambda = args.nextDouble("maxLambda");
  }
  args.expectEnd();
  return std::make_unique<LoadControl>(dLambda, numIter, minLambda, maxLambda);
}
void registerLoadControl(Registry& r) { r.integrators.add("LoadControl", &buildLoadControl); }
}  // namespace
BEAMSOLID_REGISTER(registerLoadControl);

}  // namespace beamsolid
