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
};

// analyze(n): for each step the integrator starts it, the algorithm
// iterates, and the domain commits; on failure the domain reverts to its
// last committed state and a negative code is returned (-1 set-up, -2
// integrator, -3 algorithm or element), exactly as OpenSees scripts expect:
// analyze never throws, and lastError() says why it failed.
class StaticAnalysis {
 public:
  StaticAnalysis(Domain& domain, AnalysisComponents& components);
  int analyze(int numSteps);
  AnalysisModel& model() { return model_; }
  const std::string& lastError() const { return lastError_; }

 private:
  int runSteps(int numSteps);
  // Reverts to the last converged state, keeps and prints the reason.
  int fail(int code, const std::string& reason);

  Domain& domain_;
  AnalysisComponents& components_;
  AnalysisModel model_;
  std::string lastError_;
  long stepsSinceSetup_ = 0;
};

}  // namespace beamsolid
