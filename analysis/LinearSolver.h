#pragma once
#include <string>

namespace beamsolid {

// A compressed-column matrix view (full storage, sorted rows).
struct SparseView {
  int n = 0;
  const int* colStart = nullptr;
  const int* rowIndex = nullptr;
  const double* values = nullptr;
  int nnz() const { return n ? colStart[n] : 0; }
};

// A sparse direct solver backend. analyze() runs once per pattern;
// factorize() every time the values change; solve() any number of times.
class LinearSolver {
 public:
  explicit LinearSolver(std::string requestedName) : requestedName_(std::move(requestedName)) {}
  virtual ~LinearSolver() = default;

  // The backend that actually runs ("UMFPACK", "CHOLMOD").
  virtual std::string backend() const = 0;
  // The OpenSees system name the user asked for ("BandGeneral", ...).
  const std::string& requestedName() const { return requestedName_; }
  // Only symmetric positive definite matrices (CHOLMOD).
  virtual bool requiresSPD() const = 0;

  virtual void analyze(const SparseView& A) = 0;
  // False on a singular (or, for SPD solvers, indefinite) matrix; lastError() says why.
  virtual bool factorize(const SparseView& A) = 0;
  virtual void solve(const double* b, double* x) = 0;
  // Sign of the determinant of the last factorized matrix: +1, -1, or 0 where the backend cannot tell.
  virtual int determinantSign() const { return 0; }

  // Counters for benchmarks and tests: how often each phase ran.
  int numAnalyze() const { return numAnalyze_; }
  int numFactorize() const { return numFactorize_; }
  const std::string& lastError() const { return lastError_; }
  // Equation at which the factorization broke down, -1 if unknown.
  int failedEquation() const { return failedEquation_; }

  // Static condensation of the equations only constant-tangent elements
  // touch (system(..., '-condense', 'auto'|'on'|'off'); see CondensedSolver).
  enum class Condensation { Auto, On, Off };
  Condensation condensation() const { return condensation_; }
  void setCondensation(Condensation c) { condensation_ = c; }

 protected:
  int numAnalyze_ = 0;
  int numFactorize_ = 0;
  std::string lastError_;
  int failedEquation_ = -1;
  Condensation condensation_ = Condensation::Auto;

 private:
  std::string requestedName_;
};

}  // namespace beamsolid
