#pragma once
#include "elements/SectionBeamColumn2d.h"

namespace beamsolid {

// Displacement-based 2D beam-column (dispBeamColumn in a model with -ndm 2):
// linear axial displacement and cubic Hermite bending in the basic system, so
// a section deforms by eps = v0 / L and
// kappa = ((6 xi - 4) theta_i + (6 xi - 2) theta_j) / L;
// q = sum w L B^T s, kb = sum w L B^T ks B (default rule: Legendre).
// Element loads enter as fixed-end forces of a prismatic member. A section's
// shear component (Vy) stays unstrained: Hermite bending has no shear strain.
class DispBeamColumn2d : public SectionBeamColumn2d {
 public:
  DispBeamColumn2d(int tag, Definition&& definition);
  static std::unique_ptr<Element> build(CommandArgs& args, Domain& domain);

  std::string className() const override { return "dispBeamColumn"; }

  void update() override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;

  Vector3 basicForce() override { return sectionForce_ + q0_; }
  const Matrix3& basicStiffness() override { return kb_; }

  // Sensitivity (sensitivityAlgorithm): the sections' parameters (material
  // and geometric) and the end nodes' coordinates. The sections' forces and
  // history are differentiated by the sections; what the element's geometry
  // adds (a coordinate moves the chord, so L, the transformation and every
  // section's deformation) is taken by central differences of the element
  // at the trial displacements with the history held.
  int sensitivityParameter(const std::vector<std::string>& args) override;
  Vector resistingForceSensitivity(int gradient, const SensitivityParameter& p) override;
  void commitSensitivity(int gradient, const SensitivityParameter& p, const Vector& dU, int numGradients) override;

  // Strain-displacement matrix of one section (rows follow its codes).
  static Interpolation strainDisplacement(const std::vector<SectionCode>& codes, double xi, double length);

 protected:
  void initializeState() override;

 private:
  void assemble();
  // Section deformations B v at the nodes' trial displacements.
  std::vector<SectionVector> sectionDeformations();
  // Moves coordinate `dim` of end node `node` to `value` and re-reads the geometry.
  void moveNode(int node, int dim, double value);

  // Per sensitivity parameter: its name and each section's id for it.
  struct SensitivityBinding {
    std::vector<std::string> args;
    std::vector<int> sectionIds;
  };
  std::vector<SensitivityBinding> sensitivity_;

  std::vector<Interpolation> strainDisplacement_;
  Vector3 sectionForce_ = Vector3::Zero();
  Vector3 q0_ = Vector3::Zero();
  Matrix3 kb_ = Matrix3::Zero();
};

}  // namespace beamsolid
