#pragma once
#include "elements/transforms/LinearCrdTransf.h"

namespace beamsolid {

// Linear transformation plus the P-Delta effect of the chord: the axial
// force N = q[0] acting on the relative transverse end displacements adds
// end shears N*dv/L, N*dw/L and the geometric stiffness N/L in both
// transverse planes. No P-delta (bowing) inside the element: members need
// subdividing to approach the exact second-order answer.
//
// The tangent is OpenSees': symmetric, without the term (dv/L) dN/du that
// the force's dependence on N adds; it is exact when the chord is not
// rotated and otherwise a symmetric approximation, so Newton converges to
// the same answer a little more slowly.
class PDeltaCrdTransf : public LinearCrdTransf {
 public:
  using LinearCrdTransf::LinearCrdTransf;

  std::string className() const override { return "PDelta"; }
  std::unique_ptr<CrdTransf> clone() const override;
  std::unique_ptr<CrdTransf2d> planar() const override;

  Vector12 globalResistingForce(const Vector6& q, const Vector12& p0) const override;
  Matrix12 globalStiffMatrix(const Matrix6& kb, const Vector6& q) const override;
  Vector12 localResistingForce(const Vector6& q, const Vector12& p0) const override;

 private:
  // Local end shears N*dv/L, N*dw/L of the rotated chord.
  Vector12 chordShear(double axialForce) const;
};

}  // namespace beamsolid
