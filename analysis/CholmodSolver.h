#pragma once
#include "analysis/LinearSolver.h"

struct cholmod_common_struct;
struct cholmod_factor_struct;

namespace beamsolid {

// SuiteSparse CHOLMOD supernodal Cholesky for symmetric positive definite
// systems (upper triangle read); the symbolic analysis is reused.
class CholmodSolver : public LinearSolver {
 public:
  explicit CholmodSolver(std::string requestedName);
  ~CholmodSolver() override;
  std::string backend() const override { return "CHOLMOD"; }
  bool requiresSPD() const override { return true; }
  void analyze(const SparseView& A) override;
  bool factorize(const SparseView& A) override;
  // A Cholesky factorization exists only for a positive definite matrix.
  int determinantSign() const override { return factorized_ ? 1 : 0; }
  void solve(const double* b, double* x) override;

 private:
  cholmod_common_struct* common_;
  cholmod_factor_struct* factor_ = nullptr;
  bool factorized_ = false;  // the last factorize() succeeded
  int n_ = 0;
};

}  // namespace beamsolid
