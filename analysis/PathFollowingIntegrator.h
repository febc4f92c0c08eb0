#pragma once
#include <string>

#include "analysis/Integrator.h"

namespace beamsolid {

// What the static integrators that choose the load factor themselves
// (DisplacementControl, ArcLength, MinUnbalDispNorm) share: the reference
// displacement K^-1 P_ref on the current factorization, a load factor
// increment applied together with its displacement increment, and a failure
// that is printed and kept for lastError().
class PathFollowingIntegrator : public Integrator {
 public:
  const std::string& lastError() const { return lastError_; }

 protected:
  // Forms P_ref and solves K dU_p = P_ref into referenceDisp_; false when dU_p is not finite.
  bool referenceDisplacement(AnalysisModel& model);
  // Time (the load factor) += dLambda, the prescribed values, then the nodes += dU (updates the elements).
  static void applyLoadIncrement(AnalysisModel& model, double dLambda, const Vector& dU);
  // "WARNING integrator <name>: why", kept in lastError(); returns -1.
  int fail(const std::string& why);

  Vector referenceLoad_, referenceDisp_;
  std::string lastError_;
};

}  // namespace beamsolid
