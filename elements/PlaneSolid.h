#pragma once
#include <array>
#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Types.h"
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// What OpenSees' plane solids with a thickness, quad and tri31, take after
// their nodes: thick, type, matTag, <pressure, rho, b1, b2>, and how they
// apply it (checked against OpenSeesPy 3.7.1 for both):
// - the material in its `type` form, 'PlaneStrain' or 'PlaneStress';
// - b1, b2 force per unit volume (not multiplied by rho) over thick * area;
// - pressure p: each edge i -> j (nodes counterclockwise) takes
//   p * (dy, -dx), outward for p > 0, half to each end node, on the
//   reference geometry, times the edge length but not thick;
// - lumped mass rho * thick * integral(N_a dA), rho the element's, or the
//   material's when that is 0.
struct PlaneSolidProperties {
  double thickness = 1.0;
  std::string type = "PlaneStrain";  // the material kind: "PlaneStrain" | "PlaneStress"
  double pressure = 0.0;
  double rho = 0.0;
  Eigen::Vector2d bodyForce = Eigen::Vector2d::Zero();

  // The mass density the element uses.
  double density(const NDMaterial& material) const { return rho != 0.0 ? rho : material.density(); }
};

namespace planesolid {

// `type` itself, or an OpenSeesError naming element `className` `tag`.
const std::string& checkedType(const std::string& className, int tag, const std::string& type);

template <int N>
struct Command {
  int tag = 0;
  std::array<int, N> nodes{};
  const NDMaterial* material = nullptr;
  PlaneSolidProperties properties;
};

// element(className, tag, *N nodes, thick, type, matTag, <pressure, rho, b1, b2>)
// in a 2D model. quad takes any leading part of the optional numbers;
// `allOrNone` (tri31) refuses 1-3 of them: OpenSees' tri31 then silently
// ignores all four (checked with OpenSeesPy 3.7.1).
template <int N>
Command<N> parse(CommandArgs& args, Domain& domain, const std::string& className, bool allOrNone = false);

// The nodal forces of pressure p on the polygon's edges (rows of X in order).
template <int N>
Eigen::Matrix<double, 2 * N, 1> pressureLoad(const Eigen::Matrix<double, N, 2>& X, double p) {
  Eigen::Matrix<double, 2 * N, 1> f = Eigen::Matrix<double, 2 * N, 1>::Zero();
  for (int a = 0; a < N; ++a) {
    const int b = (a + 1) % N;
    const Eigen::Vector2d d = X.row(b).transpose() - X.row(a).transpose();
    const Eigen::Vector2d half = 0.5 * p * Eigen::Vector2d(d.y(), -d.x());
    f.template segment<2>(2 * a) += half;
    f.template segment<2>(2 * b) += half;
  }
  return f;
}

}  // namespace planesolid

}  // namespace beamsolid
