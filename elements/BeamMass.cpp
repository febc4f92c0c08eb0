#include "elements/BeamMass.h"

namespace beamsolid {

namespace {
// Translational mass of the bending field in one plane, (v_i, theta_i, v_j, theta_j), from the
// shape functions of the shear-flexible beam (phi = 12 EI / (G Av L^2); Przemieniecki, Theory of
// Matrix Structural Analysis, 1968, 11.4). phi = 0 gives the cubic Hermite matrix m L / 420 (156, 22 L, ...).
// With r2 = I / A > 0 the rotary inertia of the cross-sections joins in (same source, and
// OpenSees' ElasticTimoshenkoBeam's consistent mass: eigenvalues equal to 1e-9).
Eigen::Matrix4d bendingMass(double m, double L, double phi, double r2) {
  const double s = m * L / ((1.0 + phi) * (1.0 + phi)), p2 = phi * phi;
  const double vv = s * (13.0 / 35.0 + 7.0 / 10.0 * phi + p2 / 3.0);
  const double vt = s * L * (11.0 / 210.0 + 11.0 / 120.0 * phi + p2 / 24.0);
  const double vvj = s * (9.0 / 70.0 + 3.0 / 10.0 * phi + p2 / 6.0);
  const double vtj = s * L * (13.0 / 420.0 + 3.0 / 40.0 * phi + p2 / 24.0);
  const double tt = s * L * L * (1.0 / 105.0 + phi / 60.0 + p2 / 120.0);
  const double ttj = s * L * L * (1.0 / 140.0 + phi / 60.0 + p2 / 120.0);
  const Eigen::Matrix4d translation = (Eigen::Matrix4d() << vv, vt, vvj, -vtj,  //
          vt, tt, vtj, -ttj,                       //
          vvj, vtj, vv, -vt,                       //
          -vtj, -ttj, -vt, tt)
      .finished();
  if (r2 == 0.0) return translation;
  const double q = m * r2 / (L * (1.0 + phi) * (1.0 + phi));
  const double a = q * 6.0 / 5.0, b = q * (0.1 - phi / 2.0) * L;
  const double c = q * (2.0 / 15.0 + phi / 6.0 + p2 / 3.0) * L * L, d = q * (-1.0 / 30.0 - phi / 6.0 + p2 / 6.0) * L * L;
  const Eigen::Matrix4d rotary = (Eigen::Matrix4d() << a, b, -a, b,  //
                                  b, c, -b, d,                       //
                                  -a, -b, a, -b,                     //
                                  b, d, -b, c)
                                     .finished();
  return translation + rotary;
}
}  // namespace

CrdTransf::Matrix12 beamMass(double m, double L, bool consistent, double torsionalInertia, const Matrix3& axes,
                             double phiY, double phiZ, double rotaryY, double rotaryZ) {
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
  const Eigen::Matrix4d massXY = bendingMass(m, L, phiY, rotaryY), massXZ = bendingMass(m, L, phiZ, rotaryZ);
  // x-y plane: (v_i, rz_i, v_j, rz_j); x-z plane: (w_i, -ry_i, w_j, -ry_j).
  const int xy[4] = {1, 5, 7, 11};
  const int xz[4] = {2, 4, 8, 10};
  const double xzSign[4] = {1.0, -1.0, 1.0, -1.0};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      local(xy[a], xy[b]) = massXY(a, b);
      local(xz[a], xz[b]) = xzSign[a] * xzSign[b] * massXZ(a, b);
    }
  Matrix12 rotation = Matrix12::Zero();
  for (int k = 0; k < 4; ++k) rotation.block<3, 3>(3 * k, 3 * k) = axes;
  return rotation.transpose() * local * rotation;
}

}  // namespace beamsolid
