#pragma once
#include <array>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

// Where the patch and layer commands put fibers: (y, z) and area of each, in
// section coordinates. Patch cells are exact: every cell's area and centroid
// are those of the cell itself, so the fibers' total area equals the patch's
// area for any subdivision and the moments of inertia converge as the square
// of the cell size.
struct FiberPoint {
  double y = 0.0, z = 0.0, area = 0.0;
};

namespace fibergeometry {

// patch('rect', ..., numSubdivY, numSubdivZ, yI, zI, yJ, zJ): opposite corners.
std::vector<FiberPoint> rectPatch(int numSubdivY, int numSubdivZ, double yI, double zI, double yJ, double zJ);

// patch('quad', ..., numSubdivIJ, numSubdivJK, yI, zI, yJ, zJ, yK, zK, yL, zL):
// a quadrilateral I-J-K-L (either orientation), cells bounded by straight
// lines of the bilinear map (its iso-lines are straight).
std::vector<FiberPoint> quadPatch(int numSubdivIJ, int numSubdivJK, const std::array<Eigen::Vector2d, 4>& vertices);

// patch('circ', ..., numSubdivCirc, numSubdivRad, yC, zC, intRad, extRad,
// startAng, endAng): annular sectors, angles in degrees from local y to z.
std::vector<FiberPoint> circPatch(int numSubdivCirc, int numSubdivRad, double yC, double zC, double innerRadius,
                                  double outerRadius, double startAngle, double endAngle);

// layer('straight', ..., numFiber, areaFiber, yStart, zStart, yEnd, zEnd):
// numFiber fibers from start to end inclusive (one fiber: the midpoint).
std::vector<FiberPoint> straightLayer(int numFiber, double areaFiber, double yStart, double zStart, double yEnd,
                                      double zEnd);

// layer('circ', ..., numFiber, areaFiber, yC, zC, radius, startAng, endAng):
// numFiber fibers from startAng to endAng inclusive (degrees).
std::vector<FiberPoint> circLayer(int numFiber, double areaFiber, double yC, double zC, double radius,
                                  double startAngle, double endAngle);

}  // namespace fibergeometry
}  // namespace beamsolid
