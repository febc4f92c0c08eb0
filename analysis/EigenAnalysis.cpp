#include "analysis/EigenAnalysis.h"

#include "core/OpenSeesError.h"

namespace beamsolid {

// Placeholder until the sparse (Spectra) and dense solvers land.
std::vector<double> EigenAnalysis::solve(AnalysisModel&, int, bool) {
  throw OpenSeesError("eigen: not available yet");
}

}  // namespace beamsolid
