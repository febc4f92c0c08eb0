#pragma once
#include "elements/PlaneGaussSolid.h"

namespace beamsolid {

// element('quad', tag, n1, n2, n3, n4, thick, type, matTag, <pressure, rho,
// b1, b2>) in a 2D model (nodes with ndf 2): the 4-node bilinear
// isoparametric quadrilateral, small strain, 2x2 Gauss integration, one copy
// of the ND material in its `type` form ('PlaneStrain' or 'PlaneStress')
// per Gauss point. Nodes counterclockwise. Strain [e11, e22, g12], stress
// [s11, s22, s12].
//
// Loads as OpenSees applies them (checked against OpenSeesPy 3.7.1):
// - b1, b2 and pressure as PlaneSolidProperties says; both act in full at
//   every step, independent of load patterns.
// - eleLoad '-selfWeight' (fx, fy): while such loads are active the body
//   force is sum over them of factor * (fx b1, fy b2) and b itself no longer
//   acts (as StdBrick). The pressure keeps acting.
// - Mass: lumped, rho * thick * integral(N_a dA) on both dofs of node a,
//   with rho the element's, or the material's density when that is 0.
class FourNodeQuad : public PlaneGaussSolid<BilinearQuadrilateral> {
 public:
  static constexpr int kNodes = 4;
  static constexpr int kDofs = 8;
  using Vector8 = NodalVector;

  FourNodeQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
               const Properties& properties)
      : PlaneGaussSolid(tag, nodeTags, material, properties, "quad") {}

  std::string className() const override { return "quad"; }
};

}  // namespace beamsolid
