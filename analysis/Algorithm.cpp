#include "analysis/Algorithm.h"

#include "analysis/AnalysisModel.h"
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

}  // namespace beamsolid
