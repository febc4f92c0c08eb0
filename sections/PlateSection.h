#pragma once
#include <Eigen/Dense>
#include <memory>

#include "sections/BeamSection.h"

namespace beamsolid {

// A shell (plate and membrane) section: generalized strains in, stress
// resultants per unit length and their tangent out, in OpenSees' order
//   e = [eps11, eps22, gamma12, kappa11, kappa22, kappa12, gamma13, gamma23]
//   s = [p11, p22, p12, m11, m22, m12, q1, q2]
// (membrane forces, moments, transverse shears). Shell elements own copies,
// one per integration point.
class PlateSection : public BeamSection {
 public:
  static constexpr int kOrder = 8;
  using Vector8 = Eigen::Matrix<double, 8, 1>;
  using Matrix8 = Eigen::Matrix<double, 8, 8>;

  explicit PlateSection(int tag) : BeamSection(tag) {}

  int ndm() const final { return 3; }
  virtual std::unique_ptr<PlateSection> clone() const = 0;
  std::unique_ptr<BeamSection> cloneSection() const final { return clone(); }
  // `section` as a plate section; an OpenSeesError naming `context` otherwise.
  static const PlateSection& of(const BeamSection& section, const std::string& context);

  virtual void setTrialDeformation(const Vector8& e) = 0;
  virtual const Vector8& deformation() const = 0;
  virtual const Vector8& force() const = 0;
  virtual const Matrix8& tangent() const = 0;
  virtual const Matrix8& initialTangent() const = 0;
  // Mass per unit area (rho h).
  virtual double areaDensity() const = 0;

  // 'force'/'forces', 'deformation'/'deformations' (8 each).
  Response setResponse(const std::vector<std::string>& args) override;
  // The deformations as OpenSees reports them: its curvatures have the
  // opposite sign to the kappa above while its moments have the same
  // (checked against OpenSeesPy 3.7.1's ShellMITC4 'strains').
  Vector8 reportedDeformation() const;

  static const char* const* forceNames();
  static const char* const* deformationNames();
};

}  // namespace beamsolid
