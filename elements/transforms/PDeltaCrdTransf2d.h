#pragma once
#include "elements/transforms/LinearCrdTransf2d.h"

namespace beamsolid {

// The 2D linear transformation plus the P-Delta effect of the chord: end
// shears N*dv/L and the geometric stiffness N/L on the relative transverse
// displacement (see PDeltaCrdTransf, its 3D counterpart).
class PDeltaCrdTransf2d : public LinearCrdTransf2d {
 public:
  using LinearCrdTransf2d::LinearCrdTransf2d;

  std::string className() const override { return "PDelta"; }

  Vector6 globalResistingForce(const Vector3& q, const Vector6& p0) const override;
  Matrix6 globalStiffMatrix(const Matrix3& kb, const Vector3& q) const override;
};

}  // namespace beamsolid
