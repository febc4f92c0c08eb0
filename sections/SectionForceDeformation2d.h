#pragma once
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "sections/BeamSection.h"
#include "sections/SectionCode.h"

namespace beamsolid {

// A section of a 2D (x-y plane) beam: deformations in, resultants and their
// tangent out, with trial and committed state. Its order is 2 ([P, Mz]) or
// 3 (an added shear Vy or an Aggregator's extra components); codes() says
// which component is which. Vectors and matrices have a fixed capacity of 3:
// no heap allocation per call.
// Signs as the 3D section: a fiber at y strains by eps - y*kappa and
// Mz = -integral(sigma*y dA).
class SectionForceDeformation2d : public BeamSection {
 public:
  static constexpr int kMaxOrder = 3;
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxOrder, 1>;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxOrder, kMaxOrder>;

  explicit SectionForceDeformation2d(int tag) : BeamSection(tag) {}

  int ndm() const final { return 2; }
  virtual std::unique_ptr<SectionForceDeformation2d> clone() const = 0;
  std::unique_ptr<BeamSection> cloneSection() const final { return clone(); }
  // `section` as a 2D section; an OpenSeesError naming `context` for a 3D one.
  static const SectionForceDeformation2d& of(const BeamSection& section, const std::string& context);

  virtual const std::vector<SectionCode>& codes() const = 0;
  int order() const { return static_cast<int>(codes().size()); }

  virtual void setTrialDeformation(const Vector& e) = 0;
  virtual const Vector& deformation() const = 0;
  virtual const Vector& force() const = 0;
  virtual const Matrix& tangent() const = 0;
  virtual const Matrix& initialTangent() const = 0;

  // 'force'/'forces', 'deformation'/'deformations', 'forceAndDeformation'
  // (deformations first), 'stiffness' (order x order, row by row), in the
  // order of codes().
  Response setResponse(const std::vector<std::string>& args) override;

  // updateParameter through an element: true when the section or one of
  // its materials took the value.
  virtual bool setParameter(const std::vector<std::string>&, double) { return false; }
  // Sensitivity (sensitivityAlgorithm). The id (> 0) of the parameter named
  // by args that the section or its materials have, 0 if none.
  virtual int sensitivityParameter(const std::vector<std::string>&) { return 0; }
  // d s / d theta at the trial deformation: through theta itself
  // (parameterId, 0 when theta is not this section's) and through the
  // committed history's sensitivities of `gradient`. Throws by default.
  virtual Vector forceSensitivity(int gradient, int parameterId);
  // Keeps the trial history's sensitivities, given d e / d theta.
  virtual void commitSensitivity(const Vector& deformationSensitivity, int gradient, int parameterId,
                                 int numGradients);
};

}  // namespace beamsolid
