#include "analysis/EigenAnalysis.h"

#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/AnalysisModel.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {

// y = A x for a matrix on the DofMap pattern (full storage, both triangles).
void multiply(const DofMap& map, const std::vector<double>& values, const Vector& x, Vector& y) {
  const auto& colStart = map.columnStart();
  const auto& rowIndex = map.rowIndex();
  const int n = map.numEquations();
  y = Vector::Zero(n);
  for (int c = 0; c < n; ++c) {
    const double xc = x[c];
    if (xc == 0.0) continue;
    for (int k = colStart[c]; k < colStart[c + 1]; ++k) y[rowIndex[k]] += values[k] * xc;
  }
}

Matrix toDense(const DofMap& map, const std::vector<double>& values) {
  const int n = map.numEquations();
  Matrix A = Matrix::Zero(n, n);
  for (int c = 0; c < n; ++c)
    for (int k = map.columnStart()[c]; k < map.columnStart()[c + 1]; ++k) A(map.rowIndex()[k], c) = values[k];
  return A;
}

// The eigenproblem lives on the equations that carry mass ("massed"); the
// massless ones are condensed out: for a semi-definite M whose zero rows are
// those of zero diagonal, K phi = lambda M phi is exactly
// (K_mm - K_ms K_ss^-1 K_sm) phi_m = lambda M_mm phi_m with phi_s = -K_ss^-1 K_sm phi_m,
// a problem with a positive definite mass.
struct Partition {
  std::vector<int> massed;    // equation of each massed index
  std::vector<int> massless;  // equations without mass
};

Partition partition(const DofMap& map, const std::vector<double>& mass) {
  const int n = map.numEquations();
  const auto& diag = map.diagonalPosition();
  double largest = 0.0;
  for (int eq = 0; eq < n; ++eq) largest = std::max(largest, std::fabs(mass[diag[eq]]));
  Partition p;
  for (int eq = 0; eq < n; ++eq) {
    const double m = mass[diag[eq]];
    if (m < -1e-12 * largest) {
      auto [node, dof] = map.nodeDofOfEquation(eq);
      throw OpenSeesError("eigen: node " + std::to_string(node) + " dof " + std::to_string(dof + 1) +
                          " has a negative mass (" + std::to_string(m) + ")");
    }
    // A relative cut-off so that round-off of transformed zero masses counts as none.
    (m > 1e-14 * largest ? p.massed : p.massless).push_back(eq);
  }
  return p;
}

// (K - sigma M)^-1 restricted to the massed equations, on the model's
// factorization: the massless rows of the right-hand side are zero, so this
// is exactly the inverse of the condensed K_hat - sigma M_mm.
class CondensedShiftInvert {
 public:
  using Scalar = double;
  CondensedShiftInvert(LinearSystem& system, const std::vector<int>& massed)
      : system_(system), massed_(massed), rhs_(Vector::Zero(system.size())), solution_(system.size()) {}
  Eigen::Index rows() const { return static_cast<Eigen::Index>(massed_.size()); }
  Eigen::Index cols() const { return rows(); }
  // The factorization of K - sigma M is made before the solver is built.
  void set_shift(double) {}
  void perform_op(const double* x, double* y) const {
    for (std::size_t i = 0; i < massed_.size(); ++i) rhs_[massed_[i]] = x[i];
    system_.solve(rhs_, solution_);
    for (std::size_t i = 0; i < massed_.size(); ++i) y[i] = solution_[massed_[i]];
  }

 private:
  LinearSystem& system_;
  const std::vector<int>& massed_;
  mutable Vector rhs_, solution_;
};

// y = M_mm x.
class CondensedMass {
 public:
  using Scalar = double;
  CondensedMass(const DofMap& map, const std::vector<double>& mass, const std::vector<int>& massed)
      : map_(map), mass_(mass), massed_(massed), full_(Vector::Zero(map.numEquations())) {}
  Eigen::Index rows() const { return static_cast<Eigen::Index>(massed_.size()); }
  Eigen::Index cols() const { return rows(); }
  void perform_op(const double* x, double* y) const {
    for (std::size_t i = 0; i < massed_.size(); ++i) full_[massed_[i]] = x[i];
    multiply(map_, mass_, full_, product_);
    for (std::size_t i = 0; i < massed_.size(); ++i) y[i] = product_[massed_[i]];
  }

 private:
  const DofMap& map_;
  const std::vector<double>& mass_;
  const std::vector<int>& massed_;
  mutable Vector full_, product_;
};

struct Modes {
  std::vector<double> values;
  Matrix vectors;  // numEquations x numModes
};

Modes solveDense(const DofMap& map, const std::vector<double>& stiffness, const std::vector<double>& mass,
                 const Partition& p, int numModes) {
  const Matrix K = toDense(map, stiffness);
  const Matrix M = toDense(map, mass);
  const int nm = static_cast<int>(p.massed.size()), ns = static_cast<int>(p.massless.size());
  auto block = [](const Matrix& A, const std::vector<int>& rows, const std::vector<int>& cols) {
    Matrix B(rows.size(), cols.size());
    for (std::size_t j = 0; j < cols.size(); ++j)
      for (std::size_t i = 0; i < rows.size(); ++i) B(i, j) = A(rows[i], cols[j]);
    return B;
  };
  Matrix Kc = block(K, p.massed, p.massed);
  Matrix toMassless(ns, nm);  // phi_s = toMassless * phi_m
  if (ns > 0) {
    const Eigen::FullPivLU<Matrix> Kss(block(K, p.massless, p.massless));
    if (!Kss.isInvertible()) {
      auto [node, dof] = map.nodeDofOfEquation(p.massless.front());
      throw OpenSeesError("eigen: the dofs without mass (e.g. node " + std::to_string(node) + " dof " +
                          std::to_string(dof + 1) +
                          ") form a mechanism: their stiffness is singular, so they cannot be condensed out");
    }
    toMassless = -Kss.solve(block(K, p.massless, p.massed));
    Kc += block(K, p.massed, p.massless) * toMassless;
  }
  const Matrix Kh = 0.5 * (Kc + Kc.transpose());
  const Matrix Mmm = block(M, p.massed, p.massed);
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(Kh, 0.5 * (Mmm + Mmm.transpose()));
  if (solver.info() != Eigen::Success)
    throw OpenSeesError("eigen -fullGenLapack: the mass matrix of the dofs with mass is not positive definite");
  Modes modes;
  modes.vectors = Matrix::Zero(map.numEquations(), numModes);
  for (int k = 0; k < numModes; ++k) {  // eigenvalues come in ascending order
    modes.values.push_back(solver.eigenvalues()[k]);
    const Vector phiM = solver.eigenvectors().col(k);
    for (int i = 0; i < nm; ++i) modes.vectors(p.massed[i], k) = phiM[i];
    if (ns > 0) {
      const Vector phiS = toMassless * phiM;
      for (int i = 0; i < ns; ++i) modes.vectors(p.massless[i], k) = phiS[i];
    }
  }
  return modes;
}

Modes solveSparse(AnalysisModel& model, const std::vector<double>& stiffness, const std::vector<double>& mass,
                  const Partition& p, int numModes) {
  const DofMap& map = model.dofMap();
  LinearSystem& system = model.system();
  const int nm = static_cast<int>(p.massed.size());
  // Factor K - sigma M: sigma = 0 unless K is singular (rigid-body modes),
  // then a small negative shift relative to the mean K/M ratio.
  auto factorShifted = [&](double sigma) {
    auto& values = system.values();
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = stiffness[k] - sigma * mass[k];
    system.invalidateFactor();
    return system.factor();
  };
  double sigma = 0.0;
  if (!factorShifted(sigma)) {
    double traceK = 0.0, traceM = 0.0;
    for (int eq : p.massed) {
      traceK += std::fabs(stiffness[map.diagonalPosition()[eq]]);
      traceM += mass[map.diagonalPosition()[eq]];
    }
    sigma = -1e-4 * (traceK > 0.0 ? traceK / traceM : 1.0);
    if (!factorShifted(sigma))
      throw OpenSeesError("eigen: K - sigma M cannot be factored (sigma = " + std::to_string(sigma) +
                          "): " + model.describeFactorFailure());
  }

  CondensedShiftInvert op(system, p.massed);
  CondensedMass massOp(map, mass, p.massed);
  const int ncv = std::min(nm, std::max(2 * numModes + 1, 20));
  Vector lambda;
  Matrix x;
  try {
    Spectra::SymGEigsShiftSolver<CondensedShiftInvert, CondensedMass, Spectra::GEigsMode::ShiftInvert> lanczos(
        op, massOp, numModes, ncv, sigma);
    lanczos.init();
    lanczos.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
    if (lanczos.info() != Spectra::CompInfo::Successful)
      throw OpenSeesError("eigen: the shift-invert Lanczos iteration (Spectra) did not converge for " +
                          std::to_string(numModes) + " modes; try '-fullGenLapack'");
    lambda = lanczos.eigenvalues();
    x = lanczos.eigenvectors();
  } catch (const OpenSeesError&) {
    system.invalidateFactor();
    throw;
  } catch (const std::exception& e) {
    system.invalidateFactor();
    throw OpenSeesError(std::string("eigen: the Lanczos solver (Spectra) failed: ") + e.what());
  }

  // The full mode, massless dofs included, and purified of round-off in the
  // massless directions: phi = (lambda - sigma) (K - sigma M)^-1 M phi.
  Modes modes;
  modes.vectors = Matrix::Zero(map.numEquations(), numModes);
  Vector full(map.numEquations()), Mx, phi;
  for (int k = 0; k < numModes; ++k) {
    full.setZero();
    for (int i = 0; i < nm; ++i) full[p.massed[i]] = x(i, k);
    multiply(map, mass, full, Mx);
    system.solve(Mx, phi);
    modes.vectors.col(k) = (lambda[k] - sigma) * phi;
    modes.values.push_back(lambda[k]);
  }
  system.invalidateFactor();  // the factorization holds K - sigma M, not a tangent
  return modes;
}

}  // namespace

std::vector<double> EigenAnalysis::solve(AnalysisModel& model, int numModes, bool dense) {
  const DofMap& map = model.dofMap();
  const int n = model.numEquations();
  if (numModes < 1) throw OpenSeesError("eigen: the number of eigenvalues must be at least 1");
  if (n == 0) throw OpenSeesError("eigen: the model has no free dofs");

  model.formTangent(AnalysisModel::Stiffness::Current);
  const std::vector<double> stiffness = model.system().values();
  std::vector<double> mass;
  model.assembleMass(mass);

  const Partition p = partition(map, mass);
  const int nm = static_cast<int>(p.massed.size());
  if (nm < numModes)
    throw OpenSeesError("eigen: asked for " + std::to_string(numModes) + " eigenvalues but only " +
                        std::to_string(nm) + " of the " + std::to_string(n) +
                        " free dofs have mass (assign mass with mass() or the element density)");

  // Spectra needs numModes < size; the dense solver is exact for any size.
  Modes modes = (dense || numModes >= nm) ? solveDense(map, stiffness, mass, p, numModes)
                                          : solveSparse(model, stiffness, mass, p, numModes);

  // Mass-normalize (phi^T M phi = 1), refine the eigenvalue with the Rayleigh
  // quotient, and fix the sign: the largest component is positive.
  Vector Mphi, Kphi;
  for (int k = 0; k < numModes; ++k) {
    auto phi = modes.vectors.col(k);
    multiply(map, mass, phi, Mphi);
    const double m = phi.dot(Mphi);
    if (!(m > 0.0)) throw OpenSeesError("eigen: mode " + std::to_string(k + 1) + " has no mass");
    multiply(map, stiffness, phi, Kphi);
    modes.values[k] = phi.dot(Kphi) / m;
    Eigen::Index largest = 0;
    phi.cwiseAbs().maxCoeff(&largest);
    phi *= (phi[largest] < 0.0 ? -1.0 : 1.0) / std::sqrt(m);
  }

  // Node mode shapes through the DofMap terms: constrained dofs follow their
  // equations, fixed dofs (no term) stay zero.
  for (Node* node : map.nodes()) {
    const int start = map.fullStartOfNode(node->tag());
    Matrix shape = Matrix::Zero(node->ndf(), numModes);
    for (int d = 0; d < node->ndf(); ++d)
      for (auto* t = map.fullTermsBegin(start + d); t != map.fullTermsEnd(start + d); ++t)
        shape.row(d) += t->coefficient * modes.vectors.row(t->equation);
    node->setEigenvectors(std::move(shape));
  }
  return modes.values;
}

}  // namespace beamsolid
