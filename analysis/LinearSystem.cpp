#include "analysis/LinearSystem.h"

#include "analysis/DofMap.h"

namespace beamsolid {

void LinearSystem::setPattern(const DofMap& map) {
  map_ = &map;
  n_ = map.numEquations();
  values_.assign(map.rowIndex().size(), 0.0);
  b_ = Vector::Zero(n_);
  x_ = Vector::Zero(n_);
  analyzed_ = factored_ = false;
}

void LinearSystem::setSolver(LinearSolver* solver) {
  if (solver != solver_) analyzed_ = factored_ = false;
  solver_ = solver;
}

SparseView LinearSystem::view() const {
  return SparseView{n_, map_->columnStart().data(), map_->rowIndex().data(), values_.data()};
}

bool LinearSystem::factor() {
  const SparseView A = view();
  if (!analyzed_) {
    solver_->analyze(A);
    analyzed_ = true;
  }
  factored_ = solver_->factorize(A);
  return factored_;
}

void LinearSystem::solve() { solve(b_, x_); }

void LinearSystem::solve(const Vector& rhs, Vector& out) {
  out.resize(n_);
  solver_->solve(rhs.data(), out.data());
}

}  // namespace beamsolid
