#pragma once
#include <vector>

#include "analysis/TransientIntegrator.h"

namespace beamsolid {

// integrator('ExplicitDifference'): explicit central differences in
// half-step (leapfrog) form, as OpenSees documents and runs it:
//   V_n+1/2 = V_n-1/2 + dt A_n,   U_n+1 = U_n + dt V_n+1/2,
//   M A_n+1 = P(t_n+1) - F(U_n+1) - C V_n+1/2,
// so the system matrix is M alone (every free dof needs mass; damping and
// stiffness limit the step: dt <= 2 / w_max without damping). The first step
// starts with V_-1/2 = 0 and A_0 = the nodes' (zero) accelerations. The
// velocity reported at t_n+1 is OpenSees' V_n+1/2 + dt (3 A_n+1 + A_n) / 8
// (checked against OpenSeesPy). Needs algorithm('Linear').
class ExplicitDifference : public TransientIntegrator {
 public:
  std::string name() const override { return "ExplicitDifference"; }
  void domainChanged(AnalysisModel&) override { halfVel_.clear(); }
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& x) override;
  void commit(AnalysisModel& model, int iterations) override;

 private:
  int updates_ = 0;
  std::vector<double> halfVel_;      // V_n-1/2 of each full dof (committed)
  std::vector<double> nextHalfVel_;  // V_n+1/2 of the step being taken
  std::vector<double> accelAtStart_; // A_n
};

}  // namespace beamsolid
