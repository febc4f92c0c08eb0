#pragma once
#include <vector>

#include "analysis/Algorithm.h"
#include "core/Types.h"

namespace beamsolid {

// algorithm('BFGS', <'-initial'>, <'-count', n>) and
// algorithm('Broyden', <'-initial'>, <'-count', n>): quasi-Newton iterations
// on a factored tangent K (current at the start of the step, or the initial
// stiffness with '-initial'). Each iteration's correction is H b with b the
// unbalance and H an approximate inverse built from K^-1 and the pairs
// (s_j, y_j) of earlier corrections and the unbalance changes they caused
// (y_j = b_j - b_{j+1}, so that H y_j = s_j):
//   BFGS (Matthies & Strang 1979): H_{j+1} = (I - rho s y') H_j (I - rho y s') + rho s s',
//        rho = 1/(y's), applied by the two-loop recursion;
//   Broyden ("good" update, inverse by Sherman-Morrison):
//        H_{j+1} = (I + a_j s_j') H_j,  a_j = (s_j - H_j y_j) / (s_j' H_j y_j).
// After `count` iterations without convergence the tangent is reformed and
// the pairs are dropped.
class QuasiNewton : public Algorithm {
 public:
  enum class Update { BFGS, Broyden };
  QuasiNewton(Update update, bool initial, int count) : update_(update), initial_(initial), count_(count) {}
  std::string name() const override { return update_ == Update::BFGS ? "BFGS" : "Broyden"; }
  int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) override;

 private:
  bool prepareTangent(AnalysisModel& model, Integrator& integrator);
  // H b with the pairs stored so far.
  Vector apply(AnalysisModel& model, const Vector& b) const;

  Update update_;
  bool initial_;
  int count_;
  std::vector<Vector> s_, y_, a_;
  std::vector<double> rho_;
};

}  // namespace beamsolid
