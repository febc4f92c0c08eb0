#pragma once
#include <string>
#include <vector>

#include "analysis/AnalysisModel.h"
#include "core/Types.h"

namespace beamsolid {

// Sets up each step, forms tangent and residual with its own factors, and
// maps a solution back to node increments (OpenSees' Integrator).
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  virtual bool isStatic() const { return true; }

  // Called when the model was renumbered.
  virtual void domainChanged(AnalysisModel&) {}
  // Applies the next load increment; negative on failure.
  virtual int newStep(AnalysisModel& model) = 0;
  virtual void formTangent(AnalysisModel& model, AnalysisModel::Stiffness which) { model.formTangent(which); }
  virtual void formUnbalance(AnalysisModel& model) { model.formUnbalance(); }
  // Applies the solution dU of the last solve; negative on failure.
  virtual int update(AnalysisModel& model, const Vector& dU) = 0;
  // Sensitivities: an integrator that holds a dof at a given value (displacement
  // control) gives it as a combination of equations, so that d lambda / d theta
  // keeps it there; false for those that prescribe lambda (load control).
  virtual bool controlledDof(std::vector<DofMap::Term>&) const { return false; }
  // After a converged step (iterations it took) and after a failed one.
  virtual void commit(AnalysisModel&, int /*iterations*/) {}
  virtual void revert(AnalysisModel&) {}
};

}  // namespace beamsolid
