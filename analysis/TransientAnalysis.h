#pragma once
#include "analysis/Analysis.h"

namespace beamsolid {

class TransientIntegrator;

// analysis('Transient' | 'VariableTransient'): analyze(n, dt) runs n steps
// of dt with a transient integrator. The variable form
// analyze(n, dt, dtMin, dtMax, Jd) runs until the elapsed time reaches
// n dt (as OpenSees: not n steps), scaling dt after each converged step by
// Jd / (iterations of that step) within [dtMin, dtMax]; a failed step is
// retried with half the dt, and the analysis gives up (-3) below dtMin. A failure leaves the model at its last converged state.
class TransientAnalysis : public Analysis {
 public:
  TransientAnalysis(Domain& domain, AnalysisComponents& components, bool variable);
  bool variable() const { return variable_; }
  int analyze(int numSteps, double dt);
  int analyze(int numSteps, double dt, double dtMin, double dtMax, int desiredIterations);

 private:
  TransientIntegrator& integrator();
  bool variable_;
};

}  // namespace beamsolid
