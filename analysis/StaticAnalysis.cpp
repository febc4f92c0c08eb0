#include "analysis/StaticAnalysis.h"

namespace beamsolid {

int StaticAnalysis::analyze(int numSteps) {
  return guarded([&] {
    for (int step = 0; step < numSteps; ++step) {
      if (const int code = setupStep()) return code;
      if (const int code = oneStep()) return code;
    }
    return 0;
  });
}

}  // namespace beamsolid
