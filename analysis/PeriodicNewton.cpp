#include "analysis/PeriodicNewton.h"

#include <memory>

#include "core/Registry.h"

namespace beamsolid {

bool PeriodicNewton::prepareTangent(AnalysisModel& model, Integrator& integrator, int iteration) {
  // iteration counts from 0: forms at 0, 1, 1 + maxDim, 1 + 2 maxDim, ...
  const bool reform = iteration == 0 || (iteration - 1) % maxDim_ == 0;
  if (!reform && model.system().isFactored()) return true;
  return Newton::prepareTangent(model, integrator, iteration);
}

namespace {

std::unique_ptr<Algorithm> buildPeriodicNewton(CommandArgs& args, Domain&) {
  int maxDim = 3;
  auto tangent = Newton::Tangent::Current;
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-maxDim") maxDim = args.nextInt("maxDim");
    else if (opt == "-initial") continue;  // accepted and ignored, as OpenSees does
    else args.fail("unknown option '" + opt + "' (expected -maxDim)");
  }
  if (maxDim < 1) args.fail("-maxDim must be at least 1, got " + std::to_string(maxDim));
  return std::make_unique<PeriodicNewton>(tangent, maxDim);
}

void registerPeriodicNewton(Registry& r) { r.algorithms.add("PeriodicNewton", &buildPeriodicNewton); }

}  // namespace
BEAMSOLID_REGISTER(registerPeriodicNewton);
}  // namespace beamsolid
