#pragma once
#include <memory>

#include "elements/BeamFixedEndForces.h"
#include "elements/Element.h"
#include "elements/transforms/CrdTransf.h"

namespace beamsolid {

// Linear elastic 3D Euler-Bernoulli beam-column (elasticBeamColumn, 3D form):
//   element('elasticBeamColumn', tag, iNode, jNode, A, E, G, J, Iy, Iz,
//           transfTag, <'-mass', massPerLength>, <'-cMass'>, <'-releasez', code>,
//           <'-releasey', code>)
// Basic stiffness EA/L, 4EI/L 2EI/L in both planes, GJ/L in the basic system
// of CrdTransf.h; the transformation (Linear, PDelta, ...) does the rest.
// Element loads (-beamUniform, -beamPoint) enter as fixed-end forces, so
// resistingForce = K u - (equivalent nodal loads), as in OpenSees.
// '-releasez'/'-releasey' 1 (I), 2 (J), 3 (both) release the moments about
// local z/y (BeamRelease.h).
class ElasticBeam3d : public Element {
 public:
  using Vector6 = CrdTransf::Vector6;
  using Vector12 = CrdTransf::Vector12;
  using Matrix6 = CrdTransf::Matrix6;
  using Matrix12 = CrdTransf::Matrix12;

  struct Properties {
    double A = 0.0, E = 0.0, G = 0.0, J = 0.0, Iy = 0.0, Iz = 0.0;
    double Avy = 0.0, Avz = 0.0;  // > 0: shear deformation too (ElasticTimoshenkoBeam)
    bool torsionalInertia = true;  // m J / A about the axis (none in OpenSees' Timoshenko beam's lumped mass)
    double massPerLength = 0.0;
    bool consistentMass = false;
    int releaseZ = 0, releaseY = 0;  // 0 none, 1 moment released at I, 2 at J, 3 both
  };

  ElasticBeam3d(int tag, int nodeI, int nodeJ, const Properties& properties, std::unique_ptr<CrdTransf> transf);

  std::string className() const override { return "elasticBeamColumn"; }
  bool hasConstantTangent() const override { return transf_->className() == "Linear"; }

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
  bool acceptsLoad(ElementLoad::Type type) const override;

  // 'force'/'globalForce' (12), 'localForce' (12), 'basicForce' (6),
  // 'basicDeformation'/'deformation' (6), 'basicStiffness' (36, row by row),
  // 'xaxis'/'yaxis'/'zaxis' (also 'xlocal', ...: local axes, 3 each).
  Response setResponse(const std::vector<std::string>& args) override;

  void print(std::ostream& os) const override;
  void printJSON(std::ostream& os) const override;

  const Properties& properties() const { return properties_; }
  const CrdTransf& transformation() const { return *transf_; }
  double length() const { return length_; }

  // Basic forces q = kb v + q0 of the current trial state.
  Vector6 basicForce() const;
  // Local end forces (12) in the local axes, from the basic forces and the
  // element loads alone: end shears (Mi + Mj)/L. As in OpenSees'
  // 'localForce', a PDelta transformation's chord shear N*dv/L is left out
  // (it is in the global 'force').
  Vector12 localForce() const;

 protected:
  void setDomain(Domain& domain) override;

 private:
  void formMass();
  // Adds the fixed-end forces of loads in the x-y and x-z planes.
  void addPlaneLoads(const BeamFixedEndForces& xy, const BeamFixedEndForces& xz);

  Properties properties_;
  std::unique_ptr<CrdTransf> transf_;
  double length_ = 0.0;

  Matrix6 kb_ = Matrix6::Zero();
  // Fixed-end forces of element loads: q0 in the basic system, p0 the
  // basic system's reactions (local, see CrdTransf.h).
  Vector6 q0_ = Vector6::Zero();
  Vector12 p0_ = Vector12::Zero();

  Matrix12 stiff_ = Matrix12::Zero();
  Matrix12 initialStiff_ = Matrix12::Zero();
  Vector12 force_ = Vector12::Zero();
  Matrix12 mass_ = Matrix12::Zero();
};

}  // namespace beamsolid
