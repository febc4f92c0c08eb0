#include "analysis/StaticAnalysis.h"

#include <iostream>

#include "core/Domain.h"
#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

StaticAnalysis::StaticAnalysis(Domain& domain, AnalysisComponents& components)
    : domain_(domain), components_(components), model_(domain) {}

int StaticAnalysis::analyze(int numSteps) {
  lastError_.clear();
  try {
    return runSteps(numSteps);
  } catch (const std::exception& e) {
    // OpenSees' contract: whatever happens while analyze runs (an element or
    // material that throws, a Python element's exception) is a failed step,
    // reported by a negative code so that scripts can change course and
    // retry; the model goes back to its last converged state.
    return fail(-3, std::string("an element failed: ") + e.what());
  }
}

int StaticAnalysis::fail(int code, const std::string& reason) {
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

int StaticAnalysis::runSteps(int numSteps) {
  AnalysisComponents& c = components_;
  for (int step = 0; step < numSteps; ++step) {
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
        reason = "the stiffness matrix is singular before any step converged (a mechanism or a missing "
                 "support?): " + reason;
      return fail(-3, reason);
    }
    c.integrator->commit(model_, c.test->numIterations());
    domain_.commit();
    ++stepsSinceSetup_;
  }
  return 0;
}

}  // namespace beamsolid
