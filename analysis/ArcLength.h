#pragma once
#include <string>

#include "analysis/PathFollowingIntegrator.h"

namespace beamsolid {

// integrator('ArcLength', s, alpha): spherical arc-length (Crisfield). Each
// step moves a distance s along the equilibrium path measured as
//   DU.DU + alpha^2 DLambda^2 = s^2
// (DU, DLambda: increments since the last commit; lambda is the Domain
// time). Every iteration solves K dU_r = R and K dU_p = P_ref on the same
// factorization and takes the root dLambda of the constraint on
// DU + dU_r + dLambda dU_p whose new increment makes the smaller angle with
// the previous one. The predictor keeps the direction of the last converged
// step; the first one goes along +P_ref when P_ref.K^-1 P_ref > 0 (stable
// start) and against it otherwise.
class ArcLength : public PathFollowingIntegrator {
 public:
  ArcLength(double arcLength, double alpha);
  std::string name() const override { return "ArcLength"; }
  void domainChanged(AnalysisModel& model) override;
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& dU) override;
  void commit(AnalysisModel& model, int iterations) override;
  void revert(AnalysisModel& model) override;

  double arcLength() const { return arcLength_; }
  // Roots were complex in an iteration of the last step (closest point taken).
  int complexRootIterations() const { return complexRoots_; }

 private:
  double arcLength_, alpha2_;
  // Increments of the current step and of the last converged one.
  Vector stepDisp_;
  double stepLambda_ = 0.0;
  Vector previousDisp_;
  double previousLambda_ = 0.0;
  bool hasPrevious_ = false;
  int complexRoots_ = 0;
};

}  // namespace beamsolid
