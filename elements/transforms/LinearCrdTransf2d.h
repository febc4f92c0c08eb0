#pragma once
#include "elements/transforms/CrdTransf2d.h"

namespace beamsolid {

// Small-displacement transformation of a 2D beam, with optional rigid joint
// offsets (global dX, dY): an end sits at node + offset and moves with the
// node as a rigid arm (u_end = u + theta Z x offset). Built by
// geomTransf('Linear', tag, <'-jntOffset', dXi, dYi, dXj, dYj>) in a 2D model.
class LinearCrdTransf2d : public CrdTransf2d {
 public:
  LinearCrdTransf2d(int tag, const Eigen::Vector2d& jointOffsetI, const Eigen::Vector2d& jointOffsetJ);

  std::string className() const override { return "Linear"; }

  void initialize(const Node& nodeI, const Node& nodeJ) override;
  void update() override;
  void revertToStart() override;

  double initialLength() const override { return length_; }
  Eigen::Vector2d axis() const override { return axis_; }

  Vector3 basicTrialDisp() const override { return basicTrial_; }
  Vector6 globalResistingForce(const Vector3& q, const Vector6& p0) const override;
  Matrix6 globalStiffMatrix(const Matrix3& kb, const Vector3& q) const override;
  Matrix6 initialGlobalStiffMatrix(const Matrix3& kb) const override;
  Vector6 localResistingForce(const Vector3& q, const Vector6& p0) const override;
  const Matrix6& localFromGlobal() const override { return localFromGlobal_; }

 protected:
  std::string context() const;
  const Vector6& localTrialDisp() const { return localTrial_; }

 private:
  Eigen::Vector2d offsetI_, offsetJ_;
  const Node* nodeI_ = nullptr;  // not owned: the element's end nodes
  const Node* nodeJ_ = nullptr;

  double length_ = 0.0;
  Eigen::Vector2d axis_ = Eigen::Vector2d::UnitX();
  Matrix6 localFromGlobal_ = Matrix6::Zero();
  Eigen::Matrix<double, 3, 6> basicFromGlobal_ = Eigen::Matrix<double, 3, 6>::Zero();
  Vector6 localTrial_ = Vector6::Zero();
  Vector3 basicTrial_ = Vector3::Zero();
};

}  // namespace beamsolid
