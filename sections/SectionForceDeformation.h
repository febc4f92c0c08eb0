#pragma once
#include <Eigen/Dense>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/Response.h"

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
class SectionForceDeformation {
 public:
  static constexpr int kOrder = 4;
  using Vector4 = Eigen::Matrix<double, 4, 1>;
  using Matrix4 = Eigen::Matrix<double, 4, 4>;

  explicit SectionForceDeformation(int tag) : tag_(tag) {}
  virtual ~SectionForceDeformation() = default;

  int tag() const { return tag_; }
  virtual std::string className() const = 0;
  virtual std::unique_ptr<SectionForceDeformation> clone() const = 0;

  virtual void setTrialDeformation(const Vector4& e) = 0;
  virtual const Vector4& deformation() const = 0;
  virtual const Vector4& force() const = 0;
  virtual const Matrix4& tangent() const = 0;
  virtual const Matrix4& initialTangent() const = 0;

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  // 'force'/'forces' (P, Mz, My, T), 'deformation'/'deformations',
  // 'forceAndDeformation', 'stiffness' (16, row by row); an empty Response
  // when the arguments name nothing this section has.
  virtual Response setResponse(const std::vector<std::string>& args);
  virtual void print(std::ostream& os) const;

  // "section <className> <tag>", the prefix of this section's messages.
  std::string context() const;

 private:
  int tag_;
};

}  // namespace beamsolid
