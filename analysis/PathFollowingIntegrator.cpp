#include "analysis/PathFollowingIntegrator.h"

#include <iostream>

#include "core/Domain.h"

namespace beamsolid {

bool PathFollowingIntegrator::referenceDisplacement(AnalysisModel& model) {
  model.formReferenceLoad(referenceLoad_);
  model.system().solve(referenceLoad_, referenceDisp_);
  return referenceDisp_.allFinite();
}

void PathFollowingIntegrator::applyLoadIncrement(AnalysisModel& model, double dLambda, const Vector& dU) {
  Domain& domain = model.domain();
  domain.applyLoad(domain.currentTime() + dLambda);
  model.enforcePrescribed();
  model.applyIncrement(dU);
}

int PathFollowingIntegrator::fail(const std::string& why) {
  lastError_ = why;
  std::cerr << "WARNING integrator " << name() << ": " << why << "\n";
  return -1;
}

}  // namespace beamsolid
