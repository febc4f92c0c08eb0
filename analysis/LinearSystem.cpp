#include "analysis/LinearSystem.h"

#include "core/BlasThreads.h"

#include "analysis/DofMap.h"

#include <chrono>

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

namespace {
double seconds() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

bool LinearSystem::factor() {
  const double start = seconds();
  // One BLAS thread unless a solver asks for more around large dense work
  // (core/BlasThreads.h: idle threads spin between the small calls).
  BlasThreads::Scope threads(1);
  const SparseView A = view();
  if (!analyzed_) {
    solver_->analyze(A);
    analyzed_ = true;
  }
  factored_ = solver_->factorize(A);
  solverSeconds_ += seconds() - start;
  return factored_;
}

void LinearSystem::solve() { solve(b_, x_); }

void LinearSystem::solve(const Vector& rhs, Vector& out) {
  const double start = seconds();
  BlasThreads::Scope threads(1);
  out.resize(n_);
  solver_->solve(rhs.data(), out.data());
  solverSeconds_ += seconds() - start;
}

}  // namespace beamsolid
