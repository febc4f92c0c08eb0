#pragma once
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace beamsolid {

class Domain;

// modalProperties after eigen: total and free mass, centre of mass, modal
// participation factors and effective (participating) masses per global
// direction, as OpenSees' DomainModalProperties reports them.
//
// With the model mass M (nodal masses plus element mass matrices, over every
// node dof), M_f its free rows and columns (no fix/sp) and, for direction d,
// the rigid-body vector r_d (a unit translation, or a unit rotation about the
// centre of mass), mode phi gives
//   Gamma_d = phi' M_f r_d / (phi' M_f phi),   Meff_d = (phi' M_f r_d)^2 / (phi' M_f phi).
// Total and free masses and the centre of mass use M lumped to the dofs (each
// row summed over the same dof of every node), as OpenSees does; both
// choices were found by running OpenSeesPy on a consistent-mass frame.
// The directions are MX (1D); MX, MY, RMZ (2D); MX, MY, MZ, RMX, RMY, RMZ (3D).
// '-unorm' scales each mode so that its largest component (translation or rotation, as OpenSees) is 1 in size
// (Gamma changes, Meff does not).
class ModalProperties {
 public:
  ModalProperties(const Domain& domain, const std::vector<double>& eigenvalues, bool unitNormalized);

  // The dict of '-return', keyed as OpenSeesPy keys it.
  std::map<std::string, std::vector<double>> toDict() const;
  // The report of '-print' and '-file'.
  void report(std::ostream& os) const;
  // Gamma of mode (0-based) in direction (0-based, in the order above).
  double participationFactor(int mode, int direction) const { return factor_.at(mode).at(direction); }
  int numDirections() const { return static_cast<int>(directions_.size()); }

 private:
  int ndm_;
  std::vector<std::string> directions_;
  std::vector<double> lambda_;
  std::vector<double> totalMass_, freeMass_, centre_;
  // [mode][direction]
  std::vector<std::vector<double>> factor_, mass_;
};

}  // namespace beamsolid
