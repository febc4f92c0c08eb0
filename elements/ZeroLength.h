#pragma once
#include <memory>
#include <vector>

#include "elements/Element.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// element('zeroLength', tag, i, j, '-mat', *matTags, '-dir', *dirs,
//         <'-doRayleigh', r>, <'-orient', x1, x2, x3, yp1, yp2, yp3>):
// uncoupled uniaxial springs between two nodes, in 1D, 2D and 3D models.
// Direction 1-3 is a translation along local x, y, z, 4-6 a rotation about
// them; a spring sees the components of its axis in the model's space:
//   3D: nodes of ndf 3 or 6, rotations (4-6) need ndf 6 at both nodes;
//   2D: nodes of ndf 2 or 3, directions 1, 2 translations, 3 (or 6) the
//       in-plane rotation (ndf 3 at both nodes), as OpenSees;
//   1D: nodes of ndf 1, direction 1.
// Local axes: x from -orient, z = x cross yp, y = z cross x; global axes by
// default. In 1D and 2D OpenSees ignores the given yp and takes
// yp = (-x2, x1, 0), so y stays in the plane; we do the same.
// A spring's deformation is the local component of (u_j - u_i); its force
// pushes node j along +axis and node i along -axis.
class ZeroLength : public Element {
 public:
  static constexpr int kMaxDofs = 12;
  using ForceVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDofs, 1>;
  using StiffnessMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDofs, kMaxDofs>;

  // `directions` are 1-based as in the command; `localAxes` rows are x, y, z.
  ZeroLength(int tag, int iNode, int jNode, const std::vector<const UniaxialMaterial*>& materials,
             const std::vector<int>& directions, const Matrix3& localAxes, bool doRayleigh);

  std::string className() const override { return "zeroLength"; }
  bool hasConstantTangent() const override {
    for (const auto& s : springs_)
      if (!s.material->isLinear()) return false;
    return true;
  }
  bool supportsSpace(int ndm) const override { return ndm >= 1 && ndm <= 3; }

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 'force'/'globalForce' (numDOF), 'basicForce'/'localForce' (one per spring),
  // 'deformation'/'deformations'/'basicDeformation' (one per spring),
  // 'basicStiffness' (n x n, row by row), 'xaxis'/'yaxis'/'zaxis' (local axes),
  // 'material' k ... forwarded to spring k (1-based).
  Response setResponse(const std::vector<std::string>& args) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;

  void print(std::ostream& os) const override;

  const Matrix3& localAxes() const { return localAxes_; }
  int numSprings() const { return static_cast<int>(springs_.size()); }
  const UniaxialMaterial& material(int k) const { return *springs_[k].material; }
  bool doRayleigh() const { return doRayleigh_; }
  bool doesRayleighDamping() const override { return doRayleigh_; }
  bool hasDampingTangent() const override { return true; }
  Matrix dampingTangent() override;
  // Builds the local axes from -orient vectors; throws (naming `context`) if
  // x is zero or parallel to yp.
  // In a model of ndm < 3, yp is replaced by (-x2, x1, 0) (see above).
  static Matrix3 axesFromOrientation(const Vector3& x, const Vector3& yp, const std::string& context, int ndm = 3);

 protected:
  void setDomain(Domain& domain) override;

 private:
  struct Spring {
    std::unique_ptr<UniaxialMaterial> material;
    int direction;  // 1..6 as given
    // deformation = gradient . element displacement vector
    ForceVector gradient;
  };
  void formStiffness(bool initial);
  Vector springForces() const;
  Vector springDeformations() const;

  std::vector<Spring> springs_;
  Matrix3 localAxes_;
  bool doRayleigh_;

  ForceVector displacement_, velocity_;
  ForceVector force_;
  StiffnessMatrix stiffness_;
};

}  // namespace beamsolid
