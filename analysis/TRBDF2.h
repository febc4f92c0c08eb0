#pragma once
#include <vector>

#include "analysis/TransientIntegrator.h"

namespace beamsolid {

// integrator('TRBDF2'): Bathe's composite scheme as OpenSees runs it, each
// analyze step one sub-step of dt that alternates the trapezoidal rule
// (Newmark 1/2, 1/4) and the three-point backward difference
// v_n+1 = (3 u_n+1 - 4 u_n + u_n-1) / (2 dt), likewise a from v.
class TRBDF2 : public TransientIntegrator {
 public:
  std::string name() const override { return "TRBDF2"; }
  void domainChanged(AnalysisModel&) override { step_ = 0; }
  int newStep(AnalysisModel& model) override;
  int update(AnalysisModel& model, const Vector& x) override;
  void commit(AnalysisModel& model, int iterations) override;

 private:
  bool backward() const { return step_ % 2 == 1; }
  long step_ = 0;
  double cv_ = 0.0, ca_ = 0.0;
  // u, v of the step before the last committed one (the backward difference's n-1).
  std::vector<double> uPrev_, vPrev_, uLast_, vLast_;
  std::vector<double> u1_, v1_, a1_;
};

}  // namespace beamsolid
