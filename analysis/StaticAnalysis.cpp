#include "analysis/StaticAnalysis.h"

#include <iostream>

#include "core/Domain.h"
#include "core/ElementStateError.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

StaticAnalysis::StaticAnalysis(Domain& domain, AnalysisComponents& components)
    : domain_(domain), components_(components), model_(domain) {}

int StaticAnalysis::analyze(int numSteps) {
  try {
    return runSteps(numSteps);
  } catch (...) {
    // An element or material that throws mid-step (bad state, a Python
    // element's exception) must not leave a half-updated model behind.
    domain_.revertToLastCommit();
    if (components_.integrator) components_.integrator->revert(model_);
    throw;
  }
}

int StaticAnalysis::runSteps(int numSteps) {
  AnalysisComponents& c = components_;
  for (int step = 0; step < numSteps; ++step) {
    if (model_.setup(*c.handler, *c.numberer, *c.solver)) {
      c.integrator->domainChanged(model_);
      stepsSinceSetup_ = 0;
    }
    int result = 0;
    std::string elementFailure;
    try {
      if (c.integrator->newStep(model_) < 0) {
        lastError_ = c.integrator->name() + ": could not start the step";
        domain_.revertToLastCommit();
        c.integrator->revert(model_);
        return -2;
      }
      result = c.algorithm->solveCurrentStep(model_, *c.integrator, *c.test);
    } catch (const ElementStateError& e) {
      result = -3;
      elementFailure = e.what();
    }
    if (result < 0) {
      lastError_ = c.algorithm->name() + " at time " + std::to_string(domain_.currentTime()) + ": " +
                   (elementFailure.empty() ? c.algorithm->lastError() : elementFailure);
      const bool singularModel = elementFailure.empty() && c.algorithm->failedOnSingularMatrix() && stepsSinceSetup_ == 0 &&
                                 domain_.committedTime() == 0.0;
      // A model that is singular before any step converged is a modelling
      // error, not a convergence failure: say so loudly (analyze() reverts).
      if (singularModel) throw OpenSeesError("analyze: the stiffness matrix is singular: " + c.algorithm->lastError());
      domain_.revertToLastCommit();
      c.integrator->revert(model_);
      std::cerr << "WARNING analyze: step failed: " << lastError_ << "; the model is back at time "
                << domain_.currentTime() << "\n";
      return -3;
    }
    c.integrator->commit(model_, c.test->numIterations());
    domain_.commit();
    ++stepsSinceSetup_;
  }
  return 0;
}

}  // namespace beamsolid
