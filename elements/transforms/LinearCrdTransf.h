#pragma once
#include "core/CommandArgs.h"
#include "elements/transforms/CrdTransf.h"

namespace beamsolid {

// Small-displacement transformation of a 3D beam, with optional rigid joint
// offsets given in global coordinates: the beam's ends sit at node + offset
// and move with the node as a rigid arm (u_end = u + theta x offset).
class LinearCrdTransf : public CrdTransf {
 public:
  LinearCrdTransf(int tag, const Vector3& vecxz, const Vector3& jointOffsetI = Vector3::Zero(),
                  const Vector3& jointOffsetJ = Vector3::Zero());

  std::string className() const override { return "Linear"; }
  std::unique_ptr<CrdTransf> clone() const override;

  void initialize(const Node& nodeI, const Node& nodeJ) override;
  void update() override;
  void revertToStart() override;

  double initialLength() const override { return length_; }
  double deformedLength() const override { return length_; }
  Matrix3 localAxes() const override { return axes_; }
  Vector3 vecxz() const override { return vecxz_; }
  const Vector3& jointOffsetI() const { return offsetI_; }
  const Vector3& jointOffsetJ() const { return offsetJ_; }

  Vector6 basicTrialDisp() const override { return basicTrial_; }
  Vector6 basicIncrDisp() const override { return basicIncr_; }
  Vector6 basicIncrDeltaDisp() const override { return basicIncrDelta_; }

  Vector12 globalResistingForce(const Vector6& q, const Vector12& p0) const override;
  Matrix12 globalStiffMatrix(const Matrix6& kb, const Vector6& q) const override;
  Matrix12 initialGlobalStiffMatrix(const Matrix6& kb) const override;
  Vector12 localResistingForce(const Vector6& q, const Vector12& p0) const override;

  void print(std::ostream& os) const override;
  std::unique_ptr<CrdTransf2d> planar() const override;

  // What geomTransf('Linear'|'PDelta', tag, vecxzX, vecxzY, vecxzZ,
  // <'-jntOffset', dXi, dYi, dZi, dXj, dYj, dZj>) defines.
  struct Definition {
    int tag = 0;
    Vector3 vecxz = Vector3::Zero();
    Vector3 jointOffsetI = Vector3::Zero();
    Vector3 jointOffsetJ = Vector3::Zero();
  };
  // Parses the arguments after the type name; sets the args' context. In a
  // 2D model: (tag, <'-jntOffset', dXi, dYi, dXj, dYj>), vecxz = Z.
  static Definition parse(CommandArgs& args, const std::string& type, int ndm = 3);

 protected:
  // "geomTransf <type> <tag>", the prefix of this transformation's messages.
  std::string context() const;
  // Local end displacements (12) of the trial state, at the offset ends.
  const Vector12& localTrialDisp() const { return localTrial_; }
  // Maps global node dofs to local end dofs: rotation and rigid offsets.
  const Matrix12& localFromGlobal() const { return localFromGlobal_; }
  // Local end forces from basic forces, A^T q + p0.
  Vector12 basicToLocal(const Vector6& q, const Vector12& p0) const;

 private:
  Vector12 globalTrialDisp() const;
  Vector12 globalCommittedDisp() const;

  Vector3 vecxz_;
  Vector3 offsetI_, offsetJ_;
  // Not owned: the element's end nodes, which outlive the element.
  const Node* nodeI_ = nullptr;
  const Node* nodeJ_ = nullptr;

  double length_ = 0.0;
  Matrix3 axes_ = Matrix3::Identity();
  Matrix12 localFromGlobal_ = Matrix12::Zero();
  // Basic deformations from global dofs: A * localFromGlobal.
  Eigen::Matrix<double, 6, 12> basicFromGlobal_ = Eigen::Matrix<double, 6, 12>::Zero();

  Vector12 localTrial_ = Vector12::Zero();
  Vector6 basicTrial_ = Vector6::Zero();
  Vector6 basicIncr_ = Vector6::Zero();
  Vector6 basicIncrDelta_ = Vector6::Zero();
};

}  // namespace beamsolid
