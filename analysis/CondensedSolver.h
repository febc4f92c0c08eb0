#pragma once
#include <memory>
#include <string>
#include <vector>

#include "analysis/LinearSolver.h"

struct cholmod_common_struct;
struct cholmod_factor_struct;

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
class CondensedSolver : public LinearSolver {
 public:
  // interior[eq] != 0 for equations to condense; spd: S must be SPD (dpotrf)
  // as the system the user asked for (CHOLMOD) requires, else LU (dgetrf).
  CondensedSolver(std::string requestedName, std::string outerBackend, bool spd, std::vector<char> interior);
  ~CondensedSolver() override;

  std::string backend() const override { return outerBackend_ + " with condensation"; }
  bool requiresSPD() const override { return spd_; }
  void analyze(const SparseView& A) override;
  bool factorize(const SparseView& A) override;
  void solve(const double* b, double* x) override;

  const std::vector<char>& interior() const { return interior_; }
  int numInterior() const { return nI_; }
  int numInterface() const { return nB_; }
  // How often A_II was factored and the Schur complement formed.
  int numCondensations() const { return numCondensations_; }

 private:
  bool condense();
  void freeFactor();

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
  int numCondensations_ = 0;

  std::vector<double> coupling_;  // A_BI A_II^-1 A_IB, dense n_B x n_B
  std::vector<double> schur_;     // factored S
  std::vector<int> pivots_;

  cholmod_common_struct* common_ = nullptr;
  cholmod_factor_struct* factor_ = nullptr;
  std::vector<double> work_;
};

}  // namespace beamsolid
