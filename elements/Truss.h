#pragma once
#include <memory>

#include "elements/Element.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

class CommandArgs;

// element('truss', tag, i, j, A, matTag, <'-rho', rho>, <'-cMass', 1>, <'-doRayleigh', 1>):
// a two-node bar with axial force N = A * sigma(strain). Small displacement:
// strain = e0 . (u_j - u_i) / L0 along the initial axis e0. Works in 1D, 2D
// and 3D: nodes have ndm translations (ndf 1; 2 or 3; 3 or 6) and the bar
// loads translations only (zero rows/columns for the rotations). rho is mass per unit length: lumped rho*L/2 per translation
// by default, consistent (rho*L/6)[2 1; 1 2] with -cMass 1.
class Truss : public Element {
 public:
  // Sized to the element's dofs (6 x 6 for a 3D bar with ndf 3) rather than
  // the largest case inline: models have 10^5 bars, and 2.3 kB of storage
  // each made building them memory-bound.
  using ForceVector = Vector;
  using StiffnessMatrix = Matrix;

  // The arguments after the nodes, shared by 'truss' and 'corotTruss'.
  struct Options {
    double area = 0.0;
    int matTag = 0;
    double rho = 0.0;
    bool consistentMass = false;
    bool doRayleigh = false;
  };
  static Options readOptions(CommandArgs& args);

  Truss(int tag, int iNode, int jNode, double area, const UniaxialMaterial& material, double rho,
        bool consistentMass, bool doRayleigh);

  std::string className() const override { return "truss"; }
  bool hasConstantTangent() const override { return material_->isLinear(); }
  bool supportsSpace(int ndm) const override { return ndm >= 1 && ndm <= 3; }

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  void commitState() override { material_->commitState(); }
  void revertToLastCommit() override { material_->revertToLastCommit(); }
  void revertToStart() override { material_->revertToStart(); }

  // 'axialForce' (1), 'force'/'globalForce' (numDOF), 'localForce' (truss:
  // numDOF, local axes, only -N and +N non-zero; corotTruss: N alone),
  // 'basicStiffness' (truss: A E_t / L), 'basicDeformation'/'deformation'
  // (1: elongation), 'material' ... forwarded.
  Response setResponse(const std::vector<std::string>& args) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;

  void print(std::ostream& os) const override;

  double area() const { return area_; }
  double initialLength() const { return initialLength_; }
  double axialForce() const { return area_ * material_->stress(); }
  // Elongation used for the strain: current minus initial length (corotational),
  // or its linearization e0 . (u_j - u_i) (small displacement).
  double elongation() const { return initialLength_ * material_->strain(); }
  bool doRayleigh() const { return doRayleigh_; }
  bool doesRayleighDamping() const override { return doRayleigh_; }
  // A rate-dependent material (Viscous) damps along the bar's axis.
  bool hasDampingTangent() const override { return material_->dampingTangent() != 0.0; }
  Matrix dampingTangent() override;
  const UniaxialMaterial& material() const { return *material_; }

 protected:
  void setDomain(Domain& domain) override;
  // Corotational subclasses measure strain from the current length and add
  // the geometric stiffness.
  virtual bool largeDisplacement() const { return false; }

 private:
  // Writes [k -k; -k k] on the translations of the two nodes.
  void formStiffness(const Matrix3& k);
  // j minus i on the translations, padded to 3 with zeros.
  Vector3 relative(const Eigen::VectorXd& iValues, const Eigen::VectorXd& jValues) const;

  double area_;
  std::unique_ptr<UniaxialMaterial> material_;
  double rho_;
  bool consistentMass_;
  bool doRayleigh_;

  int dim_ = 3;      // translations per node: the nodes' ndm
  int jOffset_ = 3;  // first dof of node j (ndf of node i)
  double initialLength_ = 0.0;
  Vector3 initialAxis_ = Vector3::UnitX();
  // Axis and length the force acts along: initial ones for small displacement.
  Vector3 axis_ = Vector3::UnitX();
  double currentLength_ = 0.0;

  ForceVector force_;
  StiffnessMatrix stiffness_;
  StiffnessMatrix mass_;  // allocated by the first massMatrix()
};

}  // namespace beamsolid
