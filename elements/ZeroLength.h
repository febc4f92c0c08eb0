#pragma once
#include <memory>
#include <vector>

#include "elements/Element.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// element('zeroLength', tag, i, j, '-mat', *matTags, '-dir', *dirs,
//         <'-doRayleigh', r>, <'-orient', x1, x2, x3, yp1, yp2, yp3>):
// uncoupled uniaxial springs between two nodes. Direction 1-3 is a
// translation along local x, y, z, 4-6 a rotation about them (both nodes
// then need ndf 6). Local axes: x from -orient, z = x cross yp, y = z cross x;
// global axes by default. A spring's deformation is the local component of
// (u_j - u_i); its force pushes node j along +axis and node i along -axis.
class ZeroLength : public Element {
 public:
  static constexpr int kMaxDofs = 12;
  using ForceVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDofs, 1>;
  using StiffnessMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDofs, kMaxDofs>;

  // `directions` are 1-based as in the command; `localAxes` rows are x, y, z.
  ZeroLength(int tag, int iNode, int jNode, const std::vector<const UniaxialMaterial*>& materials,
             const std::vector<int>& directions, const Matrix3& localAxes, bool doRayleigh);

  std::string className() const override { return "zeroLength"; }

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
  // Builds the local axes from -orient vectors; throws (naming `context`) if
  // x is zero or parallel to yp.
  static Matrix3 axesFromOrientation(const Vector3& x, const Vector3& yp, const std::string& context);

 protected:
  void setDomain(Domain& domain) override;

 private:
  struct Spring {
    std::unique_ptr<UniaxialMaterial> material;
    int direction;  // 1..6
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
