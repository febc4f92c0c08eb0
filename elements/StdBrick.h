#pragma once
#include "elements/GaussPointSolid.h"

namespace beamsolid {

// element('stdBrick', tag, n1, ..., n8, matTag, <b1, b2, b3>): the 8-node
// trilinear hexahedron, small strain, 2x2x2 Gauss integration, one copy of
// the ND material ("ThreeDimensional") per Gauss point. Node order as in
// OpenSees: bottom face 1-4 counterclockwise seen from above, then the top
// face 5-8 in the same order (node 5 above node 1).
//
// Body forces b = (b1, b2, b3) are force per unit volume (not multiplied by
// the density): the OpenSees manual calls them "body forces in global x, y,
// z directions", which is what they are added as. They act in full at every
// step, independent of load patterns; eleLoad '-selfWeight' (fx, fy, fz)
// replaces them by factor * (fx b1, fy b2, fz b3) while active (see
// SolidElement). The values scale the element's own b, component by
// component; the density plays no part. So element(..., b1, b2, b3) plus
// eleLoad '-selfWeight' 1 1 1 in a Linear pattern ramps the self weight up
// with the load factor.
//
// Mass: consistent, rho integral(N_a N_b dV) on the 2x2x2 rule (as
// OpenSees' stdBrick, checked against OpenSeesPy's periods).
// Responses: 'stresses'/'strains' (8 Gauss points x 6, OpenSees' point
// order: xi slowest, zeta fastest), 'forces' (24), 'material' k ....
class StdBrick : public GaussPointSolid<3, 6> {
 public:
  static constexpr int kNodes = 8;
  static constexpr int kDofs = 24;

  // `material` is the prototype the element copies once per Gauss point.
  StdBrick(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const Vector3& bodyForce);

  std::string className() const override { return "stdBrick"; }

 protected:
  void formStrainDisplacement(int g, StrainDisplacement& B) const override;
};

}  // namespace beamsolid
