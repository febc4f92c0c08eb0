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

// The eigenproblem lives on the directions that carry mass ("massed"); the
// massless ones are condensed out. With an orthogonal change of basis
// Q = [Q_m Q_s] that splits M into M' = diag(M_mm, 0), K phi = lambda M phi is
// exactly (K'_mm - K'_ms K'_ss^-1 K'_sm) phi_m = lambda M_mm phi_m, a problem
// with a positive definite mass. Mostly a direction is one equation (a dof
// with mass or without); where masses couple equations (a mass carried
// through a rigidLink onto the rotations of its retained node, consistent
// element masses) each coupled block is split by its own eigenvectors, since
// such a block can be singular although every diagonal entry is positive
// (translational mass on a rigidLink: 6 coupled dofs, rank 3).
struct Direction {
  std::vector<std::pair<int, double>> terms;  // (equation, coefficient), unit length
};

struct Partition {
  std::vector<Direction> massed;
  std::vector<Direction> massless;
};

Partition partition(const DofMap& map, const std::vector<double>& mass) {
  const int n = map.numEquations();
  const auto& diag = map.diagonalPosition();
  const auto& colStart = map.columnStart();
  const auto& rowIndex = map.rowIndex();
  double largest = 0.0;
  for (int eq = 0; eq < n; ++eq) largest = std::max(largest, std::fabs(mass[diag[eq]]));
  // A relative cut-off so that round-off of transformed zero masses counts as none.
  const double tiny = 1e-14 * largest;
  for (int eq = 0; eq < n; ++eq) {
    const double m = mass[diag[eq]];
    if (m < -1e-12 * largest) {
      auto [node, dof] = map.nodeDofOfEquation(eq);
      throw OpenSeesError("eigen: node " + std::to_string(node) + " dof " + std::to_string(dof + 1) +
                          " has a negative mass (" + std::to_string(m) + ")");
    }
  }
  // Blocks of equations coupled by off-diagonal masses (union-find).
  std::vector<int> parent(n);
  for (int i = 0; i < n; ++i) parent[i] = i;
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int c = 0; c < n; ++c)
    for (int k = colStart[c]; k < colStart[c + 1]; ++k)
      if (rowIndex[k] != c && std::fabs(mass[k]) > tiny) parent[root(rowIndex[k])] = root(c);
  std::vector<std::vector<int>> blocks(n);
  for (int eq = 0; eq < n; ++eq) blocks[root(eq)].push_back(eq);

  Partition p;
  auto unit = [](int eq) { return Direction{{{eq, 1.0}}}; };
  for (const std::vector<int>& block : blocks) {
    if (block.empty()) continue;
    if (block.size() == 1) {
      (mass[diag[block[0]]] > tiny ? p.massed : p.massless).push_back(unit(block[0]));
      continue;
    }
    const int size = static_cast<int>(block.size());
    Matrix B = Matrix::Zero(size, size);
    for (int j = 0; j < size; ++j)
      for (int k = colStart[block[j]]; k < colStart[block[j] + 1]; ++k) {
        const auto at = std::lower_bound(block.begin(), block.end(), rowIndex[k]);
        if (at != block.end() && *at == rowIndex[k]) B(at - block.begin(), j) = mass[k];
      }
    // Small blocks (nodal masses through constraints) are split exactly; a
    // large one (consistent mass of a whole mesh) is positive definite in
    // practice, which a Cholesky factorization confirms.
    constexpr int kLargestDenseBlock = 240;
    if (size > kLargestDenseBlock) {
      Eigen::LLT<Matrix> llt(0.5 * (B + B.transpose()));
      if (llt.info() != Eigen::Success) {
        auto [node, dof] = map.nodeDofOfEquation(block.front());
        throw OpenSeesError("eigen: the mass matrix is singular within a block of " + std::to_string(size) +
                            " coupled dofs (from node " + std::to_string(node) + " dof " + std::to_string(dof + 1) +
                            "); give those dofs mass or use lumped masses");
      }
      for (int eq : block) p.massed.push_back(unit(eq));
      continue;
    }
    Eigen::SelfAdjointEigenSolver<Matrix> split(0.5 * (B + B.transpose()));
    for (int j = 0; j < size; ++j) {
      Direction d;
      for (int i = 0; i < size; ++i)
        if (split.eigenvectors()(i, j) != 0.0) d.terms.emplace_back(block[i], split.eigenvectors()(i, j));
      (split.eigenvalues()[j] > tiny ? p.massed : p.massless).push_back(std::move(d));
    }
  }
  return p;
}

// x = sum_i c_i d_i over directions d_i (full equation space).
void expand(const std::vector<Direction>& dirs, const double* c, Vector& x) {
  for (std::size_t i = 0; i < dirs.size(); ++i)
    for (const auto& [eq, coef] : dirs[i].terms) x[eq] += coef * c[i];
}

// c_i = d_i . x.
void project(const std::vector<Direction>& dirs, const Vector& x, double* c) {
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    double sum = 0.0;
    for (const auto& [eq, coef] : dirs[i].terms) sum += coef * x[eq];
    c[i] = sum;
  }
}

// Q_m^T (K - sigma M)^-1 Q_m on the model's factorization: the right-hand
// side has no massless component, so this is exactly the inverse of the
// condensed K_hat - sigma M_mm.
class CondensedShiftInvert {
 public:
  using Scalar = double;
  CondensedShiftInvert(LinearSystem& system, const std::vector<Direction>& massed)
      : system_(system), massed_(massed), rhs_(Vector::Zero(system.size())), solution_(system.size()) {}
  Eigen::Index rows() const { return static_cast<Eigen::Index>(massed_.size()); }
  Eigen::Index cols() const { return rows(); }
  // The factorization of K - sigma M is made before the solver is built.
  void set_shift(double) {}
  void perform_op(const double* x, double* y) const {
    rhs_.setZero();
    expand(massed_, x, rhs_);
    system_.solve(rhs_, solution_);
    project(massed_, solution_, y);
  }

 private:
  LinearSystem& system_;
  const std::vector<Direction>& massed_;
  mutable Vector rhs_, solution_;
};

// y = M_mm x = Q_m^T M Q_m x.
class CondensedMass {
 public:
  using Scalar = double;
  CondensedMass(const DofMap& map, const std::vector<double>& mass, const std::vector<Direction>& massed)
      : map_(map), mass_(mass), massed_(massed), full_(Vector::Zero(map.numEquations())) {}
  Eigen::Index rows() const { return static_cast<Eigen::Index>(massed_.size()); }
  Eigen::Index cols() const { return rows(); }
  void perform_op(const double* x, double* y) const {
    full_.setZero();
    expand(massed_, x, full_);
    multiply(map_, mass_, full_, product_);
    project(massed_, product_, y);
  }

 private:
  const DofMap& map_;
  const std::vector<double>& mass_;
  const std::vector<Direction>& massed_;
  mutable Vector full_, product_;
};

struct Modes {
  std::vector<double> values;
  Matrix vectors;  // numEquations x numModes
};

Modes solveDense(const DofMap& map, const std::vector<double>& stiffness, const std::vector<double>& mass,
                 const Partition& p, int numModes) {
  const int n = map.numEquations();
  const int nm = static_cast<int>(p.massed.size()), ns = static_cast<int>(p.massless.size());
  // Q = [Q_m Q_s], orthogonal; K' = Q^T K Q and M' = Q^T M Q = diag(M_mm, 0).
  Matrix Q = Matrix::Zero(n, nm + ns);
  auto fill = [&Q](const std::vector<Direction>& dirs, int first) {
    for (std::size_t i = 0; i < dirs.size(); ++i)
      for (const auto& [eq, coef] : dirs[i].terms) Q(eq, first + static_cast<int>(i)) = coef;
  };
  fill(p.massed, 0);
  fill(p.massless, nm);
  const Matrix K = Q.transpose() * toDense(map, stiffness) * Q;
  const Matrix M = Q.transpose() * toDense(map, mass) * Q;
  Matrix Kc = K.topLeftCorner(nm, nm);
  Matrix toMassless(ns, nm);  // phi_s = toMassless * phi_m
  if (ns > 0) {
    const Eigen::FullPivLU<Matrix> Kss(K.bottomRightCorner(ns, ns));
    if (!Kss.isInvertible()) {
      Eigen::Index worst = 0;
      // Name an equation of a massless direction the stiffness cannot hold.
      const Vector kernel = Kss.kernel().col(0);
      kernel.cwiseAbs().maxCoeff(&worst);
      const Direction& d = p.massless[worst];
      int eq = d.terms.front().first;
      double biggest = 0.0;
      for (const auto& [e, c] : d.terms)
        if (std::fabs(c) > biggest) biggest = std::fabs(c), eq = e;
      auto [node, dof] = map.nodeDofOfEquation(eq);
      throw OpenSeesError("eigen: the dofs without mass (e.g. node " + std::to_string(node) + " dof " +
                          std::to_string(dof + 1) +
                          ") form a mechanism: their stiffness is singular, so they cannot be condensed out");
    }
    toMassless = -Kss.solve(K.bottomLeftCorner(ns, nm));
    Kc += K.topRightCorner(nm, ns) * toMassless;
  }
  const Matrix Kh = 0.5 * (Kc + Kc.transpose());
  const Matrix Mmm = M.topLeftCorner(nm, nm);
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(Kh, 0.5 * (Mmm + Mmm.transpose()));
  if (solver.info() != Eigen::Success)
    throw OpenSeesError("eigen -fullGenLapack: the mass matrix of the dofs with mass is not positive definite");
  Modes modes;
  modes.vectors = Matrix::Zero(n, numModes);
  Vector phi(nm + ns);
  for (int k = 0; k < numModes; ++k) {  // eigenvalues come in ascending order
    modes.values.push_back(solver.eigenvalues()[k]);
    phi.head(nm) = solver.eigenvectors().col(k);
    if (ns > 0) phi.tail(ns) = toMassless * phi.head(nm);
    modes.vectors.col(k) = Q * phi;
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
    for (const Direction& d : p.massed)
      for (const auto& [eq, coef] : d.terms) {
        traceK += coef * coef * std::fabs(stiffness[map.diagonalPosition()[eq]]);
        traceM += coef * coef * mass[map.diagonalPosition()[eq]];
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
    expand(p.massed, x.col(k).data(), full);
    multiply(map, mass, full, Mx);
    system.solve(Mx, phi);
    modes.vectors.col(k) = (lambda[k] - sigma) * phi;
    modes.values.push_back(lambda[k]);
  }
  system.invalidateFactor();  // the factorization holds K - sigma M, not a tangent
  return modes;
}

}  // namespace

std::vector<double> EigenAnalysis::solve(AnalysisModel& model, int numModes, bool dense, bool standard) {
  const DofMap& map = model.dofMap();
  const int n = model.numEquations();
  if (numModes < 1) throw OpenSeesError("eigen: the number of eigenvalues must be at least 1");
  if (n == 0) throw OpenSeesError("eigen: the model has no free dofs");

  model.formTangent(AnalysisModel::Stiffness::Current);
  const std::vector<double> stiffness = model.system().values();
  std::vector<double> mass;
  if (standard) {
    mass.assign(stiffness.size(), 0.0);
    for (int eq = 0; eq < n; ++eq) mass[map.diagonalPosition()[eq]] = 1.0;
  } else {
    model.assembleMass(mass);
  }

  const Partition p = partition(map, mass);
  const int nm = static_cast<int>(p.massed.size());
  if (nm < numModes)
    throw OpenSeesError("eigen: asked for " + std::to_string(numModes) + " eigenvalues but only " +
                        std::to_string(nm) + " of the " + std::to_string(n) +
                        " free dofs have mass (assign mass with mass() or the element density)");

  // Spectra needs numModes < size. A Lanczos run that fails (a Krylov space of
  // a few dofs whose masses differ by 1e9 may not converge) falls back to the
  // dense solver on models of moderate size. Dense is not the default for
  // small models: with masses that span many orders of magnitude its lowest
  // eigenvalues lose accuracy (8e-5 on a frame with 1e-10 rotational masses),
  // where shift-invert keeps them to round-off.
  constexpr int kDenseFallbackSize = 1000;
  Modes modes;
  if (dense || numModes >= nm) {
    modes = solveDense(map, stiffness, mass, p, numModes);
  } else {
    try {
      modes = solveSparse(model, stiffness, mass, p, numModes);
    } catch (const OpenSeesError&) {
      if (n > kDenseFallbackSize) throw;
      modes = solveDense(map, stiffness, mass, p, numModes);
    }
  }

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
    const double biggest = phi.cwiseAbs().maxCoeff(&largest);
    phi *= (phi[largest] < 0.0 ? -1.0 : 1.0) / std::sqrt(m);
    // Round-off where a mode has no motion (the other direction of a
    // symmetric frame: 1e-16 of the largest component) is zero, as in
    // OpenSees' modes, so modal participations print as 0, not 1e-28.
    const double cut = 1e-12 * biggest / std::sqrt(m);
    for (Eigen::Index i = 0; i < phi.size(); ++i)
      if (std::fabs(phi[i]) < cut) phi[i] = 0.0;
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
