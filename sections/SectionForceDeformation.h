#pragma once
#include <Eigen/Dense>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "sections/BeamSection.h"

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

  // 'force'/'forces' (P, Mz, My, T), 'deformation'/'deformations',
  // 'forceAndDeformation', 'stiffness' (16, row by row); an empty Response
  // when the arguments name nothing this section has.
  Response setResponse(const std::vector<std::string>& args) override;
};

}  // namespace beamsolid
