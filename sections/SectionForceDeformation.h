#pragma once
#include <Eigen/Dense>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "sections/BeamSection.h"
#include "sections/SectionCode.h"

namespace beamsolid {

// A 3D beam section: section deformations in, stress resultants and their
// tangent out, with trial and committed state. Beam elements own copies
// (clone()), one per integration point.
//
// Order of the resultants (OpenSees' 3D order):
//   e = [eps, kappaZ, kappaY, theta]   axial strain of the reference axis
//                                      (y = z = 0), curvatures, twist rate
//   s = [P, Mz, My, T]                 axial force (tension +), moments, torque
// A fiber at (y, z) strains by eps - y*kappaZ + z*kappaY, and
// Mz = -integral(sigma*y dA), My = integral(sigma*z dA), so a linear section
// has ks = diag(EA, EIz, EIy, GJ) when y = z = 0 is the centroid.
class SectionForceDeformation : public BeamSection {
 public:
  static constexpr int kOrder = 4;
  using Vector4 = Eigen::Matrix<double, 4, 1>;
  using Matrix4 = Eigen::Matrix<double, 4, 4>;

  explicit SectionForceDeformation(int tag) : BeamSection(tag) {}

  int ndm() const final { return 3; }
  virtual std::unique_ptr<SectionForceDeformation> clone() const = 0;
  std::unique_ptr<BeamSection> cloneSection() const final { return clone(); }
  // `section` as a 3D section; an OpenSeesError naming `context` for a 2D one.
  static const SectionForceDeformation& of(const BeamSection& section, const std::string& context);

  virtual void setTrialDeformation(const Vector4& e) = 0;
  virtual const Vector4& deformation() const = 0;
  virtual const Vector4& force() const = 0;
  virtual const Matrix4& tangent() const = 0;
  virtual const Matrix4& initialTangent() const = 0;

  // Shear-deformable sections (section('Elastic', ..., alphaY, alphaZ), an
  // Aggregator with Vy/Vz) carry up to two shear components besides
  // [P, Mz, My, T]: shear strains gammaY/gammaZ in, Vy/Vz out. Each is
  // uncoupled from the other components and from the other shear (true of
  // both sections), so its tangent is one number. The 4-component interface
  // above leaves the shear state as it is: an element that does not model
  // shear (dispBeamColumn, as OpenSees') leaves it unstrained. All other
  // sections keep the defaults: no shear, nothing to pay.
  static constexpr int kMaxShear = 2;
  using ShearVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxShear, 1>;
  virtual int numShear() const { return 0; }
  // Vy or Vz, for k < numShear().
  virtual SectionCode shearCode(int k) const;
  virtual void setTrialShear(const ShearVector& gamma);
  virtual ShearVector shearDeformation() const { return {}; }
  virtual ShearVector shearForce() const { return {}; }
  // d(V_k)/d(gamma_k), current and initial.
  virtual ShearVector shearTangent() const { return {}; }
  virtual ShearVector shearInitialTangent() const { return {}; }
  // All components in the order OpenSees reports them (the section's
  // responses): by default [P, Mz, My, T] then the shear codes in order.
  virtual std::vector<SectionCode> responseCodes() const;
  // Deformations, forces and tangent of all components in responseCodes()
  // order (for elements that take the section's own order, zeroLengthSection).
  Vector responseDeformation() const { return responseValues(false); }
  Vector responseForce() const { return responseValues(true); }
  Matrix responseTangent(bool initial) const;
  void setTrialResponseDeformation(const Vector& e);

  // 'force'/'forces' (P, Mz, My, T, then any shear in responseCodes() order),
  // 'deformation'/'deformations', 'forceAndDeformation', 'stiffness'
  // (order x order, row by row); an empty Response when the arguments name
  // nothing this section has.
  Response setResponse(const std::vector<std::string>& args) override;

 private:
  // Forces (or deformations) in responseCodes() order.
  Vector responseValues(bool forces) const;
  // Where each of responseCodes() is in [P, Mz, My, T, shear 0, shear 1].
  std::vector<int> responsePositions() const;
};

}  // namespace beamsolid
