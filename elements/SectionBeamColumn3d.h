#pragma once
#include <memory>
#include <vector>

#include "elements/BeamColumnCommand.h"
#include "elements/Element.h"
#include "elements/transforms/CrdTransf.h"
#include "sections/BeamIntegration.h"
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

class CommandArgs;

// What the distributed-plasticity beam-columns (dispBeamColumn,
// forceBeamColumn) share: two 6-dof nodes, a geometric transformation
// (clone), a copy of a section at every integration point, the basic system
// of CrdTransf.h, lumped (or consistent) mass, element loads and responses.
// Subclasses compute the basic forces q and basic stiffness kb in update().
class SectionBeamColumn3d : public Element {
 public:
  using Vector4 = SectionForceDeformation::Vector4;
  using Matrix4 = SectionForceDeformation::Matrix4;
  using Vector6 = CrdTransf::Vector6;
  using Vector12 = CrdTransf::Vector12;
  using Matrix6 = CrdTransf::Matrix6;
  using Matrix12 = CrdTransf::Matrix12;
  using Sections = std::vector<std::unique_ptr<SectionForceDeformation>>;

  using Options = BeamColumnOptions;

  // Everything an element command defines, parsed by parse().
  struct Definition {
    int tag = 0, nodeI = 0, nodeJ = 0;
    std::unique_ptr<CrdTransf> transf;
    std::shared_ptr<const BeamIntegration> integration;
    Sections sections;
    Options options;
  };
  // Parses, after the type name,
  //   tag, iNode, jNode, transfTag, integrationTag, <options>            or
  //   tag, iNode, jNode, numIntgrPts, secTag, transfTag, <options>       (older form)
  // with options '-mass', m, '-cMass' (when allowed), '-iter', maxIter, tol
  // (when allowed) and, for the older form, '-integration', rule.
  static Definition parse(CommandArgs& args, Domain& domain, const std::string& type,
                          BeamIntegration::Rule defaultRule, bool forceBased);

  SectionBeamColumn3d(int tag, Definition&& definition);

  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  bool acceptsLoad(ElementLoad::Type type) const override;

  // 'force'/'globalForce', 'localForce', 'basicForce', 'basicDeformation',
  // 'plasticDeformation', 'basicStiffness', 'integrationPoints' and
  // 'integrationWeights' (in length units, as x and w*L), 'section', i (1-based), *args.
  Response setResponse(const std::vector<std::string>& args) override;

  void print(std::ostream& os) const override;
  void printJSON(std::ostream& os) const override;

  double length() const { return length_; }
  const CrdTransf& transformation() const { return *transf_; }
  const BeamIntegration& integration() const { return *integration_; }
  int numSections() const { return static_cast<int>(sections_.size()); }
  const SectionForceDeformation& section(int i) const { return *sections_.at(i); }
  // Locations (fractions of L) and weights (summing to 1) of the sections.
  const std::vector<double>& sectionLocations() const { return xi_; }
  const std::vector<double>& sectionWeights() const { return weights_; }

  // Basic forces, including the fixed-end forces of element loads.
  virtual Vector6 basicForce() = 0;
  virtual const Matrix6& basicStiffness() = 0;
  const Matrix6& initialBasicStiffness() const { return initialBasicStiffness_; }
  // Basic deformations of the current trial state.
  Vector6 basicDeformation() const { return transf_->basicTrialDisp(); }
  // v - kb0^-1 q: basic deformations beyond the initial (elastic) response.
  // v minus the elastic deformations of the basic forces (the force-based
  // element also removes its element loads').
  virtual Vector6 plasticDeformation();

 protected:
  void setDomain(Domain& domain) override;
  // Called once the length and the integration points are known.
  virtual void initializeState() = 0;
  const Options& options() const { return options_; }

  // An element load scaled by its factor; validated by readLoad.
  struct BeamLoad {
    bool uniform = true;
    double wy = 0.0, wz = 0.0, wx = 0.0;            // uniform
    double py = 0.0, pz = 0.0, px = 0.0, a = 0.0;   // point load at x = a
  };
  BeamLoad readLoad(const ElementLoad& load, double factor) const;
  // Adds the basic system's reactions to the load (p0 of CrdTransf.h).
  void addLoadReactions(const BeamLoad& load);
  void zeroLoadReactions() { p0_.setZero(); }

  std::unique_ptr<CrdTransf> transf_;
  std::shared_ptr<const BeamIntegration> integration_;
  Sections sections_;
  std::vector<double> xi_, weights_;
  double length_ = 0.0;
  Matrix6 initialBasicStiffness_ = Matrix6::Identity();
  Vector12 p0_ = Vector12::Zero();

 private:
  void formMass();

  Options options_;
  Matrix12 stiff_ = Matrix12::Zero();
  Matrix12 initialStiff_ = Matrix12::Zero();
  Vector12 force_ = Vector12::Zero();
  Matrix12 mass_ = Matrix12::Zero();
};

}  // namespace beamsolid
