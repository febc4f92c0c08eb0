#include "analysis/ConstraintHandler.h"

#include <memory>
#include <string>

#include "core/Registry.h"

namespace beamsolid {

std::string ConstraintHandler::name() const {
  switch (method_) {
    case Method::Plain: return "Plain";
    case Method::Transformation: return "Transformation";
    case Method::Penalty: return "Penalty";
    case Method::Lagrange: return "Lagrange";
  }
  return "?";
}

namespace {

std::unique_ptr<ConstraintHandler> buildPenalty(CommandArgs& args, Domain&) {
  const double alphaS = args.nextDouble("alphaS");
  const double alphaM = args.nextDouble("alphaM");
  if (alphaS <= 0.0 || alphaM <= 0.0) args.fail("penalty factors alphaS and alphaM must be positive");
  args.expectEnd();
  return std::make_unique<ConstraintHandler>(ConstraintHandler::Method::Penalty, alphaS, alphaM);
}

void registerConstraintHandlers(Registry& r) {
  r.constraintHandlers.add("Plain", [](CommandArgs& args, Domain&) {
    args.expectEnd();
    return std::make_unique<ConstraintHandler>(ConstraintHandler::Method::Plain);
  });
  r.constraintHandlers.add("Transformation", [](CommandArgs& args, Domain&) {
    args.expectEnd();
    return std::make_unique<ConstraintHandler>(ConstraintHandler::Method::Transformation);
  });
  r.constraintHandlers.add("Penalty", &buildPenalty);
  r.constraintHandlers.add("Lagrange", [](CommandArgs& args, Domain&) {
    // alphaS, alphaM (default 1) scale the multiplier equations in OpenSees; they do not change the answer
    for (const char* name : {"alphaS", "alphaM"})
      if (!args.done() && args.nextDouble(name) <= 0.0) args.fail(std::string(name) + " must be positive");
    args.expectEnd();
    return std::make_unique<ConstraintHandler>(ConstraintHandler::Method::Lagrange);
  });
}

}  // namespace

BEAMSOLID_REGISTER(registerConstraintHandlers);

}  // namespace beamsolid
