#include "analysis/SystemOptions.h"

namespace beamsolid {

void readSystemOptions(CommandArgs& args, LinearSolver& solver) {
  while (!args.done()) {
    if (!args.nextFlag("-condense")) {
      args.seek(args.position() + 1);
      continue;
    }
    const std::string mode = args.nextString("-condense");
    if (mode == "auto") solver.setCondensation(LinearSolver::Condensation::Auto);
    else if (mode == "on") solver.setCondensation(LinearSolver::Condensation::On);
    else if (mode == "off") solver.setCondensation(LinearSolver::Condensation::Off);
    else args.fail("-condense '" + mode + "' is unknown (expected auto, on or off)");
  }
}

}  // namespace beamsolid
