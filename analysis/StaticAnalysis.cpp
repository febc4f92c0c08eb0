#include "analysis/StaticAnalysis.h"

#include "core/Domain.h"

namespace beamsolid {

int StaticAnalysis::analyze(int numSteps) {
  domain_.setTransient(false);
  return guarded([&] {
    for (int step = 0; step < numSteps; ++step) {
      if (const int code = setupStep()) return code;
      if (const int code = oneStep()) return code;
    }
    return 0;
  });
}

}  // namespace beamsolid
