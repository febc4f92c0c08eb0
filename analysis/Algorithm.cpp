#include "analysis/Algorithm.h"

#include <cstdio>

#include "analysis/AnalysisModel.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"

namespace beamsolid {

bool Algorithm::formAndFactor(AnalysisModel& model, Integrator& integrator, bool initial) {
  using S = AnalysisModel::Stiffness;
  const S kind = initial ? S::Initial : S::Current;
  if (kind == S::Initial && model.factoredIs(S::Initial)) return true;
  integrator.formTangent(model, kind);
  if (!model.factor(kind)) {
    singular_ = true;
    lastError_ = model.describeFactorFailure();
    return false;
  }
  return true;
}

int Algorithm::notConverged(const ConvergenceTest& test, const std::string& what) {
  // %g: std::to_string's six fixed decimals print small norms as 0.000000.
  char numbers[64];
  std::snprintf(numbers, sizeof numbers, "last norm %g, tolerance %g", test.norms().back(), test.tolerance());
  lastError_ = test.name() + " failed to converge in " + std::to_string(test.numIterations()) + " " + what + " (" +
               numbers + ")";
  return -3;
}

}  // namespace beamsolid
