#pragma once
#include <string>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

class LinearSystem;

// Decides after each iteration whether a step has converged, and records
// the norm of every iteration (testNorm) so rates can be read back.
class ConvergenceTest {
 public:
  enum class Result { Converged, Continue, Failed };

  ConvergenceTest(double tolerance, int maxIterations, int printFlag, int normType)
      : tolerance_(tolerance), maxIterations_(maxIterations), printFlag_(printFlag), normType_(normType) {}
  virtual ~ConvergenceTest() = default;
  virtual std::string name() const = 0;

  // Called once per step after the first residual is formed.
  virtual void start(const LinearSystem& system);
  // Called after every update: b holds the new residual, x the increment just applied.
  Result test(const LinearSystem& system);
  // Whether the state passes the tolerance, without counting an iteration or
  // recording a norm (the inner iterations of BFGS and Broyden). Never for
  // FixedNumIter.
  bool wouldConverge(const LinearSystem& system) { return tolerance_ >= 0.0 && measure(system) <= tolerance_; }

  int numIterations() const { return iteration_; }
  // OpenSees' testIter: one past the last iteration when the step failed.
  int reportedIterations() const { return failed_ ? iteration_ + 1 : iteration_; }
  const std::vector<double>& norms() const { return norms_; }
  // What testNorm returns: the norms padded with zeros to maxIter entries
  // (at most `cap`); a test with two norms gives both lists, one after the other.
  virtual std::vector<double> reportedNorms(int cap) const;
  double tolerance() const { return tolerance_; }
  int maxIterations() const { return maxIterations_; }

 protected:
  virtual double measure(const LinearSystem& system) = 0;
  // Whether the value measure() just returned (and recorded) passes; the
  // relative tests compare a ratio, the combined ones two norms.
  virtual bool passes(double value) const { return value <= tolerance_; }
  // Whether the step has failed before maxIter (NormDispAndUnbalance's maxIncr).
  virtual bool diverged() const { return false; }
  double norm(const Vector& v) const;

  double tolerance_;
  int maxIterations_;
  int printFlag_;
  int normType_;
  int iteration_ = 0;
  bool failed_ = false;
  std::vector<double> norms_;
};

}  // namespace beamsolid
