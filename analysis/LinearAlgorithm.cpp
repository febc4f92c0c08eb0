#include <memory>

#include "analysis/Algorithm.h"
#include "analysis/AnalysisModel.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "core/Registry.h"

namespace beamsolid {
namespace {

// One solve per step, no convergence test ('Linear'); with '-initial' the
// initial stiffness is factored once, '-factorOnce' keeps any first factor.
class LinearAlgorithm : public Algorithm {
 public:
  LinearAlgorithm(bool initial, bool factorOnce) : initial_(initial), factorOnce_(factorOnce) {}
  std::string name() const override { return "Linear"; }
  int solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest&) override {
    using S = AnalysisModel::Stiffness;
    singular_ = false;
    const S which = initial_ ? S::Initial : S::Current;
    const bool reuse = (initial_ || factorOnce_) && model.factoredIs(which);
    if (!reuse && !formAndFactor(model, integrator, initial_)) return -3;
    integrator.formUnbalance(model);
    model.system().solve();
    return integrator.update(model, model.system().x()) < 0 ? -3 : 0;
  }

 private:
  bool initial_, factorOnce_;
};

void registerLinear(Registry& r) {
  r.algorithms.add("Linear", [](CommandArgs& args, Domain&) -> std::unique_ptr<Algorithm> {
    bool initial = false, factorOnce = false;
    while (!args.done()) {
      const std::string opt = args.nextString("option");
      if (opt == "-initial") initial = true;
      else if (opt == "-factorOnce") factorOnce = true;
      else if (opt == "-secant") {}
      else args.fail("unknown option '" + opt + "' (expected -initial or -factorOnce)");
    }
    return std::make_unique<LinearAlgorithm>(initial, factorOnce);
  });
}

}  // namespace
BEAMSOLID_REGISTER(registerLinear);
}  // namespace beamsolid
