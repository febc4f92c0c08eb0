#include "analysis/CondensedSolver.h"

#include <cholmod.h>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "analysis/CondensationCache.h"
#include "core/BlasThreads.h"
#include "core/OpenSeesError.h"

extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dpotrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda, double* b,
             const int* ldb, int* info);
}

namespace beamsolid {

namespace {

// The process's CPU time (all threads: a threaded BLAS counts in full).
double now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// Adds the scope's CPU time to a counter.
struct Timed {
  double& total;
  double start = now();
  ~Timed() { total += now() - start; }
};

// Columns of A_II^-1 A_IB solved at once: a dense block of n_I x kBlock.
constexpr int kBlock = 64;
// Interfaces smaller than this are factored every time (a few ms).
constexpr int kMinReuse = 256;
// From this interface size on the dense factorization and the condensation
// run on every BLAS thread (a second or more of BLAS-3 work per call).
constexpr int kThreadedInterface = 4000;
// GMRES: restart length, iterations at most per solve, relative residual.
constexpr int kRestart = 60;
constexpr int kMaxKrylov = 240;
constexpr double kKrylovTol = 1e-13;
// Accepted when GMRES stagnates above kKrylovTol (round-off of an
// ill-conditioned interface: contact multipliers next to soil stiffness);
// Newton corrects an error this small in its next iteration like round-off.
constexpr double kKrylovAccept = 1e-10;

cholmod_dense denseView(double* x, int rows, int cols) {
  cholmod_dense d{};
  d.nrow = rows;
  d.ncol = cols;
  d.nzmax = static_cast<size_t>(rows) * cols;
  d.d = rows;
  d.x = x;
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

// A CSC matrix of which CHOLMOD reads the upper triangle.
cholmod_sparse symmetricView(int n, std::vector<int>& start, std::vector<int>& row, std::vector<double>& values) {
  cholmod_sparse s{};
  s.nrow = s.ncol = n;
  s.nzmax = row.size();
  s.p = start.data();
  s.i = row.data();
  s.x = values.data();
  s.stype = 1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

}  // namespace

CondensedSolver::CondensedSolver(std::string requestedName, std::string outerBackend, bool spd,
                                 std::vector<char> interior, Reuse reuse)
    : LinearSolver(std::move(requestedName)),
      outerBackend_(std::move(outerBackend)),
      spd_(spd),
      interior_(std::move(interior)),
      // An SPD solver must fail on an indefinite matrix as CHOLMOD would:
      // only a fresh factorization tells, so no reuse there.
      reuse_(spd ? Reuse::Off : reuse),
      common_(new cholmod_common) {
  cholmod_start(common_);
  common_->supernodal = CHOLMOD_SUPERNODAL;
  common_->print = 0;
  common_->error_handler = nullptr;
}

CondensedSolver::~CondensedSolver() {
  freeFactor();
  cholmod_finish(common_);
  delete common_;
}

void CondensedSolver::freeFactor() {
  if (factor_) cholmod_free_factor(&factor_, common_);
  factor_ = nullptr;
  for (cholmod_dense** d : {&solveX_, &solveY_, &solveE_})
    if (*d) cholmod_free_dense(d, common_);
}

void CondensedSolver::analyze(const SparseView& A) {
  if (static_cast<int>(interior_.size()) != A.n)
    throw OpenSeesError("system " + requestedName() + ": condensation partition does not match the equations");
  n_ = A.n;
  nI_ = nB_ = 0;
  local_.assign(n_, -1);
  for (int eq = 0; eq < n_; ++eq) local_[eq] = interior_[eq] ? nI_++ : nB_++;

  iiStart_.assign(nI_ + 1, 0);
  ibStart_.assign(nB_ + 1, 0);
  iiRow_.clear(), iiSource_.clear(), ibRow_.clear(), ibSource_.clear();
  biRow_.clear(), biCol_.clear(), biSource_.clear(), bbDense_.clear(), bbSource_.clear();
  // Columns are visited in order and the maps are monotone, so each block's
  // columns come out sorted, as CHOLMOD wants them.
  for (int col = 0; col < n_; ++col) {
    const int c = local_[col];
    for (int p = A.colStart[col]; p < A.colStart[col + 1]; ++p) {
      const int row = A.rowIndex[p];
      const int r = local_[row];
      if (interior_[col]) {
        if (interior_[row]) {
          iiRow_.push_back(r);
          iiSource_.push_back(p);
        } else {
          biRow_.push_back(r);
          biCol_.push_back(c);
          biSource_.push_back(p);
        }
      } else if (interior_[row]) {
        ibRow_.push_back(r);
        ibSource_.push_back(p);
      } else {
        bbDense_.push_back(r + c * nB_);
        bbSource_.push_back(p);
      }
    }
    if (interior_[col]) iiStart_[c + 1] = static_cast<int>(iiRow_.size());
    else ibStart_[c + 1] = static_cast<int>(ibRow_.size());
  }
  iiValues_.assign(iiSource_.size(), 0.0);
  ibValues_.assign(ibSource_.size(), 0.0);
  biValues_.assign(biSource_.size(), 0.0);
  bbCurrent_.assign(bbSource_.size(), 0.0);
  condensed_ = false;
  factored_ = false;

  freeFactor();
  if (nI_ > 0) {
    cholmod_sparse s = symmetricView(nI_, iiStart_, iiRow_, iiValues_);
    factor_ = cholmod_analyze(&s, common_);
    if (!factor_) throw OpenSeesError("system " + requestedName() + ": symbolic analysis of the condensed block failed");
  }
  ++numAnalyze_;
}

bool CondensedSolver::condense() {
  Timed timed{condenseSeconds_};
  BlasThreads::Scope threads(nB_ >= kThreadedInterface ? BlasThreads::available() : 1);
  // The same constant part condensed before in this process (a rebuilt model): reuse it.
  std::unique_ptr<CondensationCache::Key> key;
  if (nI_ > 0 && CondensationCache::enabled()) {
    key = std::make_unique<CondensationCache::Key>(CondensationCache::Key{
        interior_, iiStart_, iiRow_, ibStart_, ibRow_, biRow_, biCol_, iiValues_, ibValues_, biValues_});
    cholmod_factor* cached = nullptr;
    if (CondensationCache::find(*key, common_, &cached, coupling_)) {
      if (factor_) cholmod_free_factor(&factor_, common_);
      factor_ = cached;
      condensed_ = true;
      ++numCondensationsReused_;
      return true;
    }
  }
  if (nI_ > 0) {
    cholmod_sparse s = symmetricView(nI_, iiStart_, iiRow_, iiValues_);
    cholmod_factorize(&s, factor_, common_);
    if (common_->status != CHOLMOD_OK) {
      lastError_ = "the condensed block (equations of constant-tangent elements only) is not positive definite";
      return false;
    }
  }
  // coupling = A_BI A_II^-1 A_IB, column block by column block of A_IB.
  coupling_.assign(static_cast<size_t>(nB_) * nB_, 0.0);
  std::vector<int> columns;
  for (int c = 0; c < nB_; ++c)
    if (ibStart_[c + 1] > ibStart_[c]) columns.push_back(c);
  // A_BI by interior column, for the product with the solved block.
  std::vector<int> biStart(nI_ + 1, 0), biOrder(biRow_.size());
  for (int col : biCol_) ++biStart[col + 1];
  for (int c = 0; c < nI_; ++c) biStart[c + 1] += biStart[c];
  {
    std::vector<int> next(biStart.begin(), biStart.end() - 1);
    for (int k = 0; k < static_cast<int>(biCol_.size()); ++k) biOrder[next[biCol_[k]]++] = k;
  }
  std::vector<double> block(static_cast<size_t>(nI_) * kBlock);
  for (std::size_t first = 0; first < columns.size(); first += kBlock) {
    const int width = static_cast<int>(std::min<std::size_t>(kBlock, columns.size() - first));
    std::fill(block.begin(), block.begin() + static_cast<size_t>(nI_) * width, 0.0);
    for (int t = 0; t < width; ++t) {
      const int c = columns[first + t];
      for (int p = ibStart_[c]; p < ibStart_[c + 1]; ++p) block[ibRow_[p] + static_cast<size_t>(t) * nI_] = ibValues_[p];
    }
    cholmod_dense rhs = denseView(block.data(), nI_, width);
    cholmod_dense* y = cholmod_solve(CHOLMOD_A, factor_, &rhs, common_);
    if (!y) {
      lastError_ = "solve with the condensed block failed";
      return false;
    }
    const double* Y = static_cast<const double*>(y->x);
    for (int ci = 0; ci < nI_; ++ci)
      for (int q = biStart[ci]; q < biStart[ci + 1]; ++q) {
        const int k = biOrder[q];
        const double a = biValues_[k];
        const int r = biRow_[k];
        for (int t = 0; t < width; ++t)
          coupling_[r + static_cast<size_t>(columns[first + t]) * nB_] += a * Y[ci + static_cast<size_t>(t) * nI_];
      }
    cholmod_free_dense(&y, common_);
  }
  condensed_ = true;
  ++numCondensations_;
  if (key) CondensationCache::store(*key, factor_, coupling_);
  return true;
}

bool CondensedSolver::factorize(const SparseView& A) {
  ++numFactorize_;
  failedEquation_ = -1;
  // Redo the condensation only when a constant block changed.
  bool same = condensed_;
  auto gather = [&](const std::vector<int>& source, std::vector<double>& values) {
    for (std::size_t k = 0; k < source.size(); ++k) {
      const double v = A.values[source[k]];
      if (v != values[k]) {
        same = false;
        values[k] = v;
      }
    }
  };
  gather(iiSource_, iiValues_);
  gather(ibSource_, ibValues_);
  gather(biSource_, biValues_);
  if (!same) {
    factored_ = false;
    if (!condense()) return false;
  }
  for (std::size_t k = 0; k < bbSource_.size(); ++k) bbCurrent_[k] = A.values[bbSource_[k]];
  if (nB_ == 0) return true;
  deltaRow_.clear(), deltaCol_.clear(), deltaValue_.clear();
  bool fresh = reuse_ == Reuse::Off || !factored_ || refactorNext_ || (reuse_ == Reuse::Auto && nB_ < kMinReuse);
  if (!fresh) {
    for (std::size_t k = 0; k < bbSource_.size(); ++k) {
      const double d = bbCurrent_[k] - bbReference_[k];
      if (d == 0.0) continue;
      deltaRow_.push_back(bbDense_[k] % nB_);
      deltaCol_.push_back(bbDense_[k] / nB_);
      deltaValue_.push_back(d);
    }
    // A change of most entries is no low-rank update: factor.
    fresh = deltaValue_.size() > bbSource_.size() / 2 + 16 * static_cast<std::size_t>(nB_);
  }
  return fresh ? factorInterface() : true;
}

bool CondensedSolver::factorInterface() {
  deltaRow_.clear(), deltaCol_.clear(), deltaValue_.clear();
  refactorNext_ = false;
  factored_ = false;
  schur_.resize(coupling_.size());
  for (std::size_t k = 0; k < schur_.size(); ++k) schur_[k] = -coupling_[k];
  for (std::size_t k = 0; k < bbSource_.size(); ++k) schur_[bbDense_[k]] += bbCurrent_[k];
  ++numInterfaceFactorizations_;
  Timed timed{factorSeconds_};
  BlasThreads::Scope threads(nB_ >= kThreadedInterface ? BlasThreads::available() : 1);
  int info = 0;
  if (spd_) {
    dpotrf_("U", &nB_, schur_.data(), &nB_, &info);
    if (info != 0) lastError_ = "the matrix is not positive definite";
  } else {
    pivots_.resize(nB_);
    dgetrf_(&nB_, &nB_, schur_.data(), &nB_, pivots_.data(), &info);
    if (info != 0) lastError_ = "the matrix is singular";
  }
  if (info > 0) {
    // The breakdown is in S: name an interface equation.
    int seen = 0;
    for (int eq = 0; eq < n_; ++eq)
      if (!interior_[eq] && seen++ == info - 1) failedEquation_ = eq;
  }
  if (info != 0) return false;
  factored_ = true;
  bbReference_ = bbCurrent_;
  return true;
}

void CondensedSolver::applyReference(double* v) {
  int info = 0, one = 1;
  if (spd_) dpotrs_("U", &nB_, &one, schur_.data(), &nB_, v, &nB_, &info);
  else dgetrs_("N", &nB_, &one, schur_.data(), &nB_, pivots_.data(), v, &nB_, &info);
  if (info != 0) throw OpenSeesError("system " + requestedName() + ": interface solve failed");
}

// Right-preconditioned restarted GMRES on (S_ref + Delta) S_ref^-1 y = b
// (modified Gram-Schmidt, Givens rotations); x = S_ref^-1 y. Saad, Iterative
// Methods for Sparse Linear Systems, 2nd ed., algorithms 6.9 and 9.5.
bool CondensedSolver::solveInterface(double* bB) {
  Timed timed{interfaceSolveSeconds_};
  const int n = nB_;
  if (deltaValue_.empty()) {
    applyReference(bB);
    return true;
  }
  auto norm = [n](const double* v) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += v[i] * v[i];
    return std::sqrt(s);
  };
  const double bnorm = norm(bB);
  if (bnorm == 0.0) return true;
  const int m = std::min(kRestart, n);
  krylov_.resize(static_cast<size_t>(m + 1) * n);
  hessenberg_.resize(static_cast<size_t>(m + 1) * m);
  std::vector<double> y(n, 0.0), r(bB, bB + n), z(n), cs(m), sn(m), g(m + 1), c(m);
  // r <- b - M y with M y = y + Delta S_ref^-1 y.
  auto residual = [&]() {
    std::copy(y.begin(), y.end(), z.begin());
    applyReference(z.data());
    for (int i = 0; i < n; ++i) r[i] = bB[i] - y[i];
    for (std::size_t k = 0; k < deltaValue_.size(); ++k) r[deltaRow_[k]] -= deltaValue_[k] * z[deltaCol_[k]];
  };
  const double tol = kKrylovTol * bnorm;
  int iterations = 0;
  double rnorm = bnorm;
  while (rnorm > tol && iterations < kMaxKrylov) {
    double* V = krylov_.data();
    double* H = hessenberg_.data();
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = rnorm;
    for (int i = 0; i < n; ++i) V[i] = r[i] / rnorm;
    int k = 0;
    for (int j = 0; j < m && iterations < kMaxKrylov; ++j) {
      ++iterations;
      double* w = V + static_cast<size_t>(j + 1) * n;
      std::copy(V + static_cast<size_t>(j) * n, V + static_cast<size_t>(j + 1) * n, z.begin());
      applyReference(z.data());
      std::copy(V + static_cast<size_t>(j) * n, V + static_cast<size_t>(j + 1) * n, w);
      for (std::size_t q = 0; q < deltaValue_.size(); ++q) w[deltaRow_[q]] += deltaValue_[q] * z[deltaCol_[q]];
      double* h = H + static_cast<size_t>(j) * (m + 1);
      for (int i = 0; i <= j; ++i) {
        const double* vi = V + static_cast<size_t>(i) * n;
        double d = 0.0;
        for (int p = 0; p < n; ++p) d += w[p] * vi[p];
        h[i] = d;
        for (int p = 0; p < n; ++p) w[p] -= d * vi[p];
      }
      h[j + 1] = norm(w);
      if (h[j + 1] > 0.0)
        for (int p = 0; p < n; ++p) w[p] /= h[j + 1];
      for (int i = 0; i < j; ++i) {
        const double a = cs[i] * h[i] + sn[i] * h[i + 1];
        h[i + 1] = -sn[i] * h[i] + cs[i] * h[i + 1];
        h[i] = a;
      }
      const double d = std::hypot(h[j], h[j + 1]);
      cs[j] = d > 0.0 ? h[j] / d : 1.0;
      sn[j] = d > 0.0 ? h[j + 1] / d : 0.0;
      h[j] = d;
      h[j + 1] = 0.0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      k = j + 1;
      if (std::abs(g[j + 1]) <= tol || d == 0.0) break;
    }
    // y += V_k c with H_k c = g_k (upper triangular).
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int q = i + 1; q < k; ++q) s -= H[static_cast<size_t>(q) * (m + 1) + i] * c[q];
      const double hii = H[static_cast<size_t>(i) * (m + 1) + i];
      c[i] = hii != 0.0 ? s / hii : 0.0;
    }
    for (int i = 0; i < k; ++i) {
      const double* vi = V + static_cast<size_t>(i) * n;
      for (int p = 0; p < n; ++p) y[p] += c[i] * vi[p];
    }
    const double before = rnorm;
    residual();  // the true residual decides, not the recurrence
    rnorm = norm(r.data());
    if (!(rnorm < 0.5 * before) && rnorm > tol) break;  // stagnates
  }
  numKrylovIterations_ += iterations;
  // A solve that took longer than a factorization is worth: refactor next
  // time (n_B^3 / 3 against about 20 n_B^2 per iteration at BLAS-2 speed).
  // (Lateral pile, n_B = 1636, CPU of the whole run: limit n_B/125 5.5 s,
  // n_B/62 5.0 s, n_B/33 5.4 s, n_B/17 7.8 s.)
  if (iterations > std::max(3, nB_ / 60)) refactorNext_ = true;
  if (!(rnorm <= kKrylovAccept * bnorm)) return false;
  std::copy(y.begin(), y.end(), bB);
  applyReference(bB);
  return true;
}

// x <- A_II^-1 x (in place; CHOLMOD's solve2 keeps its work arrays between calls).
void CondensedSolver::solveInterior(double* x) {
  cholmod_dense rhs = denseView(x, nI_, 1);
  if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &solveX_, nullptr, &solveY_, &solveE_, common_))
    throw OpenSeesError("system " + requestedName() + ": solve with the condensed block failed");
  std::memcpy(x, solveX_->x, sizeof(double) * nI_);
}

void CondensedSolver::solve(const double* b, double* x) {
  if (n_ == 0) return;
  work_.resize(static_cast<size_t>(nI_) + nB_);
  double* bI = work_.data();
  double* bB = work_.data() + nI_;
  for (int eq = 0; eq < n_; ++eq) (interior_[eq] ? bI : bB)[local_[eq]] = b[eq];
  if (nB_ > 0) {
    if (nI_ > 0) {
      // interface: S xB = bB - A_BI A_II^-1 bI
      interiorWork_.assign(bI, bI + nI_);
      solveInterior(interiorWork_.data());
      for (std::size_t k = 0; k < biSource_.size(); ++k) bB[biRow_[k]] -= biValues_[k] * interiorWork_[biCol_[k]];
    }
    if (!deltaValue_.empty()) interfaceWork_.assign(bB, bB + nB_);
    if (!solveInterface(bB)) {
      // GMRES did not reach the tolerance: factor S_k and solve directly.
      std::copy(interfaceWork_.begin(), interfaceWork_.end(), bB);
      if (!factorInterface()) {
        // S_k is singular: no solution, as the plain solver would have said.
        std::fill(x, x + n_, std::numeric_limits<double>::quiet_NaN());
        return;
      }
      applyReference(bB);
    }
  }
  // interior: A_II xI = bI - A_IB xB
  for (int c = 0; c < nB_; ++c)
    for (int p = ibStart_[c]; p < ibStart_[c + 1]; ++p) bI[ibRow_[p]] -= ibValues_[p] * bB[c];
  if (nI_ > 0) solveInterior(bI);
  for (int eq = 0; eq < n_; ++eq) x[eq] = interior_[eq] ? bI[local_[eq]] : bB[local_[eq]];
}

}  // namespace beamsolid
