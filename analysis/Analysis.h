#pragma once
#include <memory>
#include <string>

#include "analysis/Algorithm.h"
#include "analysis/AnalysisModel.h"
#include "analysis/ConstraintHandler.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "analysis/LinearSolver.h"
#include "analysis/Numberer.h"
#include "analysis/SensitivityAlgorithm.h"

namespace beamsolid {

class Domain;

// The analysis objects a script chose with constraints/numberer/system/
// test/algorithm/integrator; missing ones get OpenSees' defaults.
struct AnalysisComponents {
  std::unique_ptr<ConstraintHandler> handler;
  std::unique_ptr<Numberer> numberer;
  std::unique_ptr<LinearSolver> solver;
  std::unique_ptr<ConvergenceTest> test;
  std::unique_ptr<Algorithm> algorithm;
  std::unique_ptr<Integrator> integrator;
  std::unique_ptr<SensitivityAlgorithm> sensitivity;  // sensitivityAlgorithm, if any
};

// What Static and Transient analyses share: one step is set-up (renumber
// if the model changed), the integrator's newStep, the algorithm's
// iterations and the commit; on failure the domain reverts to its last
// committed state (displacements, velocities, accelerations, element
// state) and a negative code is returned (-1 set-up, -2 integrator, -3
// algorithm or element), exactly as OpenSees scripts expect: analyze never
// throws, and lastError() says why it failed.
class Analysis {
 public:
  Analysis(Domain& domain, AnalysisComponents& components);
  virtual ~Analysis() = default;
  AnalysisModel& model() { return model_; }
  const std::string& lastError() const { return lastError_; }

 protected:
  // Runs `steps` (a callable returning a code) and turns any exception into -3.
  template <class Steps>
  int guarded(Steps&& steps) {
    lastError_.clear();
    try {
      return steps();
    } catch (const std::exception& e) {
      // OpenSees' contract: whatever happens while analyze runs (an element
      // or material that throws, a Python element's exception) is a failed
      // step, reported by a negative code so that scripts can change course.
      return fail(-3, std::string("an element failed: ") + e.what());
    }
  }
  // Set-up before a step; 0 or the failure code.
  int setupStep();
  // One step from the integrator's newStep to the commit; 0 or the failure code.
  int oneStep();
  // Reverts to the last converged state, keeps and prints the reason.
  int fail(int code, const std::string& reason);

  Domain& domain_;
  AnalysisComponents& components_;
  AnalysisModel model_;
  std::string lastError_;
  long stepsSinceSetup_ = 0;
};

}  // namespace beamsolid
