#pragma once
#include "analysis/Analysis.h"

namespace beamsolid {

// analysis('Static'): analyze(n) runs n steps of the static integrator.
class StaticAnalysis : public Analysis {
 public:
  using Analysis::Analysis;
  int analyze(int numSteps);
};

}  // namespace beamsolid
