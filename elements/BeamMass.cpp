#include "elements/BeamMass.h"

namespace beamsolid {

CrdTransf::Matrix12 beamMass(double m, double L, bool consistent, double torsionalInertia, const Matrix3& axes) {
  using Matrix12 = CrdTransf::Matrix12;
  Matrix12 mass = Matrix12::Zero();
  if (m == 0.0) return mass;
  if (!consistent) {
    for (int d : {0, 1, 2, 6, 7, 8}) mass(d, d) = 0.5 * m * L;
    return mass;
  }
  Matrix12 local = Matrix12::Zero();
  local(0, 0) = local(6, 6) = m * L / 3.0;
  local(0, 6) = local(6, 0) = m * L / 6.0;
  local(3, 3) = local(9, 9) = torsionalInertia * L / 3.0;
  local(3, 9) = local(9, 3) = torsionalInertia * L / 6.0;
  const double c = m * L / 420.0;
  const Eigen::Matrix4d hermite = (Eigen::Matrix4d() << 156.0, 22.0 * L, 54.0, -13.0 * L,  //
                                   22.0 * L, 4.0 * L * L, 13.0 * L, -3.0 * L * L,          //
                                   54.0, 13.0 * L, 156.0, -22.0 * L,                       //
                                   -13.0 * L, -3.0 * L * L, -22.0 * L, 4.0 * L * L)
                                      .finished();
  // x-y plane: (v_i, rz_i, v_j, rz_j); x-z plane: (w_i, -ry_i, w_j, -ry_j).
  const int xy[4] = {1, 5, 7, 11};
  const int xz[4] = {2, 4, 8, 10};
  const double xzSign[4] = {1.0, -1.0, 1.0, -1.0};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      local(xy[a], xy[b]) = c * hermite(a, b);
      local(xz[a], xz[b]) = c * xzSign[a] * xzSign[b] * hermite(a, b);
    }
  Matrix12 rotation = Matrix12::Zero();
  for (int k = 0; k < 4; ++k) rotation.block<3, 3>(3 * k, 3 * k) = axes;
  return rotation.transpose() * local * rotation;
}

}  // namespace beamsolid
