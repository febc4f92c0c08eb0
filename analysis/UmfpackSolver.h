#pragma once
#include "analysis/LinearSolver.h"

namespace beamsolid {

// SuiteSparse UMFPACK: general (unsymmetric, indefinite) sparse LU with
// METIS ordering; the symbolic analysis is reused while the pattern holds.
class UmfpackSolver : public LinearSolver {
 public:
  explicit UmfpackSolver(std::string requestedName);
  ~UmfpackSolver() override;
  std::string backend() const override { return "UMFPACK"; }
  bool requiresSPD() const override { return false; }
  void analyze(const SparseView& A) override;
  bool factorize(const SparseView& A) override;
  int determinantSign() const override;
  void solve(const double* b, double* x) override;

 private:
  void freeNumeric();
  void freeSymbolic();
  double control_[20];
  double info_[90];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  SparseView A_;
};

}  // namespace beamsolid
