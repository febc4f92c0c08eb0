#pragma once
#include "elements/StdBrick.h"

namespace beamsolid {

// element('bbarBrick', tag, n1, ..., n8, matTag, <b1, b2, b3>): the 8-node
// brick with Hughes' (1980) B-bar: at each of the 2x2x2 Gauss points the
// volumetric strain is replaced by its mean over the element,
//   B-bar = B + (1/3) m (b-bar - b)^T per node,  m = [1 1 1 0 0 0],
// with b-bar_a = (1/V) integral(grad N_a dV) (docs/solid_elements.md). The
// deviatoric strain stays that of the trilinear field, so the element does
// not lock when the material flow is isochoric (J2, undrained clay, nu ->
// 1/2). Everything else is stdBrick's: node order, body forces and
// '-selfWeight', consistent mass, responses (8 Gauss points); all checked
// against OpenSeesPy 3.7.1's bbarBrick (stiffness and mass to round-off).
class BbarBrick : public StdBrick {
 public:
  BbarBrick(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const Vector3& bodyForce)
      : StdBrick(tag, nodeTags, material, bodyForce) {}

  std::string className() const override { return "bbarBrick"; }

 protected:
  void formStrainDisplacement(int g, StrainDisplacement& B) const override;
};

}  // namespace beamsolid
