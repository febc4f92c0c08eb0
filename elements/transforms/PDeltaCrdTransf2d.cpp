#include "elements/transforms/PDeltaCrdTransf2d.h"

namespace beamsolid {

PDeltaCrdTransf2d::Vector6 PDeltaCrdTransf2d::globalResistingForce(const Vector3& q, const Vector6& p0) const {
  // Chord shear N*dv/L of the relative transverse end displacement.
  const Vector6& u = localTrialDisp();
  const double shear = q[0] * (u[4] - u[1]) / initialLength();
  Vector6 p = basicToLocal(q, p0, initialLength());
  p[1] -= shear;
  p[4] += shear;
  return localFromGlobal().transpose() * p;
}

PDeltaCrdTransf2d::Matrix6 PDeltaCrdTransf2d::globalStiffMatrix(const Matrix3& kb, const Vector3& q) const {
  // Geometric stiffness N/L (e_j - e_i)(e_j - e_i)^T on the local v dofs.
  const Vector6 dv = (localFromGlobal().row(4) - localFromGlobal().row(1)).transpose();
  Matrix6 k = initialGlobalStiffMatrix(kb);
  k.noalias() += (q[0] / initialLength()) * (dv * dv.transpose());
  return k;
}

}  // namespace beamsolid
