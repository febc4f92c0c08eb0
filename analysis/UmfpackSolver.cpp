#include "analysis/UmfpackSolver.h"

#include <umfpack.h>

#include <memory>

#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "analysis/SystemOptions.h"

namespace beamsolid {

UmfpackSolver::UmfpackSolver(std::string requestedName) : LinearSolver(std::move(requestedName)) {
  umfpack_di_defaults(control_);
  control_[UMFPACK_PRL] = 0;
  // METIS roughly halves the fill of 3D solid meshes compared with AMD.
  control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
}

UmfpackSolver::~UmfpackSolver() {
  freeNumeric();
  freeSymbolic();
}

void UmfpackSolver::freeNumeric() {
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void UmfpackSolver::freeSymbolic() {
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

void UmfpackSolver::analyze(const SparseView& A) {
  freeNumeric();
  freeSymbolic();
  A_ = A;
  if (A.n == 0) return;
  int status = umfpack_di_symbolic(A.n, A.n, A.colStart, A.rowIndex, A.values, &symbolic_, control_, info_);
  if (status == UMFPACK_ERROR_invalid_system || status < 0) {
    // METIS may be missing from a SuiteSparse build: fall back to AMD.
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
    status = umfpack_di_symbolic(A.n, A.n, A.colStart, A.rowIndex, A.values, &symbolic_, control_, info_);
  }
  if (status != UMFPACK_OK) throw OpenSeesError("system UmfPack: symbolic analysis failed (status " + std::to_string(status) + ")");
  ++numAnalyze_;
}

int UmfpackSolver::determinantSign() const {
  if (!numeric_) return 0;
  double mantissa = 0.0, exponent = 0.0;
  if (umfpack_di_get_determinant(&mantissa, &exponent, numeric_, nullptr) < 0) return 0;
  return mantissa > 0.0 ? 1 : (mantissa < 0.0 ? -1 : 0);
}

bool UmfpackSolver::factorize(const SparseView& A) {
  A_ = A;
  if (A.n == 0) return true;
  freeNumeric();
  const int status = umfpack_di_numeric(A.colStart, A.rowIndex, A.values, symbolic_, &numeric_, control_, info_);
  ++numFactorize_;
  failedEquation_ = -1;
  if (status == UMFPACK_WARNING_singular_matrix) {
    lastError_ = "the matrix is singular";
    return false;
  }
  if (status != UMFPACK_OK) {
    lastError_ = "numeric factorization failed (UMFPACK status " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

void UmfpackSolver::solve(const double* b, double* x) {
  if (A_.n == 0) return;
  const int status = umfpack_di_solve(UMFPACK_A, A_.colStart, A_.rowIndex, A_.values, x, b, numeric_, control_, info_);
  if (status != UMFPACK_OK && status != UMFPACK_WARNING_singular_matrix)
    throw OpenSeesError("system UmfPack: solve failed (status " + std::to_string(status) + ")");
}

namespace {
void registerUmfpack(Registry& r) {
  // Every general OpenSees system maps to UMFPACK: it handles unsymmetric and
  // indefinite matrices (frictional contact, Lagrange multipliers) and is the
  // fastest general sparse LU we have. The diagonal systems of explicit
  // dynamics solve exactly the same equations when the matrix is diagonal.
  for (const char* name : {"UmfPack", "Umfpack", "SparseGeneral", "SparseGEN", "BandGeneral", "BandGen", "BandGEN",
                           "FullGeneral", "Mumps", "SuperLU", "ProfileSPD_General", "Diagonal", "MPIDiagonal"})
    r.systems.add(name, [name](CommandArgs& args, Domain&) -> std::unique_ptr<LinearSolver> {
      auto solver = std::make_unique<UmfpackSolver>(name);
      readSystemOptions(args, *solver);
      return solver;
    });
}
}  // namespace
BEAMSOLID_REGISTER(registerUmfpack);

}  // namespace beamsolid
