#pragma once
#include <Eigen/Geometry>

#include "elements/transforms/CrdTransf.h"

namespace beamsolid {

// Corotational transformation of a 3D beam for large displacements and
// rotations (geomTransf('Corotational', tag, vecxzX, vecxzY, vecxzZ,
// <'-jntOffset', dXi, dYi, dZi, dXj, dYj, dZj>)), after Crisfield (1990;
// Non-linear FE Analysis of Solids and Structures vol. 2, ch. 17) in the
// explicit form of Battini & Pacoste (2002): see docs/corotational.md.
//
// - Nodal triads R_I, R_J (rotation from the initial configuration) are
//   updated multiplicatively, R <- exp(dw) R, by the spatial rotation
//   increments dw the nodes' rotational dofs received since the previous
//   update() (OpenSees' convention: rotational dofs add up increments).
//   The trial triads are copied at commitState() and restored by
//   revertToLastCommit().
// - The corotated frame: r1 along the deformed chord, r3 = r1 x q / |r1 x q|,
//   r2 = r3 x r1, where q is the mean of the two nodal local y axes.
// - Natural deformations: chord elongation ln - L0 and the local end
//   rotations theta_k = log(R_r^T R_k E0), E0 the initial local axes, mapped
//   to the basic system [ln - L0, thz_i, thz_j, thy_i, thy_j, twist] of
//   CrdTransf.h (thz = theta_3, thy = theta_2, twist = theta_J1 - theta_I1).
// - The tangent is the exact derivative of the global resisting force with
//   respect to the nodal translations and spatial rotation increments:
//   material part B^T kb B plus the geometric part from the variation of B
//   (chord direction, corotated frame, T_s^-1 of the local rotations).
//   Fixed-end forces p0 of element loads act in the corotated frame; their
//   turning is left out of the tangent, because globalStiffMatrix() is not
//   given p0 (Newton then converges linearly in that part only).
// - Joint offsets are rigid arms given in global coordinates in the initial
//   configuration; they turn with their node's triad.
class CorotationalCrdTransf : public CrdTransf {
 public:
  using Matrix3x12 = Eigen::Matrix<double, 3, 12>;
  using Matrix6x12 = Eigen::Matrix<double, 6, 12>;

  CorotationalCrdTransf(int tag, const Vector3& vecxz, const Vector3& jointOffsetI = Vector3::Zero(),
                        const Vector3& jointOffsetJ = Vector3::Zero());

  std::string className() const override { return "Corotational"; }
  std::unique_ptr<CrdTransf> clone() const override;

  void initialize(const Node& nodeI, const Node& nodeJ) override;
  void update() override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  double initialLength() const override { return initialLength_; }
  double deformedLength() const override { return trial_.length; }
  Matrix3 localAxes() const override { return initialAxes_.transpose(); }
  Vector3 vecxz() const override { return vecxz_; }
  const Vector3& jointOffsetI() const { return offset_[0]; }
  const Vector3& jointOffsetJ() const { return offset_[1]; }

  Vector6 basicTrialDisp() const override { return trial_.basic; }
  Vector6 basicIncrDisp() const override { return trial_.basic - committed_.basic; }
  Vector6 basicIncrDeltaDisp() const override { return basicIncrDelta_; }

  Vector12 globalResistingForce(const Vector6& q, const Vector12& p0) const override;
  Matrix12 globalStiffMatrix(const Matrix6& kb, const Vector6& q) const override;
  Matrix12 initialGlobalStiffMatrix(const Matrix6& kb) const override;
  // End forces in the current corotated frame (r1, r2, r3 at each end).
  Vector12 localResistingForce(const Vector6& q, const Vector12& p0) const override;

  // Columns r1, r2, r3 of the current corotated frame, in global coordinates.
  const Matrix3& corotatedAxes() const { return trial_.frame; }
  // Trial rotation of node I (end 0) or J (end 1) since the start.
  Matrix3 nodeRotation(int end) const { return trial_.rotation[end].toRotationMatrix(); }
  // Local end rotations theta_k = log(R_r^T R_k E0) (components in r1, r2, r3).
  const Vector3& localRotation(int end) const { return trial_.theta[end]; }

  void print(std::ostream& os) const override;
  // In a 2D model: CorotationalCrdTransf2d with the offsets' x, y.
  std::unique_ptr<CrdTransf2d> planar() const override;

 private:
  // Everything that depends on the trial configuration, kept together so
  // that commit and revert copy one value.
  struct State {
    Eigen::Quaterniond rotation[2] = {Eigen::Quaterniond::Identity(), Eigen::Quaterniond::Identity()};
    // The nodes' rotational dofs as last applied to the triads.
    Vector3 appliedRotation[2] = {Vector3::Zero(), Vector3::Zero()};
    Vector3 arm[2] = {Vector3::Zero(), Vector3::Zero()};  // offsets turned with the nodes
    Matrix3 frame = Matrix3::Identity();                   // columns r1, r2, r3
    Vector3 nodalY[2] = {Vector3::Zero(), Vector3::Zero()};  // R_k e2 of the initial axes
    double length = 0.0;
    Vector3 theta[2] = {Vector3::Zero(), Vector3::Zero()};
    Matrix3 thetaRateInverse[2] = {Matrix3::Identity(), Matrix3::Identity()};  // T_s^-1(theta_k)
    Matrix3x12 frameSpin = Matrix3x12::Zero();      // d(spin of the frame) / d(end dofs)
    Matrix3x12 thetaRate[2] = {Matrix3x12::Zero(), Matrix3x12::Zero()};  // d(theta_k) / d(end dofs)
    Matrix6x12 basicFromEnd = Matrix6x12::Zero();   // d(basic) / d(end dofs)
    Vector6 basic = Vector6::Zero();
  };

  std::string context() const;
  // Frame, local rotations, basic deformations and their derivatives with
  // respect to the end dofs, from the end positions and the triads in s.
  void formGeometry(State& s, const Vector3& endI, const Vector3& endJ) const;
  // Turns the triads by the nodes' rotational dofs applied since s was
  // formed, then refreshes the geometry of s.
  void formState(State& s, const Vector& dispI, const Vector& dispJ) const;
  // End forces (translations at the offset ends, global) from q and p0.
  Vector12 endForce(const State& s, const Vector6& q, const Vector12& p0) const;
  // Moves end forces to the nodes through the rigid arms.
  Vector12 endToNode(const State& s, const Vector12& endForce) const;
  Matrix12 stiffness(const State& s, const Matrix6& kb, const Vector6& q) const;

  Vector3 vecxz_;
  Vector3 offset_[2];
  // Not owned: the element's end nodes, which outlive the element.
  const Node* node_[2] = {nullptr, nullptr};

  double initialLength_ = 0.0;
  Matrix3 initialAxes_ = Matrix3::Identity();  // columns e1, e2, e3
  State start_, trial_, committed_;
  Vector6 basicIncrDelta_ = Vector6::Zero();
};

}  // namespace beamsolid
