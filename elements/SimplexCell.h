#pragma once
#include <cmath>
#include <sstream>
#include <string>

#include "core/OpenSeesError.h"
#include "core/Types.h"

namespace beamsolid {

// The linear simplices of OpenSees' constant-strain solids: the 3-node
// triangle (Dim 2: tri31) and the 4-node tetrahedron (Dim 3:
// FourNodeTetrahedron). Shape functions are the barycentric coordinates,
// N_0 = 1 - sum(xi), N_a = xi_a; their gradients are constant, so one
// integration point at the centroid (weight = the volume) integrates the
// stiffness exactly. The same interface as MultilinearCell, so that
// SolidElement and GaussPointSolid serve both.
//
// Node order: the Jacobian [x_a - x_0] must have a positive determinant:
// a triangle counterclockwise; a tetrahedron with node 4 on the side from
// which 1-2-3 runs counterclockwise. OpenSees accepts the other order and
// computes with a negative area (a negative stiffness); we refuse it.
template <int Dim>
class SimplexCell {
 public:
  static constexpr int kNodes = Dim + 1;
  static constexpr int kGaussPoints = 1;
  using Point = Eigen::Matrix<double, Dim, 1>;
  using ShapeValues = Eigen::Matrix<double, kNodes, 1>;
  using ShapeGradients = Eigen::Matrix<double, kNodes, Dim>;
  using NodeCoordinates = Eigen::Matrix<double, kNodes, Dim>;
  using Jacobian = Eigen::Matrix<double, Dim, Dim>;
  using NodalScalars = Eigen::Matrix<double, kNodes, kNodes>;

  static const char* orderHint() {
    return Dim == 3 ? "give the nodes so that node 4 lies on the side from which nodes 1-2-3 run counterclockwise, "
                      "and check that the tetrahedron is not flat"
                    : "give the nodes counterclockwise and check that the triangle is not flat";
  }

  static ShapeValues shapeFunctions(const Point& xi) {
    ShapeValues n;
    n(0) = 1.0 - xi.sum();
    n.template tail<Dim>() = xi;
    return n;
  }

  // dN_a / dxi_j (constant).
  static ShapeGradients naturalGradients(const Point& = Point::Zero()) {
    ShapeGradients g;
    g.row(0).setConstant(-1.0);
    g.template bottomRows<Dim>().setIdentity();
    return g;
  }

  // The one integration point: the centroid.
  static Point gaussPoint(int) { return Point::Constant(1.0 / kNodes); }

  SimplexCell() = default;

  SimplexCell(const NodeCoordinates& X, const std::string& context, const char* orderHint) : X_(X) {
    const ShapeGradients G = naturalGradients();
    jacobian_ = X.transpose() * G;
    const double detJ = jacobian_.determinant();
    // The reference simplex has volume 1/Dim!.
    const double volume = detJ / (Dim == 3 ? 6.0 : 2.0);
    const double scale = (X.rowwise() - X.row(0)).rowwise().norm().maxCoeff();
    if (!(volume > 1e-14 * std::pow(scale, Dim))) {
      std::ostringstream os;
      os << context << ": the " << (Dim == 3 ? "volume" : "area") << " from the node order is " << volume << "; "
         << orderHint;
      throw OpenSeesError(os.str());
    }
    volume_ = volume;
    gradients_ = G * jacobian_.inverse();
    nodalVolume_.setConstant(volume / kNodes);
  }

  const NodeCoordinates& nodeCoordinates() const { return X_; }
  const ShapeGradients& gradients(int = 0) const { return gradients_; }
  // The integration weight of the centroid rule.
  double weightedDetJ(int = 0) const { return volume_; }
  double volume() const { return volume_; }
  // integral of N_a dV = V / (Dim + 1).
  const ShapeValues& nodalVolume() const { return nodalVolume_; }
  const ShapeGradients& meanGradients() const { return gradients_; }
  const Jacobian& centreJacobian() const { return jacobian_; }
  Point coordinatesAt(const Point& xi) const { return X_.transpose() * shapeFunctions(xi); }
  // N_a N_b at the centroid times V: the one-point "consistent" mass over
  // rho (rank 1 per direction), which OpenSees' FourNodeTetrahedron uses.
  NodalScalars shapeProducts() const {
    const ShapeValues n = shapeFunctions(gaussPoint(0));
    return volume_ * n * n.transpose();
  }

 private:
  NodeCoordinates X_ = NodeCoordinates::Zero();
  ShapeGradients gradients_ = ShapeGradients::Zero();
  Jacobian jacobian_ = Jacobian::Identity();
  double volume_ = 0.0;
  ShapeValues nodalVolume_ = ShapeValues::Zero();
};

using LinearTriangle = SimplexCell<2>;
using LinearTetrahedron = SimplexCell<3>;

}  // namespace beamsolid
