#pragma once
#include "elements/GaussPointSolid.h"

namespace beamsolid {

// element('quad', tag, n1, n2, n3, n4, thick, type, matTag, <pressure, rho,
// b1, b2>) in a 2D model (nodes with ndf 2): the 4-node bilinear
// isoparametric quadrilateral, small strain, 2x2 Gauss integration, one copy
// of the ND material in its `type` form ('PlaneStrain' or 'PlaneStress')
// per Gauss point. Nodes counterclockwise. Strain [e11, e22, g12], stress
// [s11, s22, s12].
//
// Loads as OpenSees applies them (checked against OpenSeesPy 3.7.1):
// - b1, b2 are force per unit volume (not multiplied by rho), integrated
//   over thick * area; pressure p gives each edge i -> j the force
//   p * (dy, -dx) (outward for counterclockwise nodes; the edge length times
//   p, not times thick), half to each end node, on the reference geometry.
//   Both act in full at every step, independent of load patterns.
// - eleLoad '-selfWeight' (fx, fy): while such loads are active the body
//   force is sum over them of factor * (fx b1, fy b2) and b itself no longer
//   acts (as StdBrick). The pressure keeps acting.
// - Mass: lumped, rho * thick * integral(N_a dA) on both dofs of node a,
//   with rho the element's, or the material's density when that is 0.
class FourNodeQuad : public GaussPointSolid<2, 3> {
 public:
  static constexpr int kNodes = 4;
  static constexpr int kDofs = 8;
  using Vector8 = NodalVector;

  struct Properties {
    double thickness = 1.0;
    std::string type = "PlaneStrain";  // the material kind: "PlaneStrain" | "PlaneStress"
    double pressure = 0.0;
    double rho = 0.0;
    Eigen::Vector2d bodyForce = Eigen::Vector2d::Zero();
  };

  FourNodeQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
               const Properties& properties);

  std::string className() const override { return "quad"; }

  const Properties& properties() const { return properties_; }
  double area() const { return volume(); }
  // Mass density in use: the element's rho, else the material's.
  double density() const override;
  // Body force and pressure: the nodal forces resistingForce() subtracts.
  NodalVector appliedLoad() const override;

 protected:
  void prepare() override;
  void formStrainDisplacement(int g, StrainDisplacement& B) const override;
  MassKind massKind() const override { return MassKind::RowSum; }

 private:
  Properties properties_;
  NodalVector pressureLoad_ = NodalVector::Zero();
};

}  // namespace beamsolid
