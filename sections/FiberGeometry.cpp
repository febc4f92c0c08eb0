#include "sections/FiberGeometry.h"

#include <cmath>
#include <numbers>

namespace beamsolid::fibergeometry {

namespace {

// Area and centroid of a simple polygon (shoelace); the area is unsigned.
FiberPoint polygonFiber(const std::array<Eigen::Vector2d, 4>& p) {
  double twiceArea = 0.0, sy = 0.0, sz = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& a = p[k];
    const Eigen::Vector2d& b = p[(k + 1) % 4];
    const double cross = a.x() * b.y() - b.x() * a.y();
    twiceArea += cross;
    sy += (a.x() + b.x()) * cross;
    sz += (a.y() + b.y()) * cross;
  }
  // The centroid formula holds for either orientation (signs cancel).
  return FiberPoint{sy / (3.0 * twiceArea), sz / (3.0 * twiceArea), 0.5 * std::fabs(twiceArea)};
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

std::vector<FiberPoint> rectPatch(int numSubdivY, int numSubdivZ, double yI, double zI, double yJ, double zJ) {
  std::vector<FiberPoint> out;
  out.reserve(static_cast<std::size_t>(numSubdivY) * numSubdivZ);
  const double dy = (yJ - yI) / numSubdivY;
  const double dz = (zJ - zI) / numSubdivZ;
  for (int j = 0; j < numSubdivZ; ++j)
    for (int i = 0; i < numSubdivY; ++i)
      out.push_back(FiberPoint{yI + (i + 0.5) * dy, zI + (j + 0.5) * dz, std::fabs(dy * dz)});
  return out;
}

std::vector<FiberPoint> quadPatch(int numSubdivIJ, int numSubdivJK, const std::array<Eigen::Vector2d, 4>& v) {
  // Bilinear map: s runs I->J, t runs J->K (I=(0,0), J=(1,0), K=(1,1), L=(0,1)).
  auto map = [&v](double s, double t) -> Eigen::Vector2d {
    return (1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3];
  };
  std::vector<FiberPoint> out;
  out.reserve(static_cast<std::size_t>(numSubdivIJ) * numSubdivJK);
  for (int j = 0; j < numSubdivJK; ++j)
    for (int i = 0; i < numSubdivIJ; ++i) {
      const double s0 = double(i) / numSubdivIJ, s1 = double(i + 1) / numSubdivIJ;
      const double t0 = double(j) / numSubdivJK, t1 = double(j + 1) / numSubdivJK;
      out.push_back(polygonFiber({map(s0, t0), map(s1, t0), map(s1, t1), map(s0, t1)}));
    }
  return out;
}

std::vector<FiberPoint> circPatch(int numSubdivCirc, int numSubdivRad, double yC, double zC, double innerRadius,
                                  double outerRadius, double startAngle, double endAngle) {
  std::vector<FiberPoint> out;
  out.reserve(static_cast<std::size_t>(numSubdivCirc) * numSubdivRad);
  const double dTheta = radians(endAngle - startAngle) / numSubdivCirc;
  const double dr = (outerRadius - innerRadius) / numSubdivRad;
  // Annular sector r in [r0, r1], angle dTheta: area dTheta (r1^2 - r0^2) / 2,
  // centroid on the bisector at (2/3)(r1^3 - r0^3)/(r1^2 - r0^2) sin(h)/h, h = dTheta/2.
  const double half = 0.5 * std::fabs(dTheta);
  const double shrink = std::sin(half) / half;
  for (int j = 0; j < numSubdivRad; ++j) {
    const double r0 = innerRadius + j * dr, r1 = innerRadius + (j + 1) * dr;
    const double area = 0.5 * std::fabs(dTheta) * std::fabs(r1 * r1 - r0 * r0);
    const double rc = 2.0 / 3.0 * (r1 * r1 * r1 - r0 * r0 * r0) / (r1 * r1 - r0 * r0) * shrink;
    for (int i = 0; i < numSubdivCirc; ++i) {
      const double theta = radians(startAngle) + (i + 0.5) * dTheta;
      out.push_back(FiberPoint{yC + rc * std::cos(theta), zC + rc * std::sin(theta), area});
    }
  }
  return out;
}

std::vector<FiberPoint> straightLayer(int numFiber, double areaFiber, double yStart, double zStart, double yEnd,
                                      double zEnd) {
  std::vector<FiberPoint> out;
  out.reserve(numFiber);
  if (numFiber == 1) {
    out.push_back(FiberPoint{0.5 * (yStart + yEnd), 0.5 * (zStart + zEnd), areaFiber});
    return out;
  }
  for (int k = 0; k < numFiber; ++k) {
    const double t = double(k) / (numFiber - 1);
    out.push_back(FiberPoint{yStart + t * (yEnd - yStart), zStart + t * (zEnd - zStart), areaFiber});
  }
  return out;
}

std::vector<FiberPoint> circLayer(int numFiber, double areaFiber, double yC, double zC, double radius,
                                  double startAngle, double endAngle) {
  std::vector<FiberPoint> out;
  out.reserve(numFiber);
  const double step = numFiber > 1 ? (endAngle - startAngle) / (numFiber - 1) : 0.0;
  for (int k = 0; k < numFiber; ++k) {
    const double theta = radians(startAngle + k * step);
    out.push_back(FiberPoint{yC + radius * std::cos(theta), zC + radius * std::sin(theta), areaFiber});
  }
  return out;
}

}  // namespace beamsolid::fibergeometry
