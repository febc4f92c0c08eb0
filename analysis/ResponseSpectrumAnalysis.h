#pragma once
#include <functional>

namespace beamsolid {

class Domain;
class ModalProperties;

// responseSpectrumAnalysis: the peak displacements of each mode of the last
// eigen analysis under a design spectrum, one mode at a time, as OpenSees'
// ResponseSpectrumAnalysis does (found by running it):
//   u_i = phi_i Gamma_i,d Sa(T_i) / omega_i^2,   T_i = 2 pi / omega_i,
// with phi_i the mode shape on the nodes and Gamma_i,d its participation
// factor in direction d (modalProperties). Each mode's displacements replace
// the nodes' displacements (whatever an analysis left there); the elements
// are updated and committed and the recorders record, so that element forces
// and recorders give that mode's response. The pseudo-time does not change.
// Combining the modes (SRSS, CQC) is left to the script.
class ResponseSpectrumAnalysis {
 public:
  // spectrum(T) -> Sa. mode is 1-based; 0 runs every mode in turn.
  static void run(Domain& domain, const ModalProperties& properties, int direction,
                  const std::function<double(double)>& spectrum, int mode);
};

}  // namespace beamsolid
