#pragma once
#include <cmath>
#include <sstream>
#include <string>

#include "core/OpenSeesError.h"
#include "core/Types.h"

namespace beamsolid {

// The isoparametric cells of OpenSees' low-order solids: the bilinear
// quadrilateral (Dim 2: quad, bbarQuad, SSPquad) and the trilinear
// hexahedron (Dim 3: stdBrick, bbarBrick, SSPbrick). Shape functions are
// products of (1 + xi_i xi_a,i) / 2 over the directions; nodes run
// counterclockwise (and, for the hexahedron, bottom face 1-4 then the top
// face 5-8 above it). An object holds one element's reference geometry:
// shape function gradients and weights at the 2^Dim Gauss points, each
// node's share of the volume, the Jacobian at the centre.
template <int Dim>
class MultilinearCell {
 public:
  static constexpr int kNodes = 1 << Dim;
  static constexpr int kGaussPoints = kNodes;
  using Point = Eigen::Matrix<double, Dim, 1>;
  using ShapeValues = Eigen::Matrix<double, kNodes, 1>;
  using ShapeGradients = Eigen::Matrix<double, kNodes, Dim>;
  using NodeCoordinates = Eigen::Matrix<double, kNodes, Dim>;
  using Jacobian = Eigen::Matrix<double, Dim, Dim>;
  using NodalScalars = Eigen::Matrix<double, kNodes, kNodes>;

  // What to check when the Jacobian is not positive.
  static const char* orderHint() {
    return Dim == 3 ? "check the node order (bottom face 1-4 counterclockwise seen from above, top face 5-8 "
                      "above 1-4) and that the element is not degenerate"
                    : "give the nodes counterclockwise and check that the quadrilateral is convex and not "
                      "degenerate";
  }

  // Natural coordinates (each +-1) of node a.
  static Point nodeNatural(int a) {
    static constexpr double square[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    Point p;
    p(0) = square[a % 4][0];
    p(1) = square[a % 4][1];
    if constexpr (Dim == 3) p(2) = a < 4 ? -1.0 : 1.0;
    return p;
  }

  static ShapeValues shapeFunctions(const Point& xi) {
    ShapeValues n;
    for (int a = 0; a < kNodes; ++a) {
      const Point xa = nodeNatural(a);
      double v = 1.0;
      for (int i = 0; i < Dim; ++i) v *= 0.5 * (1.0 + xi(i) * xa(i));
      n(a) = v;
    }
    return n;
  }

  // dN_a / dxi_j.
  static ShapeGradients naturalGradients(const Point& xi) {
    ShapeGradients g;
    for (int a = 0; a < kNodes; ++a) {
      const Point xa = nodeNatural(a);
      for (int j = 0; j < Dim; ++j) {
        double v = 0.5 * xa(j);
        for (int i = 0; i < Dim; ++i)
          if (i != j) v *= 0.5 * (1.0 + xi(i) * xa(i));
        g(a, j) = v;
      }
    }
    return g;
  }

  // Gauss point g of the 2^Dim rule (+-1/sqrt(3), unit weights), numbered as
  // OpenSees reports them ('stresses', 'material' k): counterclockwise like
  // the nodes for the quadrilateral; xi slowest and zeta fastest for the
  // hexahedron, (-,-,-), (-,-,+), (-,+,-), ...
  static Point gaussPoint(int g) {
    Point p;
    if constexpr (Dim == 2) {
      p = nodeNatural(g);
    } else {
      p << (g & 4 ? 1.0 : -1.0), (g & 2 ? 1.0 : -1.0), (g & 1 ? 1.0 : -1.0);
    }
    return p / std::sqrt(3.0);
  }

  MultilinearCell() = default;

  // The reference geometry of nodes X (one row per node); `context` and
  // `orderHint` make the message when the Jacobian is not positive.
  MultilinearCell(const NodeCoordinates& X, const std::string& context, const char* orderHint) : X_(X) {
    volume_ = 0.0;
    nodalVolume_.setZero();
    for (int g = 0; g < kGaussPoints; ++g) {
      const Point xi = gaussPoint(g);
      const ShapeGradients G = naturalGradients(xi);
      const Jacobian J = X.transpose() * G;  // J_ij = dx_i / dxi_j
      const double detJ = J.determinant();
      if (!(detJ > 0.0)) {
        std::ostringstream os;
        os << context << ": the Jacobian determinant is " << detJ << " at Gauss point " << g + 1 << "; "
           << orderHint;
        throw OpenSeesError(os.str());
      }
      gradients_[g] = G * J.inverse();
      detJ_[g] = detJ;  // unit Gauss weights
      volume_ += detJ;
      nodalVolume_ += detJ * shapeFunctions(xi);
    }
    meanGradients_.setZero();
    for (int g = 0; g < kGaussPoints; ++g) meanGradients_ += detJ_[g] * gradients_[g];
    meanGradients_ /= volume_;
    centreJacobian_ = X.transpose() * naturalGradients(Point::Zero());
  }

  const NodeCoordinates& nodeCoordinates() const { return X_; }
  // dN_a / dx_j at Gauss point g.
  const ShapeGradients& gradients(int g) const { return gradients_[g]; }
  // det J at Gauss point g (the Gauss weights are 1).
  double weightedDetJ(int g) const { return detJ_[g]; }
  // Volume (area in 2D) of the element, exact for the multilinear map.
  double volume() const { return volume_; }
  // integral of N_a dV: node a's share of the volume (row-sum lumping).
  const Eigen::Matrix<double, kNodes, 1>& nodalVolume() const { return nodalVolume_; }
  // The mean shape function gradients (1/V) integral(grad N_a dV): B-bar's
  // dilatation, the single-point elements' strain.
  const ShapeGradients& meanGradients() const { return meanGradients_; }
  // dx / dxi at the centre.
  const Jacobian& centreJacobian() const { return centreJacobian_; }
  // x of natural point xi.
  Point coordinatesAt(const Point& xi) const { return X_.transpose() * shapeFunctions(xi); }
  // integral of N_a N_b dV on the Gauss rule (the consistent mass over rho).
  NodalScalars shapeProducts() const {
    NodalScalars m = NodalScalars::Zero();
    for (int g = 0; g < kGaussPoints; ++g) {
      const ShapeValues n = shapeFunctions(gaussPoint(g));
      m.noalias() += detJ_[g] * n * n.transpose();
    }
    return m;
  }

 private:
  NodeCoordinates X_ = NodeCoordinates::Zero();
  ShapeGradients gradients_[kGaussPoints];
  double detJ_[kGaussPoints] = {};
  double volume_ = 0.0;
  Eigen::Matrix<double, kNodes, 1> nodalVolume_ = Eigen::Matrix<double, kNodes, 1>::Zero();
  ShapeGradients meanGradients_ = ShapeGradients::Zero();
  Jacobian centreJacobian_ = Jacobian::Identity();
};

using BilinearQuadrilateral = MultilinearCell<2>;
using TrilinearHexahedron = MultilinearCell<3>;

}  // namespace beamsolid
