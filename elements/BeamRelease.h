#pragma once
#include <Eigen/Dense>

namespace beamsolid {

// Moment releases of elastic beams (elasticBeamColumn '-release' in 2D,
// '-releasez'/'-releasey' in 3D): code 0 none, 1 the moment at I, 2 at J,
// 3 both. A released end carries no moment: it is condensed out of the
// basic stiffness, and an element load's fixed-end moment there is carried
// over to the other end.
struct BeamRelease {
  // Condenses the bending block of moments (i, j) of a basic stiffness:
  // kjj - kij^2/kii at the end that stays (3EI/L), zero at a released end.
  template <typename MatrixType>
  static void condense(MatrixType& kb, int i, int j, int code) {
    const double kii = kb(i, i), kjj = kb(j, j), kij = kb(i, j);
    switch (code) {
      case 1: kb(i, i) = kb(i, j) = kb(j, i) = 0.0; kb(j, j) = kjj - kij * kij / kii; break;
      case 2: kb(j, j) = kb(i, j) = kb(j, i) = 0.0; kb(i, i) = kii - kij * kij / kjj; break;
      case 3: kb(i, i) = kb(j, j) = kb(i, j) = kb(j, i) = 0.0; break;
      default: break;
    }
  }
  // Fixed-end moments (mi, mj) with the released ones carried over to the
  // other end (the carry-over factor of a prismatic Euler-Bernoulli beam,
  // 1/2) or, with both released, dropped.
  static void carryOver(double& mi, double& mj, int code) {
    switch (code) {
      case 1: mj -= 0.5 * mi; mi = 0.0; break;
      case 2: mi -= 0.5 * mj; mj = 0.0; break;
      case 3: mi = mj = 0.0; break;
      default: break;
    }
  }
};

}  // namespace beamsolid
