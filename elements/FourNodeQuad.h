#pragma once
#include <array>
#include <memory>

#include "elements/Element.h"
#include "materials/nd/NDMaterial.h"

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
class FourNodeQuad : public Element {
 public:
  static constexpr int kNodes = 4;
  static constexpr int kDofs = 8;
  static constexpr int kGaussPoints = 4;
  using Vector8 = Eigen::Matrix<double, kDofs, 1>;
  using Matrix8 = Eigen::Matrix<double, kDofs, kDofs>;
  using Matrix3x8 = Eigen::Matrix<double, 3, kDofs>;
  // Shape function derivatives with respect to x, y at one Gauss point.
  using ShapeGradients = Eigen::Matrix<double, kNodes, 2>;

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
  bool hasConstantTangent() const override {
    for (const auto& m : materials_)
      if (!m->isLinear()) return false;
    return true;
  }
  bool supportsSpace(int ndm) const override { return ndm == 2; }

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;
  bool acceptsLoad(ElementLoad::Type type) const override { return type == ElementLoad::Type::SelfWeight; }

  // 'force'/'forces' (8, P1_a P2_a), 'stresses'/'stress' and
  // 'strains'/'strain' (4 Gauss points x 3), 'material'/'integrPoint' i ...
  // (i = 1..4), 'plasticStrains' (4 x 6, the 3D plastic strain) and
  // 'equivalentPlasticStrains' (4) when the material has a plastic state
  // (ours). Gauss points in OpenSees' order (counterclockwise from the one
  // nearest node 1).
  Response setResponse(const std::vector<std::string>& args) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void updateMaterialStage(int materialTag, int stage) override;
  void initialStateAnalysis(bool on) override;

  void print(std::ostream& os) const override;

  const Properties& properties() const { return properties_; }
  const NDMaterial& material(int gaussPoint) const { return *materials_[gaussPoint]; }
  double area() const;
  // Mass density in use: the element's rho, else the material's.
  double density() const;
  // Gauss point coordinates in the reference configuration.
  Eigen::Vector2d gaussPointCoordinates(int gaussPoint) const;
  // The nodal forces of the element's own loads (body force and pressure),
  // which resistingForce() subtracts.
  Vector8 appliedLoad() const;

 protected:
  void setDomain(Domain& domain) override;

 private:
  void formStrainDisplacement(int gaussPoint, Matrix3x8& B) const;
  void formStiffness(bool initial, Matrix8& K) const;
  Vector stressesAsVector() const;
  Vector strainsAsVector() const;

  Properties properties_;
  std::array<std::unique_ptr<NDMaterial>, kGaussPoints> materials_;
  // Body force from the active -selfWeight loads (see above).
  Eigen::Vector2d loadedBodyForce_ = Eigen::Vector2d::Zero();
  bool bodyForceFromLoads_ = false;

  // Reference geometry, fixed once the nodes are known.
  std::array<ShapeGradients, kGaussPoints> gradients_;
  std::array<double, kGaussPoints> weightedDetJ_{};  // thickness included
  // thick * integral(N_a dA): each node's share of the volume.
  Eigen::Matrix<double, kNodes, 1> nodalVolume_ = Eigen::Matrix<double, kNodes, 1>::Zero();
  Vector8 pressureLoad_ = Vector8::Zero();

  Vector8 displacement_ = Vector8::Zero();
  Matrix8 stiffness_ = Matrix8::Zero();
  Matrix8 mass_ = Matrix8::Zero();
  Vector8 force_ = Vector8::Zero();
};

}  // namespace beamsolid
