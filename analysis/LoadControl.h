#pragma once
#include "analysis/Integrator.h"

namespace beamsolid {

// integrator('LoadControl', dLambda, <numIter, minLambda, maxLambda>):
// time (the load factor) grows by dLambda each step, adapted by
// numIter / (iterations of the last step) within [minLambda, maxLambda].
class LoadControl : public Integrator {
 public:
  LoadControl(double increment, int desiredIterations, double minIncrement, double maxIncrement);
  std::string name() const override { return "LoadControl"; }
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& dU) override;
  void commit(AnalysisModel& model, int iterations) override;
  double increment() const { return increment_; }

 private:
  double increment_;
  int desiredIterations_;
  double minIncrement_, maxIncrement_;
  int lastIterations_ = 0;
};

}  // namespace beamsolid
