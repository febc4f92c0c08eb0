#pragma once
#include "elements/GaussPointSolid.h"

namespace beamsolid {

// element('bbarQuad', tag, n1, n2, n3, n4, thick, matTag) in a 2D model:
// OpenSees' mixed volume/pressure quadrilateral for plane strain (its class
// ConstantPressureVolumeQuad): the 2x2 Gauss quad with Hughes' B-bar, the
// dilatation at each Gauss point replaced by its mean over the element. As
// in OpenSees (Hughes, The FEM, 4.5.2) the strain keeps its out-of-plane
// component: strain [e11, e22, e33, g12] with
//   B-bar = B + (1/3) [1 1 1 0]^T (b-bar - b)^T per node,
// so e33 = (mean dilatation - dilatation) / 3 and the dilatation of the
// three normal strains is the mean one. Each Gauss point holds the
// material's ThreeDimensional form with e23 = e13 = 0 (what OpenSees'
// "AxiSymmetric" form of a material is); the responses give its [11 22 33
// 12] components, as OpenSees. Mass consistent, rho of the material.
// Stiffness and mass agree with OpenSeesPy 3.7.1 to round-off. OpenSees
// takes no body forces here (and ignores extra numbers; BeamSolid refuses
// them); eleLoad '-selfWeight' has nothing to scale.
// Responses: 'forces' (8), 'stresses'/'strains' (4 Gauss points x [11 22
// 33 12]; OpenSees 3.7.1 writes s33 in place of s12 there, a slip we do not
// copy), 'material' k 'stress'/'strain' (4), other 'material' k ... of the
// 3D material, 'plasticStrains' (4 x 6).
class BbarQuad : public GaussPointSolid<2, 6> {
 public:
  static constexpr int kNodes = 4;

  BbarQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, double thickness);

  std::string className() const override { return "bbarQuad"; }
  Response setResponse(const std::vector<std::string>& args) override;

 protected:
  void formStrainDisplacement(int g, StrainDisplacement& B) const override;
};

}  // namespace beamsolid
