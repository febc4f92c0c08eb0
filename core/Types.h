#pragma once
#include <Eigen/Dense>

namespace beamsolid {

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

// Elements keep their matrices in fixed-size Eigen members and hand out
// views, so the hot path allocates nothing.
using VectorView = Eigen::Map<const Eigen::VectorXd>;
using MatrixView = Eigen::Map<const Eigen::MatrixXd>;

template <int N>
inline VectorView viewOf(const Eigen::Matrix<double, N, 1>& v) {
  return VectorView(v.data(), v.size());
}
template <int R, int C>
inline MatrixView viewOf(const Eigen::Matrix<double, R, C>& m) {
  return MatrixView(m.data(), m.rows(), m.cols());
}
inline VectorView viewOf(const Vector& v) { return VectorView(v.data(), v.size()); }
inline MatrixView viewOf(const Matrix& m) { return MatrixView(m.data(), m.rows(), m.cols()); }

}  // namespace beamsolid
