#pragma once
#include <map>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

class Domain;

// modalDamping(factor) or modalDamping(f1, f2, ...), after eigen: the
// damping force M Phi diag(2 zeta_i omega_i / m_i) Phi^T M v over the modes
// of the last eigen analysis (m_i = phi_i^T M phi_i, M nodal and element
// mass, v the trial velocities). One factor damps every mode found, several
// damp the first modes in turn (extra factors are ignored). As OpenSees (and
// Perform3D) the force enters the residual only: the tangent would be full,
// so it keeps no modal damping and a step converges by iteration.
class ModalDamping {
 public:
  explicit ModalDamping(std::vector<double> factors) : factors_(std::move(factors)) {}
  const std::vector<double>& factors() const { return factors_; }
  // Damping forces of the nodes, by node tag (nodes without mass left out).
  std::map<int, Vector> forces(const Domain& domain) const;

 private:
  std::vector<double> factors_;
};

}  // namespace beamsolid
