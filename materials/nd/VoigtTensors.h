#pragma once
#include <cmath>

#include <Eigen/Dense>

namespace beamsolid::voigt {

// Symmetric second-order tensors as Voigt 6-vectors in OpenSees order
// [11, 22, 33, 12, 23, 13]. Two kinds share the layout:
// - strain-like: engineering shears (the 12 slot holds 2 eps_12), as
//   elements pass strains;
// - stress-like: tensor components (the 12 slot holds s_12).
// The helpers below say which kind they take and give.
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// The second-order identity (either kind: its shears are zero).
inline Vector6 identity() {
  Vector6 m;
  m << 1, 1, 1, 0, 0, 0;
  return m;
}

inline double trace(const Vector6& t) { return t(0) + t(1) + t(2); }

// Deviator of a strain-like vector as a stress-like (tensor) vector:
// e_ij = eps_ij - tr(eps)/3 delta_ij, shears halved.
inline Vector6 strainDeviatorAsTensor(const Vector6& strain) {
  const double mean = trace(strain) / 3.0;
  Vector6 e;
  e << strain(0) - mean, strain(1) - mean, strain(2) - mean, 0.5 * strain(3), 0.5 * strain(4), 0.5 * strain(5);
  return e;
}

// Deviator of a stress-like vector (stress-like).
inline Vector6 deviator(const Vector6& s) {
  const double mean = trace(s) / 3.0;
  Vector6 d = s;
  d.head<3>().array() -= mean;
  return d;
}

// Tensor norm sqrt(t : t) of a stress-like vector.
inline double norm(const Vector6& t) {
  return std::sqrt(t.head<3>().squaredNorm() + 2.0 * t.tail<3>().squaredNorm());
}

// Tensor (stress-like) to strain-like: shears doubled.
inline Vector6 tensorToStrain(const Vector6& t) {
  Vector6 e = t;
  e.tail<3>() *= 2.0;
  return e;
}

// d(stress-like)/d(strain-like) of the deviatoric projector:
// dev(eps) with engineering shears in, tensor components out.
inline Matrix6 deviatoricProjector() {
  Matrix6 P = Matrix6::Zero();
  P.topLeftCorner<3, 3>().setConstant(-1.0 / 3.0);
  for (int i = 0; i < 3; ++i) {
    P(i, i) += 1.0;
    P(i + 3, i + 3) = 0.5;
  }
  return P;
}

// Isotropic elastic tangent K 1(x)1 + 2G P_dev with engineering shears.
inline Matrix6 isotropicElasticity(double K, double G) {
  const Vector6 one = identity();
  return K * one * one.transpose() + 2.0 * G * deviatoricProjector();
}

}  // namespace beamsolid::voigt
