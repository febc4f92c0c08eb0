#pragma once
#include "analysis/Algorithm.h"
#include "core/Types.h"

namespace beamsolid {

class LinearSystem;

// algorithm('NewtonLineSearch', '-type', t, '-tol', 0.8, '-maxIter', 10,
//           '-minEta', 0.1, '-maxEta', 10):
// Newton-Raphson with a line search along each Newton correction dU
// (Crisfield, Non-linear Finite Element Analysis of Solids and Structures,
// vol. 1, sec. 9.3). The step length eta seeks a zero of
//   s(eta) = dU . R(u + eta dU),
// which makes the residual orthogonal to the search direction; the search
// runs while |s(eta)| > tol |s(0)|. Types: 'InitialInterpolated' (default,
// linear interpolation between eta = 0 and the current eta), 'Secant'
// (through the last two points), 'RegulaFalsi' and 'Bisection' (on a
// bracket of sign change, grown while there is none).
class NewtonLineSearch : public Algorithm {
 public:
  enum class Search { InitialInterpolated, Secant, RegulaFalsi, Bisection };
  struct Options {
    Search search = Search::InitialInterpolated;
    double tolerance = 0.8;
    int maxIterations = 10;
    double minEta = 0.1;
    double maxEta = 10.0;
  };
  explicit NewtonLineSearch(const Options& options) : options_(options) {}
  std::string name() const override { return "NewtonLineSearch"; }
  int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) override;

  const Options& options() const { return options_; }
  // Residual evaluations spent in line searches during the last step.
  int lineSearchEvaluations() const { return evaluations_; }

 private:
  // Applies `step` through the integrator and adds what was applied to `total`.
  int move(AnalysisModel& model, Integrator& integrator, const Vector& step, Vector& total);
  // Starting at eta = 1 with s1 = s(1); leaves the model at the final eta.
  int search(AnalysisModel& model, Integrator& integrator, const Vector& direction, double s0, double s1,
             Vector& total);

  Options options_;
  int evaluations_ = 0;
};

}  // namespace beamsolid
