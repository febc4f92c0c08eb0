#pragma once
#include "elements/PlaneGaussSolid.h"

namespace beamsolid {

// element('tri31', tag, i, j, k, thick, type, matTag, <pressure, rho, b1,
// b2>) in a 2D model (nodes with ndf 2): the 3-node constant-strain
// triangle, small strain, one material point at the centroid (exact for
// the constant strain), the ND material in its `type` form ('PlaneStrain'
// or 'PlaneStress'). Nodes counterclockwise (a clockwise triangle is
// refused; OpenSees computes it with a negative area). The optional
// numbers come all four or none (OpenSees ignores 1 to 3 of them silently;
// we refuse them).
//
// As OpenSees' Tri31 (checked against OpenSeesPy 3.7.1): b1, b2 per unit
// volume over thick * area, a third to each node; pressure on the edges as
// quad; lumped mass rho thick A / 3 per node and direction, rho the
// element's or, when 0, the material's; eleLoad '-selfWeight' as quad.
// Responses 'forces' (resisting forces minus the element loads, P1_1 P2_1
// ... P2_3), 'stresses' (sigma11 sigma22 sigma12 of the one point),
// 'material'/'integrPoint' 1 ...; also 'strains' (OpenSees gives none).
class Tri31 : public PlaneGaussSolid<LinearTriangle> {
 public:
  static constexpr int kNodes = 3;
  static constexpr int kDofs = 6;

  Tri31(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const Properties& properties)
      : PlaneGaussSolid(tag, nodeTags, material, properties, "tri31") {}

  std::string className() const override { return "tri31"; }
};

}  // namespace beamsolid
