#pragma once
#include "elements/SectionBeamColumn3d.h"

namespace beamsolid {

// Displacement-based 3D beam-column (dispBeamColumn):
//   element('dispBeamColumn', tag, iNode, jNode, transfTag, integrationTag,
//           <'-cMass'>, <'-mass', massPerLength>)
//   element('dispBeamColumn', tag, iNode, jNode, numIntgrPts, secTag, transfTag, ...)  (older form)
// Linear axial displacement and cubic Hermite bending in the basic system,
// so the section deformations are e(xi) = B(xi) v with, for each plane,
// kappa = ((6 xi - 4) theta_i + (6 xi - 2) theta_j) / L, and
// q = sum w L B^T s, kb = sum w L B^T ks B (default rule: Legendre).
// Element loads enter as consistent (fixed-end) forces. A shear section's
// Vy, Vz stay unstrained (Hermite bending has no shear strain), as in
// OpenSees and the 2D element.
class DispBeamColumn3d : public SectionBeamColumn3d {
 public:
  DispBeamColumn3d(int tag, Definition&& definition);

  std::string className() const override { return "dispBeamColumn"; }

  void update() override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;

  Vector6 basicForce() override { return sectionForce_ + q0_; }
  const Matrix6& basicStiffness() override { return kb_; }

  // Strain-displacement matrix of the basic system at xi for length L.
  static Eigen::Matrix<double, 4, 6> strainDisplacement(double xi, double length);

 protected:
  void initializeState() override;

 private:
  // Sums the sections' current forces and tangents into q and kb.
  void assemble();

  Vector6 sectionForce_ = Vector6::Zero();
  Vector6 q0_ = Vector6::Zero();
  Matrix6 kb_ = Matrix6::Zero();
};

}  // namespace beamsolid
