#include "analysis/ConstraintHandler.h"

#include <memory>

#include "core/Registry.h"

namespace beamsolid {

std::string ConstraintHandler::name() const {
  switch (method_) {
    case Method::Plain: return "Plain";
    case Method::Transformation: return "Transformation";
    case Method::Penalty: return "Penalty";
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
}

}  // namespace

BEAMSOLID_REGISTER(registerConstraintHandlers);

}  // namespace beamsolid
