#pragma once
#include <vector>

#include "analysis/TransientIntegrator.h"

namespace beamsolid {

// integrator('CentralDifference'): M (U_n+1 - 2 U_n + U_n-1) / dt^2 +
// C (U_n+1 - U_n-1) / (2 dt) + F(U_n) = P(t_n), solved for U_n+1 (tangent
// C / (2 dt) + M / dt^2: every dof needs mass or damping). The step keeps
// the domain at U_n with the velocity and acceleration of t_n; at commit the
// nodes move to U_n+1 with OpenSees' reported velocity V_n + dt A_n and
// acceleration (V_n+1 - V_n reported) / dt. As in
// OpenSees, it needs algorithm('Linear'): a second update in a step fails.
class CentralDifference : public TransientIntegrator {
 public:
  std::string name() const override { return "CentralDifference"; }
  void domainChanged(AnalysisModel&) override { previous_.clear(); }
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& x) override;
  void commit(AnalysisModel& model, int iterations) override;

 private:
  double timeAtStart_ = 0.0;
  int updates_ = 0;
  std::vector<double> previous_, current_, next_;  // U_n-1, U_n, U_n+1 of each full dof
};

}  // namespace beamsolid
