#pragma once
#include <vector>

namespace beamsolid {

class AnalysisModel;

// The lowest eigenvalues omega^2 of K phi = omega^2 M phi with the current
// tangent K and the lumped/element mass M; mode shapes (mass-normalized)
// are stored in the nodes (Node::setEigenvectors).
class EigenAnalysis {
 public:
  // `dense`: '-fullGenLapack' (dense solve of the whole problem); otherwise a
  // sparse shift-invert Lanczos (Spectra) over a sparse factorization.
  // `standard`: eigen('-standard', ...), K phi = lambda phi (M = I on the
  // equations, the masses ignored, as OpenSees); modes of unit length.
  static std::vector<double> solve(AnalysisModel& model, int numModes, bool dense, bool standard = false);
};

}  // namespace beamsolid
