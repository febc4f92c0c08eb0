// SimplexCell (the reference geometry of tri31 and FourNodeTetrahedron):
// area and volume against the cross and triple products, gradients that
// reproduce every linear field exactly (and sum to zero), the nodal shares
// and the one-point shape products, and the refusal of a wrong node order.
#include <gtest/gtest.h>

#include "core/OpenSeesError.h"
#include "elements/SimplexCell.h"

using namespace beamsolid;

TEST(SimplexCell, TriangleAreaAndGradientsOfLinearFields) {
  LinearTriangle::NodeCoordinates X;
  X << 0.0, 0.0, 2.0, 0.3, 0.5, 1.5;
  const LinearTriangle cell(X, "test", LinearTriangle::orderHint());
  const double area = 0.5 * ((X(1, 0) - X(0, 0)) * (X(2, 1) - X(0, 1)) - (X(2, 0) - X(0, 0)) * (X(1, 1) - X(0, 1)));
  EXPECT_NEAR(cell.volume(), area, 1e-15);
  // f = 3 + 2x - 5y has gradient (2, -5) from its nodal values.
  Eigen::Vector3d f;
  for (int a = 0; a < 3; ++a) f(a) = 3.0 + 2.0 * X(a, 0) - 5.0 * X(a, 1);
  const Eigen::Vector2d g = cell.gradients(0).transpose() * f;
  EXPECT_NEAR(g(0), 2.0, 1e-14);
  EXPECT_NEAR(g(1), -5.0, 1e-14);
  EXPECT_NEAR(cell.gradients(0).colwise().sum().norm(), 0.0, 1e-15);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(cell.nodalVolume()(a), area / 3.0, 1e-15);
  // The centroid.
  const Eigen::Vector2d c = cell.coordinatesAt(LinearTriangle::gaussPoint(0));
  EXPECT_NEAR(c(0), (0.0 + 2.0 + 0.5) / 3.0, 1e-15);
  EXPECT_NEAR(c(1), (0.0 + 0.3 + 1.5) / 3.0, 1e-15);
}

TEST(SimplexCell, TetrahedronVolumeGradientsAndOnePointMass) {
  LinearTetrahedron::NodeCoordinates X;
  X << 0.0, 0.0, 0.0, 2.0, 0.2, 0.1, 0.3, 1.5, -0.1, 0.2, 0.4, 1.7;
  const LinearTetrahedron cell(X, "test", LinearTetrahedron::orderHint());
  const Eigen::Vector3d a = X.row(1) - X.row(0), b = X.row(2) - X.row(0), d = X.row(3) - X.row(0);
  const double volume = a.dot(b.cross(d)) / 6.0;
  EXPECT_NEAR(cell.volume(), volume, 1e-15);
  Eigen::Vector4d f;
  for (int n = 0; n < 4; ++n) f(n) = -1.0 + 0.5 * X(n, 0) + 4.0 * X(n, 1) - 3.0 * X(n, 2);
  const Eigen::Vector3d g = cell.gradients(0).transpose() * f;
  EXPECT_NEAR((g - Eigen::Vector3d(0.5, 4.0, -3.0)).norm(), 0.0, 1e-14);
  // rho V N N^T at the centroid: V / 16 everywhere, summing to V.
  const LinearTetrahedron::NodalScalars m = cell.shapeProducts();
  EXPECT_NEAR((m.array() - volume / 16.0).abs().maxCoeff(), 0.0, 1e-15);
  EXPECT_NEAR(m.sum(), volume, 1e-14);
}

TEST(SimplexCell, WrongOrderAndFlatCellsAreRefused) {
  LinearTriangle::NodeCoordinates clockwise;
  clockwise << 0.0, 0.0, 0.5, 1.5, 2.0, 0.3;
  try {
    LinearTriangle(clockwise, "element tri31 4", LinearTriangle::orderHint());
    FAIL() << "a clockwise triangle was accepted";
  } catch (const OpenSeesError& e) {
    EXPECT_NE(std::string(e.what()).find("element tri31 4: the area"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("counterclockwise"), std::string::npos) << e.what();
  }
  LinearTetrahedron::NodeCoordinates flat;
  flat << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0;
  EXPECT_THROW(LinearTetrahedron(flat, "element FourNodeTetrahedron 2", LinearTetrahedron::orderHint()),
               OpenSeesError);
}
