#pragma once
#include <memory>
#include <vector>

#include "elements/BeamColumnCommand.h"
#include "elements/Element.h"
#include "elements/transforms/CrdTransf2d.h"
#include "sections/BeamIntegration.h"
#include "sections/SectionForceDeformation2d.h"

namespace beamsolid {

class CommandArgs;

// What the 2D distributed-plasticity beam-columns (dispBeamColumn,
// forceBeamColumn in a model with -ndm 2, nodes with ndf 3) share: a 2D
// geometric transformation (CrdTransf2d only, so any planar transformation
// plugs in), a copy of a 2D section at every integration point, the basic
// system v = [eps L, theta_i, theta_j], q = [N, M_i, M_j], lumped or
// consistent mass, element loads and responses. Subclasses compute q and kb
// in update().
class SectionBeamColumn2d : public Element {
 public:
  using Vector3 = CrdTransf2d::Vector3;
  using Vector6 = CrdTransf2d::Vector6;
  using Matrix3 = CrdTransf2d::Matrix3;
  using Matrix6 = CrdTransf2d::Matrix6;
  using SectionVector = SectionForceDeformation2d::Vector;
  using SectionMatrix = SectionForceDeformation2d::Matrix;
  // Maps the basic forces (or deformations) to one section's components.
  using Interpolation = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, SectionForceDeformation2d::kMaxOrder, 3>;
  using Sections = std::vector<std::unique_ptr<SectionForceDeformation2d>>;
  using Options = BeamColumnOptions;

  struct Definition {
    int tag = 0, nodeI = 0, nodeJ = 0;
    std::unique_ptr<CrdTransf2d> transf;
    std::shared_ptr<const BeamIntegration> integration;
    Sections sections;
    Options options;
  };
  // The arguments of BeamColumnCommand, then 2D sections and a 2D transformation.
  static Definition parse(CommandArgs& args, Domain& domain, const std::string& type,
                          BeamIntegration::Rule defaultRule, bool forceBased);

  SectionBeamColumn2d(int tag, Definition&& definition);

  bool supportsSpace(int ndm) const override { return ndm == 2; }

  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  bool acceptsLoad(ElementLoad::Type type) const override;

  // 'force'/'globalForce' (6), 'localForce' (6: N, V, M at I then J),
  // 'basicForce' (3), 'basicDeformation' (3), 'plasticDeformation' (3),
  // 'basicStiffness' (9, row by row), 'integrationPoints' and
  // 'integrationWeights' (x and w*L), 'section', i (1-based), *args.
  Response setResponse(const std::vector<std::string>& args) override;

  void print(std::ostream& os) const override;
  void printJSON(std::ostream& os) const override;

  // updateParameter: the sections' (and their materials') parameters.
  bool setParameter(const std::vector<std::string>& args, double value) override;

  double length() const { return length_; }
  const CrdTransf2d& transformation() const { return *transf_; }
  int numSections() const { return static_cast<int>(sections_.size()); }
  const SectionForceDeformation2d& section(int i) const { return *sections_.at(i); }
  const std::vector<double>& sectionLocations() const { return xi_; }
  const std::vector<double>& sectionWeights() const { return weights_; }

  // Basic forces, including the fixed-end forces of element loads.
  virtual Vector3 basicForce() = 0;
  virtual const Matrix3& basicStiffness() = 0;
  const Matrix3& initialBasicStiffness() const { return initialBasicStiffness_; }
  Vector3 basicDeformation() const { return transf_->basicTrialDisp(); }
  // v - kb0^-1 q: basic deformations beyond the initial (elastic) response.
  virtual Vector3 plasticDeformation();
  // Local end forces A^T q + p0 (no P-Delta chord shear, as OpenSees' 'localForce').
  Vector6 localForce() { return CrdTransf2d::basicToLocal(basicForce(), p0_, length_); }

 protected:
  void setDomain(Domain& domain) override;
  virtual void initializeState() = 0;
  const Options& options() const { return options_; }

  // An element load scaled by its factor (2D: wy, wx or py, px at x = a).
  struct BeamLoad {
    bool uniform = true;
    double wy = 0.0, wx = 0.0;
    double py = 0.0, px = 0.0, a = 0.0;
  };
  BeamLoad readLoad(const ElementLoad& load, double factor) const;
  // Adds the basic system's reactions to the load (p0 of CrdTransf2d.h).
  void addLoadReactions(const BeamLoad& load);
  void zeroLoadReactions() { p0_.setZero(); }

  std::unique_ptr<CrdTransf2d> transf_;
  std::shared_ptr<const BeamIntegration> integration_;
  Sections sections_;
  std::vector<double> xi_, weights_;
  double length_ = 0.0;
  Matrix3 initialBasicStiffness_ = Matrix3::Identity();
  Vector6 p0_ = Vector6::Zero();

 private:
  Options options_;
  Matrix6 stiff_ = Matrix6::Zero();
  Matrix6 initialStiff_ = Matrix6::Zero();
  Vector6 force_ = Vector6::Zero();
  Matrix6 mass_ = Matrix6::Zero();
};

}  // namespace beamsolid
