#include "analysis/CholmodSolver.h"

#include <cholmod.h>

#include <cstring>
#include <memory>

#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "analysis/SystemOptions.h"

namespace beamsolid {

namespace {
cholmod_sparse viewOf(const SparseView& A) {
  cholmod_sparse s{};
  s.nrow = s.ncol = A.n;
  s.nzmax = A.nnz();
  s.p = const_cast<int*>(A.colStart);
  s.i = const_cast<int*>(A.rowIndex);
  s.x = const_cast<double*>(A.values);
  s.stype = 1;  // symmetric, upper triangle used
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}
}  // namespace

CholmodSolver::CholmodSolver(std::string requestedName)
    : LinearSolver(std::move(requestedName)), common_(new cholmod_common) {
  cholmod_start(common_);
  common_->supernodal = CHOLMOD_SUPERNODAL;
  common_->print = 0;
  common_->error_handler = nullptr;
}

CholmodSolver::~CholmodSolver() {
  if (factor_) cholmod_free_factor(&factor_, common_);
  cholmod_finish(common_);
  delete common_;
}

void CholmodSolver::analyze(const SparseView& A) {
  if (factor_) cholmod_free_factor(&factor_, common_);
  n_ = A.n;
  if (n_ == 0) return;
  cholmod_sparse s = viewOf(A);
  factor_ = cholmod_analyze(&s, common_);
  if (!factor_) throw OpenSeesError("system Cholmod: symbolic analysis failed");
  ++numAnalyze_;
}

bool CholmodSolver::factorize(const SparseView& A) {
  if (n_ == 0) return true;
  cholmod_sparse s = viewOf(A);
  cholmod_factorize(&s, factor_, common_);
  ++numFactorize_;
  failedEquation_ = -1;
  factorized_ = false;
  if (common_->status == CHOLMOD_NOT_POSDEF) {
    const auto minor = static_cast<int>(factor_->minor);
    const int* perm = static_cast<const int*>(factor_->Perm);
    failedEquation_ = (perm && minor < n_) ? perm[minor] : -1;
    lastError_ = "the matrix is not positive definite";
    return false;
  }
  if (common_->status < CHOLMOD_OK) {
    lastError_ = "factorization failed (CHOLMOD status " + std::to_string(common_->status) + ")";
    return false;
  }
  factorized_ = true;
  return true;
}

void CholmodSolver::solve(const double* b, double* x) {
  if (n_ == 0) return;
  cholmod_dense B{};
  B.nrow = n_;
  B.ncol = 1;
  B.nzmax = n_;
  B.d = n_;
  B.x = const_cast<double*>(b);
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, factor_, &B, common_);
  if (!X) throw OpenSeesError("system Cholmod: solve failed");
  std::memcpy(x, X->x, sizeof(double) * n_);
  cholmod_free_dense(&X, common_);
}

namespace {
void registerCholmod(Registry& r) {
  // The SPD OpenSees systems map to CHOLMOD, 3-7x faster than UMFPACK on SPD stiffness.
  for (const char* name : {"Cholmod", "BandSPD", "ProfileSPD", "SProfileSPD", "ParallelProfileSPD", "SparseSYM",
                           "SparseSPD"})
    r.systems.add(name, [name](CommandArgs& args, Domain&) -> std::unique_ptr<LinearSolver> {
      auto solver = std::make_unique<CholmodSolver>(name);
      readSystemOptions(args, *solver);
      return solver;
    });
}
}  // namespace
BEAMSOLID_REGISTER(registerCholmod);

}  // namespace beamsolid
