#pragma once
#include <array>
#include <memory>

#include "elements/Element.h"
#include "materials/nd/NDMaterial.h"

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
// step, independent of load patterns: resistingForce = internal force -
// integral(N^T b dV).
//
// eleLoad '-selfWeight' (fx, fy, fz) does what it does in OpenSees (checked
// against OpenSeesPy 3.7.1): while such loads are active, the body force is
// sum over them of factor * (fx b1, fy b2, fz b3) and b itself no longer acts.
// The values scale the element's own b, component by component; the density
// plays no part. So element(..., b1, b2, b3) plus eleLoad '-selfWeight' 1 1 1
// in a Linear pattern ramps the self weight up with the load factor.
class StdBrick : public Element {
 public:
  static constexpr int kNodes = 8;
  static constexpr int kDofs = 24;
  static constexpr int kGaussPoints = 8;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Vector24 = Eigen::Matrix<double, kDofs, 1>;
  using Matrix24 = Eigen::Matrix<double, kDofs, kDofs>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Matrix6x24 = Eigen::Matrix<double, 6, kDofs>;
  // Shape function derivatives with respect to x, y, z at one Gauss point.
  using ShapeGradients = Eigen::Matrix<double, kNodes, 3>;

  // `material` is the prototype the element copies once per Gauss point.
  StdBrick(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const Vector3& bodyForce);

  std::string className() const override { return "stdBrick"; }
  bool hasConstantTangent() const override {
    for (const auto& m : materials_)
      if (!m->isLinear()) return false;
    return true;
  }

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

  // 'stresses'/'stress', 'strains'/'strain' (8 Gauss points x 6, OpenSees' point
  // order: xi slowest, zeta fastest),
  // 'force'/'forces'/'globalForce' (24), 'material' i ... (i = 1..8),
  // 'plasticStrains' (8 x 6) and 'equivalentPlasticStrains' (8) when the
  // material has a plastic state (ours).
  Response setResponse(const std::vector<std::string>& args) override;
  // Forwarded to every Gauss point material; true when any accepted it.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void updateMaterialStage(int materialTag, int stage) override;
  void initialStateAnalysis(bool on) override;

  void print(std::ostream& os) const override;

  const NDMaterial& material(int gaussPoint) const { return *materials_[gaussPoint]; }
  const Vector3& bodyForce() const { return bodyForce_; }
  // Volume of the element (sum of the Gauss weights times det J).
  double volume() const;
  // Gauss point coordinates in the reference configuration.
  Vector3 gaussPointCoordinates(int gaussPoint) const;

 protected:
  void setDomain(Domain& domain) override;

 private:
  void formStrainDisplacement(int gaussPoint, Matrix6x24& B) const;
  void formStiffness(bool initial, Matrix24& K) const;
  Vector stressesAsVector() const;
  Vector strainsAsVector() const;

  std::array<std::unique_ptr<NDMaterial>, kGaussPoints> materials_;
  Vector3 bodyForce_;
  // Body force from the active -selfWeight loads, sum of factor * (f .* b),
  // which replaces bodyForce_ while any such load is active.
  Vector3 loadedBodyForce_ = Vector3::Zero();
  bool bodyForceFromLoads_ = false;

  // Reference geometry, fixed once the nodes are known.
  std::array<ShapeGradients, kGaussPoints> gradients_;
  std::array<double, kGaussPoints> weightedDetJ_{};
  // integral of N_a dV: each node's share of the volume (body forces, lumped mass).
  Eigen::Matrix<double, kNodes, 1> nodalVolume_ = Eigen::Matrix<double, kNodes, 1>::Zero();

  Vector24 displacement_ = Vector24::Zero();
  Matrix24 stiffness_ = Matrix24::Zero();
  // The tangent of a linear material, kept (invalidated by anything that may change it).
  Matrix24 constantTangent_ = Matrix24::Zero();
  bool constantTangentValid_ = false;
  Matrix24 mass_ = Matrix24::Zero();
  Vector24 force_ = Vector24::Zero();
};

}  // namespace beamsolid
