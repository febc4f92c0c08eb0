#include "analysis/Newton.h"

#include <memory>

#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "core/Registry.h"

namespace beamsolid {

bool Newton::prepareTangent(AnalysisModel& model, Integrator& integrator, int iteration) {
  using S = AnalysisModel::Stiffness;
  S which = S::Current;
  if (tangent_ == Tangent::Initial || (tangent_ == Tangent::InitialThenCurrent && iteration == 0)) which = S::Initial;
  if (modified_ && iteration > 0 && model.system().isFactored()) return true;
  return formAndFactor(model, integrator, which == S::Initial);
}

int Newton::solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) {
  singular_ = false;
  lastError_.clear();
  LinearSystem& system = model.system();
  integrator.formUnbalance(model);
  test.start(system);
  for (int iteration = 0;; ++iteration) {
    if (!prepareTangent(model, integrator, iteration)) return -3;
    system.solve();
    if (integrator.update(model, system.x()) < 0) {
      lastError_ = "the integrator could not update the step";
      return -3;
    }
    integrator.formUnbalance(model);
    switch (test.test(system)) {
      case ConvergenceTest::Result::Converged: return 0;
      case ConvergenceTest::Result::Failed: return notConverged(test);
      case ConvergenceTest::Result::Continue: break;
    }
  }
}

namespace {

Newton::Tangent readTangentOption(CommandArgs& args) {
  Newton::Tangent t = Newton::Tangent::Current;
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-initial") t = Newton::Tangent::Initial;
    else if (opt == "-initialThenCurrent") t = Newton::Tangent::InitialThenCurrent;
    else if (opt == "-secant" || opt == "-factorOnce")
      args.fail("option " + opt + " is not supported; use -initial or -initialThenCurrent");
    else args.fail("unknown option '" + opt + "' (expected -initial or -initialThenCurrent)");
  }
  return t;
}

void registerNewton(Registry& r) {
  r.algorithms.add("Newton", [](CommandArgs& args, Domain&) -> std::unique_ptr<Algorithm> {
    return std::make_unique<Newton>(readTangentOption(args), false);
  });
  r.algorithms.add("ModifiedNewton", [](CommandArgs& args, Domain&) -> std::unique_ptr<Algorithm> {
    return std::make_unique<Newton>(readTangentOption(args), true);
  });
}

}  // namespace
BEAMSOLID_REGISTER(registerNewton);
}  // namespace beamsolid
