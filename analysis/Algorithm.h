#pragma once
#include <string>

namespace beamsolid {

class AnalysisModel;
class ConvergenceTest;
class Integrator;

// Drives the iterations of one step (OpenSees' SolutionAlgorithm).
class Algorithm {
 public:
  virtual ~Algorithm() = default;
  virtual std::string name() const = 0;
  // 0 when the step converged, negative otherwise; lastError() says why.
  virtual int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) = 0;
  const std::string& lastError() const { return lastError_; }
  // True when the last failure was a singular matrix (not slow convergence).
  bool failedOnSingularMatrix() const { return singular_; }

 protected:
  // Forms and factors the current (initial = false) or initial tangent; the
  // initial one never changes and is factored once. False when singular,
  // with lastError() naming the dofs.
  bool formAndFactor(AnalysisModel& model, Integrator& integrator, bool initial);
  // The test gave up: keeps "<test> failed to converge in <n> <what> (last norm, tolerance)"
  // for lastError() and returns -3 (OpenSees' failed step).
  int notConverged(const ConvergenceTest& test, const std::string& what = "iterations");

  std::string lastError_;
  bool singular_ = false;
};

}  // namespace beamsolid
