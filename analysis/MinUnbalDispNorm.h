#pragma once
#include <string>

#include "analysis/PathFollowingIntegrator.h"

namespace beamsolid {

// integrator('MinUnbalDispNorm', dlambda1, <Jd, minLambda, maxLambda>):
// a static path-following step whose load factor corrections minimise the
// norm of the displacement increment (Chan 1988): every iteration solves
// K dU_r = R and K dU_p = P_ref on the same factorization and takes
// dLambda = -(dU_p . dU_r) / (dU_p . dU_p). The first increment of a step is
// dlambda1 of the last step times Jd / (its iterations), its size clamped to
// [minLambda, maxLambda] (default: dlambda1 for both); its sign makes
// dLambda dU_p point along the last step's displacement increment, which
// carries the path past limit points. (OpenSees' '-det'
// sign rule, by the stiffness determinant, is not available.)
class MinUnbalDispNorm : public PathFollowingIntegrator {
 public:
  MinUnbalDispNorm(double dLambda1, int desiredIterations, double minLambda, double maxLambda, bool byDeterminant);
  std::string name() const override { return "MinUnbalDispNorm"; }
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& dU) override;
  void commit(AnalysisModel& model, int iterations) override;
  void revert(AnalysisModel& model) override;

 private:
  double dLambda1_;
  int desiredIterations_;
  double minLambda_, maxLambda_;
  int lastIterations_ = 0;
  bool byDeterminant_;
  double sign_ = 1.0;
  int lastDeterminantSign_ = 0;
  double stepLambda_ = 0.0, previousStepLambda_ = 0.0;
};

}  // namespace beamsolid
