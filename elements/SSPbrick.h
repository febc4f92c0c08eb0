#pragma once
#include "elements/SinglePointSolid.h"

namespace beamsolid {

// element('SSPbrick', tag, n1, ..., n8, matTag, <b1, b2, b3>): the
// stabilized single-point hexahedron of McGann, Arduino and
// Mackenzie-Helnwein (2015), after Puso's (2000) enhanced-assumed-strain
// physical stabilization: one material point at the centre (B0 of the
// uniform gradients, V the exact volume) and a stabilization stiffness on
// the twelve hourglass coordinates q_kd = gamma_k . u_d (k = 1..4 for the
// hourglass functions eta zeta, zeta xi, xi eta, xi eta zeta):
//   K_stab = Gamma (Kqq - Kqa Kaa^-1 Kaq) Gamma^T,
// the hourglass strain field (gradient at constant centre Jacobian J0) with
// twelve enhanced strain modes condensed out, all integrated exactly over
// the cube with det J0 and the initial tangent D0. The enhanced modes,
// tensors f(xi) sym(g^m (x) g^n) in the natural contravariant basis g^m =
// grad xi_m: e_mm ~ xi_m, e_mn ~ xi_m and xi_n, e_mm ~ the product of the
// other two coordinates. They free the bending modes of parasitic shear and
// of the lateral (Poisson) constraint and the xi eta zeta modes of normal
// strain: no shear locking, no volumetric locking (bounded as nu -> 1/2).
// docs/solid_elements.md has the equations.
//
// Agreement with OpenSeesPy 3.7.1's SSPbrick: stiffness to round-off on
// axis-aligned rectangular boxes for every nu; the centre part always; on
// rotated or distorted elements the hourglass stiffness differs by about
// 1 % of max |K| (OpenSees' is itself not invariant under a rotation of the
// element, ours is); docs/solid_elements.md. Mass lumped, rho V / 8 on
// every node (OpenSees' differs from that by 1e-3 on distorted elements).
// Body forces and '-selfWeight' as stdBrick. Responses: 'stresses'/
// 'strains' (the centre point: 6 values), 'forces' (24), 'material' 1 ....
class SSPbrick : public SinglePointSolid<3, 6> {
 public:
  static constexpr int kNodes = 8;

  SSPbrick(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const Vector3& bodyForce)
      : SinglePointSolid(tag, nodeTags, material, "ThreeDimensional", 1.0, bodyForce) {}

  std::string className() const override { return "SSPbrick"; }

 protected:
  void formStabilization(const StrainMatrix& D0, NodalMatrix& K) const override;
  MassKind massKind() const override { return MassKind::Uniform; }
};

}  // namespace beamsolid
