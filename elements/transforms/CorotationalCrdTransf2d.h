#pragma once
#include "elements/transforms/CrdTransf2d.h"

namespace beamsolid {

// Corotational transformation of a 2D beam for large displacements and
// rotations (geomTransf('Corotational', tag, <'-jntOffset', dXi, dYi, dXj,
// dYj>) in a 2D model), after Crisfield (1991, Non-linear FE Analysis of
// Solids and Structures vol. 1, sec. 7.4) and de Souza Neto et al.
//
// - The ends sit at node + arm, the arm being the joint offset turned by the
//   node's rotation (a rigid arm, exact for any rotation).
// - The chord from end I to end J (length Ln, unit r = (c, s), normal
//   z = (-s, c)) turns by beta = alpha - alpha0 from the initial chord.
// - Basic deformations v = [Ln - L0, th_i - beta, th_j - beta], the
//   rotations wrapped to (-pi, pi]: they stay small in a beam that deforms
//   little between its ends however far it turns, which keeps the
//   transformation stateless (no rotation history to commit) and exact for
//   rigid-body motion (v = 0 under any rigid rotation).
// - Global forces B^T q with B = dv/du; the tangent is the exact derivative
//   B^T kb B + N/Ln z z^T + (M_i + M_j)/Ln^2 (r z^T + z r^T) on the end
//   translations (Crisfield's geometric stiffness), plus the rigid arms' term.
//   Element loads: their basic forces q0 act through B like q, and the
//   simple-support reactions p0 go to the nodes as in the Linear
//   transformation, with the initial axes and arms (as in OpenSeesPy 3.7.1:
//   a uniform load on a horizontal cantilever stays vertical however far it
//   bends), so they add nothing to the tangent.
class CorotationalCrdTransf2d : public CrdTransf2d {
 public:
  using Vector2 = Eigen::Vector2d;

  CorotationalCrdTransf2d(int tag, const Vector2& jointOffsetI, const Vector2& jointOffsetJ);

  std::string className() const override { return "Corotational"; }

  void initialize(const Node& nodeI, const Node& nodeJ) override;
  void update() override;
  void revertToStart() override;

  double initialLength() const override { return initialLength_; }
  double deformedLength() const { return length_; }
  // The initial chord direction (the current one is chordAxis()).
  Vector2 axis() const override { return initialAxis_; }
  const Vector2& chordAxis() const { return chord_; }

  Vector3 basicTrialDisp() const override { return basic_; }
  Vector6 globalResistingForce(const Vector3& q, const Vector6& p0) const override;
  Matrix6 globalStiffMatrix(const Matrix3& kb, const Vector3& q) const override;
  Matrix6 initialGlobalStiffMatrix(const Matrix3& kb) const override;
  // End forces in the corotated frame (N, V, M at I then J) on the chord Ln.
  Vector6 localResistingForce(const Vector3& q, const Vector6& p0) const override;
  // The rotation into the current corotated frame with the rigid arms of the
  // current state (a linearization: the exact map is nonlinear).
  const Matrix6& localFromGlobal() const override { return localFromGlobal_; }

 private:
  std::string context() const;
  // Forces on the ends (translations global) from q.
  Vector6 endForce(const Vector3& q) const;

  Vector2 offset_[2];
  const Node* node_[2] = {nullptr, nullptr};  // not owned: the element's end nodes

  double initialLength_ = 0.0;
  Vector2 initialAxis_ = Vector2::UnitX();
  Matrix6 initialLocalFromGlobal_ = Matrix6::Identity();

  // Trial state.
  Vector2 arm_[2] = {Vector2::Zero(), Vector2::Zero()};
  double length_ = 0.0;
  Vector2 chord_ = Vector2::UnitX();  // r = (c, s)
  Vector3 basic_ = Vector3::Zero();
  Eigen::Matrix<double, 3, 6> basicFromEnd_ = Eigen::Matrix<double, 3, 6>::Zero();  // B of the ends
  Matrix6 endFromNode_ = Matrix6::Identity();  // d(end dofs) / d(node dofs): the rigid arms
  Matrix6 localFromGlobal_ = Matrix6::Identity();
};

}  // namespace beamsolid
