#pragma once
#include "elements/GaussPointSolid.h"

namespace beamsolid {

// element('FourNodeTetrahedron', tag, n1, n2, n3, n4, matTag, <b1, b2, b3>)
// in a 3D model (nodes with ndf 3): the 4-node linear (constant-strain)
// tetrahedron, small strain, one copy of the ND material
// ("ThreeDimensional") at the centroid. Node order: node 4 on the side from
// which 1-2-3 run counterclockwise (positive volume); the other order is
// refused (OpenSees computes it with a negative volume).
//
// As OpenSees' FourNodeTetrahedron (checked against OpenSeesPy 3.7.1):
// b1..b3 force per unit volume, V/4 to each node, in full at every step
// ('-selfWeight' as stdBrick, see SolidElement); mass from the material's
// rho on the one-point rule, M_ab = rho V N_a N_b at the centroid = rho V / 16
// for every pair of nodes (per direction: rank 1, so an eigen analysis
// sees only one mass per direction and element).
// Responses 'forces' (12), 'stresses' and 'strains' (6: 11 22 33 12 23 13),
// 'material'/'integrPoint' 1 ....
class FourNodeTetrahedron : public GaussPointSolid<3, 6, LinearTetrahedron> {
 public:
  static constexpr int kNodes = 4;
  static constexpr int kDofs = 12;

  FourNodeTetrahedron(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                      const Vector3& bodyForce);

  std::string className() const override { return "FourNodeTetrahedron"; }

 protected:
  void formStrainDisplacement(int g, StrainDisplacement& B) const override;
};

}  // namespace beamsolid
