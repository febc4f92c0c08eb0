#pragma once
#include "analysis/LinearSolver.h"
#include "core/CommandArgs.h"

namespace beamsolid {

// The options of every system command: '-condense' auto|on|off (ours); other
// solvers' options ('-piv', '-ICNTL14', 20, ...) do not apply and are read
// and ignored, as scripts pass them.
void readSystemOptions(CommandArgs& args, LinearSolver& solver);

}  // namespace beamsolid
