#pragma once
#include <memory>
#include <string>
#include <vector>

#include "analysis/LinearSolver.h"

struct cholmod_common_struct;
struct cholmod_factor_struct;
struct cholmod_dense_struct;

namespace beamsolid {

// Static condensation of the equations only constant-tangent elements touch
// (linear soil): with the equations split into interior I and interface B,
//   S = A_BB - A_BI A_II^-1 A_IB,
// A_II is factored by CHOLMOD and A_BI A_II^-1 A_IB formed once; each
// factorization then only forms and factors the dense S (LAPACK), and a solve
// is two sparse solves with A_II and one dense solve with S. The interior
// blocks are compared with those condensed on every factorization and the
// condensation is redone whenever they differ, so a wrong "constant" claim
// costs time, never accuracy.
//
// Reuse of the interface factorization: from one Newton iteration to the next
// only the contact and nonlinear elements' entries of A_BB change (a sparse
// Delta), so S_k = S_ref + Delta. Instead of refactoring the dense S_k (n_B^3)
// the interface is solved by GMRES on S_k S_ref^-1 y = b, x = S_ref^-1 y, each
// iteration one triangular solve pair (n_B^2) and a sparse product with Delta,
// to a relative residual of 1e-13 (as exact as the direct solve). S_k is
// factored afresh when the last solve needed more Krylov iterations than a
// factorization is worth (about n_B / 60), when GMRES does not converge, and
// for small interfaces (n_B < kMinReuse) where factoring is cheap.
class CondensedSolver : public LinearSolver {
 public:
  // interior[eq] != 0 for equations to condense; spd: S must be SPD (dpotrf)
  // as the system the user asked for (CHOLMOD) requires, else LU (dgetrf).
  // Reuse: solve the interface by GMRES preconditioned with an earlier
  // factorization of S (see above) instead of refactoring every time; Auto
  // from kMinReuse interface equations on, Always at any size.
  enum class Reuse { Off, Auto, Always };
  CondensedSolver(std::string requestedName, std::string outerBackend, bool spd, std::vector<char> interior,
                  Reuse reuse = Reuse::Auto);
  ~CondensedSolver() override;

  std::string backend() const override { return outerBackend_ + " with condensation"; }
  bool requiresSPD() const override { return spd_; }
  void analyze(const SparseView& A) override;
  bool factorize(const SparseView& A) override;
  void solve(const double* b, double* x) override;

  const std::vector<char>& interior() const { return interior_; }
  int numInterior() const { return nI_; }
  // Interior equations of the partition (known before analyze()).
  int numInteriorEquations() const {
    int k = 0;
    for (char c : interior_) k += c;
    return k;
  }
  int numInterface() const { return nB_; }
  // How often A_II was factored and the Schur complement formed.
  int numCondensations() const { return numCondensations_; }
  // Condensations taken from the process's CondensationCache instead (a model
  // rebuilt with the same constant part).
  int numCondensationsReused() const { return numCondensationsReused_; }
  // Dense factorizations of S, and GMRES iterations over all interface solves.
  int numInterfaceFactorizations() const { return numInterfaceFactorizations_; }
  long numKrylovIterations() const { return numKrylovIterations_; }
  // CPU seconds (process, all threads) in the condensations, the dense
  // factorizations of S and the interface solves (GMRES or direct), for benchmarks.
  double condenseSeconds() const { return condenseSeconds_; }
  double interfaceFactorSeconds() const { return factorSeconds_; }
  double interfaceSolveSeconds() const { return interfaceSolveSeconds_; }
  Reuse reuses() const { return reuse_; }

 private:
  bool condense();
  void freeFactor();
  bool factorInterface();           // dense S from coupling_ and bbCurrent_
  void applyReference(double* v);   // v <- S_ref^-1 v
  bool solveInterface(double* bB);  // S_k x = bB in place
  void solveInterior(double* x);    // A_II x = x in place

  std::string outerBackend_;
  bool spd_;
  std::vector<char> interior_;
  int n_ = 0, nI_ = 0, nB_ = 0;
  std::vector<int> local_;  // equation -> index in I or in B

  // A_II (CSC, full storage), A_IB (CSC, n_I x n_B), A_BI (triplets by
  // position in A); each entry remembers its position in A's values.
  std::vector<int> iiStart_, iiRow_, iiSource_;
  std::vector<int> ibStart_, ibRow_, ibSource_;
  std::vector<int> biRow_, biCol_, biSource_;
  std::vector<int> bbDense_, bbSource_;  // A_BB entries: column-major index in S
  std::vector<double> iiValues_, ibValues_, biValues_;
  bool condensed_ = false;
  int numCondensations_ = 0, numCondensationsReused_ = 0;

  std::vector<double> coupling_;  // A_BI A_II^-1 A_IB, dense n_B x n_B
  std::vector<double> schur_;     // factored S_ref
  std::vector<int> pivots_;

  Reuse reuse_ = Reuse::Auto;
  bool factored_ = false;        // schur_ holds a valid factorization
  bool refactorNext_ = false;    // the last solve asked for a fresh factorization
  std::vector<double> bbCurrent_, bbReference_;  // A_BB values now and in S_ref (by bbSource_)
  std::vector<int> deltaRow_, deltaCol_;         // Delta = A_BB - A_BB,ref (interface indices)
  std::vector<double> deltaValue_;
  int numInterfaceFactorizations_ = 0;
  long numKrylovIterations_ = 0;
  double condenseSeconds_ = 0.0, factorSeconds_ = 0.0, interfaceSolveSeconds_ = 0.0;
  std::vector<double> krylov_, hessenberg_;  // GMRES basis and work

  cholmod_common_struct* common_ = nullptr;
  cholmod_factor_struct* factor_ = nullptr;
  std::vector<double> work_, interiorWork_, interfaceWork_;
  cholmod_dense_struct *solveX_ = nullptr, *solveY_ = nullptr, *solveE_ = nullptr;
};

}  // namespace beamsolid
