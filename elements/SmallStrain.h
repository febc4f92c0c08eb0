#pragma once
#include "core/Types.h"

namespace beamsolid::smallstrain {

// The small-strain B matrix of shape function gradients d (dN_a/dx_j, one
// row per node) with engineering shear strains, OpenSees' Voigt order:
// 3D [xx, yy, zz, xy, yz, zx] (dofs x, y, z per node); 2D [xx, yy, xy].
template <int Nodes>
void strainDisplacement(const Eigen::Matrix<double, Nodes, 3>& d, Eigen::Matrix<double, 6, 3 * Nodes>& B) {
  B.setZero();
  for (int a = 0; a < Nodes; ++a) {
    const int c = 3 * a;
    const double dx = d(a, 0), dy = d(a, 1), dz = d(a, 2);
    B(0, c) = dx;
    B(1, c + 1) = dy;
    B(2, c + 2) = dz;
    B(3, c) = dy;
    B(3, c + 1) = dx;
    B(4, c + 1) = dz;
    B(4, c + 2) = dy;
    B(5, c) = dz;
    B(5, c + 2) = dx;
  }
}

template <int Nodes>
void strainDisplacement(const Eigen::Matrix<double, Nodes, 2>& d, Eigen::Matrix<double, 3, 2 * Nodes>& B) {
  B.setZero();
  for (int a = 0; a < Nodes; ++a) {
    const int c = 2 * a;
    B(0, c) = d(a, 0);
    B(1, c + 1) = d(a, 1);
    B(2, c) = d(a, 1);
    B(2, c + 1) = d(a, 0);
  }
}

}  // namespace beamsolid::smallstrain
