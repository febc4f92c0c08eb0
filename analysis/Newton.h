#pragma once
#include "analysis/Algorithm.h"
#include "analysis/AnalysisModel.h"

namespace beamsolid {

// Newton-Raphson with the current tangent ('Newton'), the initial tangent
// ('-initial'), or the initial tangent on the first iteration of each step
// ('-initialThenCurrent'). ModifiedNewton forms the tangent once per step.
class Newton : public Algorithm {
 public:
  enum class Tangent { Current, Initial, InitialThenCurrent };
  Newton(Tangent tangent, bool modified) : tangent_(tangent), modified_(modified) {}
  virtual ~Newton() = default;
  std::string name() const override { return modified_ ? "ModifiedNewton" : "Newton"; }
  int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) override;

 protected:
  // Forms and factors the tangent this iteration needs; false if singular.
  virtual bool prepareTangent(AnalysisModel& model, Integrator& integrator, int iteration);

  Tangent tangent_;
  bool modified_;
};

}  // namespace beamsolid
