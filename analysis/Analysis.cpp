#include "analysis/Analysis.h"

#include <iostream>

#include "core/Domain.h"
#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

Analysis::Analysis(Domain& domain, AnalysisComponents& components)
    : domain_(domain), components_(components), model_(domain) {}

int Analysis::fail(int code, const std::string& reason) {
  lastError_ = reason;
  try {
    domain_.revertToLastCommit();
    if (components_.integrator) components_.integrator->revert(model_);
  } catch (const std::exception& e) {
    // The element that failed the step may fail again while the domain
    // re-evaluates the committed state; the reason is the same.
    if (reason.find(e.what()) == std::string::npos) lastError_ += std::string("; then, reverting: ") + e.what();
  }
  std::cerr << "WARNING analyze: " << lastError_ << "; the model is back at time " << domain_.currentTime()
            << " (analyze returns " << code << ")\n";
  return code;
}

int Analysis::setupStep() {
  AnalysisComponents& c = components_;
  try {
    if (model_.setup(*c.handler, *c.numberer, *c.solver)) {
      c.integrator->domainChanged(model_);
      stepsSinceSetup_ = 0;
    }
  } catch (const std::exception& e) {
    // A model the chosen handler, numberer or system cannot take (an
    // SPD-only system for contact, a constraint conflict): OpenSees' -1.
    return fail(-1, std::string("the analysis could not be set up: ") + e.what());
  }
  return 0;
}

int Analysis::oneStep() {
  AnalysisComponents& c = components_;
  int result = 0;
  std::string elementFailure;
  try {
    if (c.integrator->newStep(model_) < 0) return fail(-2, c.integrator->name() + ": could not start the step");
    result = c.algorithm->solveCurrentStep(model_, *c.integrator, *c.test);
  } catch (const ElementStateError& e) {
    result = -3;
    elementFailure = e.what();
  }
  if (result < 0) {
    std::string reason = c.algorithm->name() + " at time " + std::to_string(domain_.currentTime()) + ": " +
                         (elementFailure.empty() ? c.algorithm->lastError() : elementFailure);
    // A model singular before any step converged is a modelling error
    // rather than a convergence failure: say so (it is still -3, as OpenSees).
    if (elementFailure.empty() && c.algorithm->failedOnSingularMatrix() && stepsSinceSetup_ == 0 &&
        domain_.committedTime() == 0.0)
      reason = "the matrix is singular before any step converged (a mechanism, a missing support, or a "
               "dof without mass in a transient analysis?): " + reason;
    return fail(-3, reason);
  }
  // Sensitivities need the converged trial state and the last committed
  // history: before the commit. Their failure fails the step (guarded()).
  if (c.sensitivity) c.sensitivity->compute(model_, *c.integrator);
  c.integrator->commit(model_, c.test->numIterations());
  domain_.commit();
  ++stepsSinceSetup_;
  return 0;
}

}  // namespace beamsolid
