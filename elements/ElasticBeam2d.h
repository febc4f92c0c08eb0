#pragma once
#include <memory>

#include "elements/BeamFixedEndForces.h"
#include "elements/Element.h"
#include "elements/transforms/CrdTransf2d.h"

namespace beamsolid {

class CommandArgs;

// Linear elastic 2D Euler-Bernoulli beam-column (elasticBeamColumn in a
// model with -ndm 2, nodes with ndf 3):
//   element('elasticBeamColumn', tag, iNode, jNode, A, E, Iz, transfTag,
//           <'-mass', massPerLength>, <'-cMass'>, <'-release', code>)
// or with secTag (an Elastic section: E, A, Iz) in place of A, E, Iz.
// Basic stiffness EA/L and 4EI/L, 2EI/L in the basic system of CrdTransf2d;
// '-release' 1 (I), 2 (J) or 3 (both) condenses the end moments out (a
// hinge). Element loads enter as fixed-end forces, as in ElasticBeam3d.
class ElasticBeam2d : public Element {
 public:
  using Vector3 = CrdTransf2d::Vector3;
  using Vector6 = CrdTransf2d::Vector6;
  using Matrix3 = CrdTransf2d::Matrix3;
  using Matrix6 = CrdTransf2d::Matrix6;

  struct Properties {
    double A = 0.0, E = 0.0, Iz = 0.0;
    double G = 0.0, Avy = 0.0;  // Avy > 0: shear deformation too (ElasticTimoshenkoBeam)
    double massPerLength = 0.0;
    bool consistentMass = false;
    int release = 0;  // 0 none, 1 moment released at I, 2 at J, 3 both
  };

  ElasticBeam2d(int tag, int nodeI, int nodeJ, const Properties& properties, std::unique_ptr<CrdTransf2d> transf);

  // Reads A, E, Iz, transfTag and the options (after the nodes).
  static std::unique_ptr<Element> build(CommandArgs& args, Domain& domain, int tag, int nodeI, int nodeJ);

  std::string className() const override { return "elasticBeamColumn"; }
  bool hasConstantTangent() const override { return transf_->className() == "Linear"; }
  // Every 2D transformation is stateless: no history with any of them.
  bool hasHistory() const override { return false; }
  bool supportsSpace(int ndm) const override { return ndm == 2; }

  void update() override { transf_->update(); }
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;
  void revertToStart() override { transf_->revertToStart(); }

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;
  bool acceptsLoad(ElementLoad::Type type) const override;

  // 'force'/'globalForce' (6), 'localForce' (6), 'basicForce' (3),
  // 'basicDeformation' (3), 'basicStiffness' (9, row by row), 'xaxis',
  // 'yaxis', 'zaxis' (3 each; also 'xlocal', ...).
  Response setResponse(const std::vector<std::string>& args) override;

  void print(std::ostream& os) const override;

  const Properties& properties() const { return properties_; }
  double length() const { return length_; }
  // q = kb v + q0 of the trial state.
  Vector3 basicForce() const { return kb_ * transf_->basicTrialDisp() + q0_; }
  // Local end forces from the basic forces and element loads alone (no
  // PDelta chord shear, as OpenSees' 'localForce').
  Vector6 localForce() const { return CrdTransf2d::basicToLocal(basicForce(), p0_, length_); }

 protected:
  void setDomain(Domain& domain) override;

 private:
  void addFixedEndForces(const BeamFixedEndForces& f);

  Properties properties_;
  std::unique_ptr<CrdTransf2d> transf_;
  double length_ = 0.0;

  Matrix3 kb_ = Matrix3::Zero();
  Vector3 q0_ = Vector3::Zero();
  Vector6 p0_ = Vector6::Zero();
  Matrix6 stiff_ = Matrix6::Zero();
  Matrix6 initialStiff_ = Matrix6::Zero();
  Vector6 force_ = Vector6::Zero();
  Matrix6 mass_ = Matrix6::Zero();
};

}  // namespace beamsolid
