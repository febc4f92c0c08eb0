#pragma once
#include <string>
#include <vector>

#include "analysis/DofMap.h"
#include "analysis/PathFollowingIntegrator.h"

namespace beamsolid {

// integrator('DisplacementControl', nodeTag, dof, incr, <numIter, dUmin, dUmax>):
// each step moves dof `dof` of node `nodeTag` by `incr`; the load factor
// lambda (the Domain time) is whatever equilibrium needs. Every iteration
// solves K dU_r = R and K dU_p = P_ref on the same factorization and takes
// dLambda so that the controlled dof sits exactly on its target:
//   dLambda = (target - u_c - e.dU_r) / e.dU_p,  dU = dU_r + dLambda dU_p.
// The increment adapts by numIter / (iterations of the last step) within
// [dUmin, dUmax] (in magnitude, keeping its sign).
class DisplacementControl : public PathFollowingIntegrator {
 public:
  // dof is 0-based here.
  DisplacementControl(int nodeTag, int dof, double increment, int desiredIterations, double minIncrement,
                      double maxIncrement);
  std::string name() const override { return "DisplacementControl"; }
  void domainChanged(AnalysisModel& model) override;
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& dU) override;
  void commit(AnalysisModel& model, int iterations) override;
  void revert(AnalysisModel& model) override;

  double increment() const { return increment_; }
  bool controlledDof(std::vector<DofMap::Term>& terms) const override {
    terms = control_;
    return true;
  }

 private:
  // The controlled dof as a combination of equations (checks node and dof).
  void resolve(AnalysisModel& model);
  double controlled(const Vector& v) const;
  // dU_p = K^-1 P_ref with the current factorization; false if it does not move the controlled dof.
  bool movesControlledDof(AnalysisModel& model);

  int nodeTag_, dof_;
  double increment_;
  int desiredIterations_;
  double minIncrement_, maxIncrement_;
  int lastIterations_ = 0;
  std::vector<DofMap::Term> control_;
  double target_ = 0.0;  // value of the controlled dof at the end of this step
};

}  // namespace beamsolid
