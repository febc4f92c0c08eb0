#include "analysis/RaphsonNewton.h"

#include <memory>

#include "core/Registry.h"

namespace beamsolid {

bool RaphsonNewton::prepareTangent(AnalysisModel& model, Integrator& integrator, int iteration) {
  const Choice choice = iteration == 0 ? increment_ : iterate_;
  // noTangent keeps the factorization there is; with none yet, form the current one.
  if (choice == Choice::NoTangent && model.system().isFactored()) return true;
  return formAndFactor(model, integrator, choice == Choice::Initial);
}

namespace {

RaphsonNewton::Choice readChoice(CommandArgs& args, const char* option) {
  const std::string t = args.nextString(option);
  if (t == "current" || t == "Current") return RaphsonNewton::Choice::Current;
  if (t == "initial" || t == "Initial") return RaphsonNewton::Choice::Initial;
  if (t == "noTangent" || t == "NoTangent") return RaphsonNewton::Choice::NoTangent;
  args.fail(std::string(option) + " '" + t + "' is unknown (expected current, initial or noTangent)");
}

std::unique_ptr<Algorithm> buildRaphsonNewton(CommandArgs& args, Domain&) {
  auto iterate = RaphsonNewton::Choice::Current, increment = RaphsonNewton::Choice::Current;
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-iterate") iterate = readChoice(args, "-iterate");
    else if (opt == "-increment") increment = readChoice(args, "-increment");
    else if (opt == "-initial") continue;  // accepted and ignored, as OpenSees does
    else args.fail("unknown option '" + opt + "' (expected -iterate or -increment)");
  }
  return std::make_unique<RaphsonNewton>(iterate, increment);
}

void registerRaphsonNewton(Registry& r) { r.algorithms.add("RaphsonNewton", &buildRaphsonNewton); }

}  // namespace
BEAMSOLID_REGISTER(registerRaphsonNewton);
}  // namespace beamsolid
