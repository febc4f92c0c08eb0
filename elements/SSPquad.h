#pragma once
#include "elements/SinglePointSolid.h"

namespace beamsolid {

// element('SSPquad', tag, n1, n2, n3, n4, matTag, type, thick, <b1, b2>) in a
// 2D model: the stabilized single-point quadrilateral of McGann, Arduino and
// Mackenzie-Helnwein (2012): one material point at the centre and a
// physical stabilization from an assumed hourglass strain whose dilatation
// and shear strain are zero (docs/solid_elements.md, eqs. SSPquad):
//   q = (gamma . u_x, gamma . u_y),  gamma = (h - (h.x) b_x - (h.y) b_y) / 4,
//   h = (1, -1, 1, -1), b = centre gradients,
//   hourglass strain (xi g1 + eta g0) with g_k = (1/2)(dk/dx q_x - dk/dy q_y) [1, -1, 0],
//   K_stab = thick (A/3) (v^T D0 v) sum_k r_k r_k^T,  v = [1, -1, 0],
// (g0 = grad xi, g1 = grad eta at the centre; integral xi^2 dA = A/3). It
// acts on the two hourglass modes only, costs no dilatation (no volumetric
// locking) and no shear (no shear locking in bending).
//
// Agreement with OpenSeesPy 3.7.1's SSPquad: stiffness and mass to
// round-off on rectangles in any orientation; on other quadrilaterals the
// two hourglass stiffnesses differ (the centre part, the patch test and
// every constant-strain answer agree); docs/solid_elements.md gives the
// measured difference.
// Body forces b1, b2 per unit volume and '-selfWeight' as quad (SolidElement);
// mass lumped, rho thick integral(N_a dA), rho of the material.
// Responses: 'stresses'/'strains' (the centre point: 3 values), 'forces'
// (8), 'material' 1 ....
class SSPquad : public SinglePointSolid<2, 3> {
 public:
  static constexpr int kNodes = 4;

  SSPquad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const std::string& type,
          double thickness, const Eigen::Vector2d& bodyForce);

  std::string className() const override { return "SSPquad"; }

 protected:
  void formStabilization(const StrainMatrix& D0, NodalMatrix& K) const override;
  MassKind massKind() const override { return MassKind::RowSum; }
};

}  // namespace beamsolid
