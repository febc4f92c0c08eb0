#pragma once
#include <vector>

#include "analysis/LinearSolver.h"
#include "core/Types.h"

namespace beamsolid {

class DofMap;

// A x = b on the DofMap's fixed compressed-column pattern: values are
// overwritten each iteration, the solver's symbolic analysis is redone only
// when the pattern (or the solver) changes.
class LinearSystem {
 public:
  void setPattern(const DofMap& map);
  void setSolver(LinearSolver* solver);
  LinearSolver* solver() const { return solver_; }

  int size() const { return n_; }
  std::vector<double>& values() { return values_; }
  const std::vector<double>& values() const { return values_; }
  Vector& b() { return b_; }
  Vector& x() { return x_; }
  const Vector& b() const { return b_; }
  const Vector& x() const { return x_; }
  void zeroA() { std::fill(values_.begin(), values_.end(), 0.0); }
  void zeroB() { b_.setZero(); }

  // Factorizes the current values; false when singular (see lastError()).
  bool factor();
  // Solves with the last factorization: x = A^-1 b.
  void solve();
  void solve(const Vector& rhs, Vector& out);
  bool isFactored() const { return factored_; }
  void invalidateFactor() { factored_ = false; }
  // The solver object changed in place (a new one at the same address).
  void resetSolverState() { analyzed_ = factored_ = false; }
  SparseView view() const;
  // Wall time spent in factor() and solve() so far (benchmarks: the solver's share).
  double solverSeconds() const { return solverSeconds_; }

 private:
  const DofMap* map_ = nullptr;
  LinearSolver* solver_ = nullptr;
  bool analyzed_ = false;
  bool factored_ = false;
  int n_ = 0;
  double solverSeconds_ = 0.0;
  std::vector<double> values_;
  Vector b_, x_;
};

}  // namespace beamsolid
