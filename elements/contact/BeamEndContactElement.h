#pragma once
#include "elements/Element.h"

namespace beamsolid {

class Domain;

// What BeamEndContact3D (Lagrange multiplier) and BeamEndContact3Dp
// (penalty) share: normal, frictionless contact of the circular end face of
// a pile (beam end node i, the end element's other node j) with one solid
// node s (docs/beam_contact.md, "End bearing", equations E1-E7).
//
// The 15 mechanical dofs are [u_i, th_i, u_j, th_j, u_s]. The face normal
// n points out of the pile, from j to i, and turns with i's rotation:
// initially n = exp(skew(th_i)) (X_i - X_j)/|X_i - X_j|, after each
// converged step n_n <- exp(skew(dth)) n_n (C1), and inside a step the
// linearized update (C2)
//   n = n_n + dth x n_n,  dth = th_i - th_i,n                               (E1)
// Gap (positive: the node is ahead of the face, negative: penetration)
//   g = n . (x_s - x_i),                                                    (E2)
// measured from the end node along the normal, so the face is the plane
// through x_i. Node j's dofs do not enter (they carry zero rows).
//
// The node can be in contact only while it lies within the face: its offset
// from the pile axis in the face plane, |d - (n.d) n| with d = x_s - x_i,
// is at most the radius (checked at commit with the committed normal).   (E7)
//
// Positive normal force t_n is compression (the tip pushes the soil node
// along n). "force" is the contact force on the soil node, "masterforce" the
// force and moment on the end node i; together they balance (exactly at the
// start of a step, to O(t_n |d| |dth|) within it, as for any linearized
// rotation).
class BeamEndContactElement : public Element {
 public:
  using Vector15 = Eigen::Matrix<double, 15, 1>;
  using Matrix15 = Eigen::Matrix<double, 15, 15>;

  double radius() const { return radius_; }
  // The status of the current step (decided at the last commit).
  bool inContact() const { return inContact_; }
  // Normal force t_n of the last update (lambda or the penalty force); zero
  // out of contact.
  double normalForce() const { return normalForce_; }
  // Whether the last update applied contact forces: 0 separated, 1 in contact.
  int status() const { return activeInUpdate_ ? 1 : 0; }

  // --- geometry of the last update (E1, E2) ------------------------------------------
  double gap() const { return gap_; }
  const Vector3& normal() const { return normal_; }
  // B = -dg/dq (E3) and H = d2g/dq2 (E4, constant within a step).
  const Vector15& gapGradient() const { return gapGradient_; }
  const Matrix15& gapHessian() const { return gapHessian_; }

  // --- held data of the last commit ---------------------------------------------------
  const Vector3& committedNormal() const { return committedNormal_; }
  // n_n . (x_s - x_i) with the committed normal and positions.
  double committedGap() const { return committedGap_; }
  // Distance of the soil node from the pile axis in the face plane (E7).
  double lateralOffset() const { return lateralOffset_; }
  bool withinFace() const { return lateralOffset_ <= radius_; }

  // Resisting force on the 15 mechanical dofs.
  const Vector15& mechanicalForce() const { return mechanicalForce_; }
  // Contact force on the soil node (global), minus its resisting force.
  Vector3 contactForce() const { return -mechanicalForce_.segment<3>(12); }

  // Rotates the face normal by the step's rotation increment (C1), refreshes
  // the held data (E4, E7) and decides the next step's status.
  // No Rayleigh damping: the multiplier rows are constraints, not stiffness. betaK
  // on them turns a released node's lambda = 0 into lambda + betaK dlambda/dt = 0,
  // so lambda stays negative and the node never closes again (it sinks into the pile).
  bool doesRayleighDamping() const override { return false; }
  void commitState() override;
  void revertToStart() override;

  // force (3, on the soil node), forcescalar (1, normal force),
  // masterforce|primaryforce (6, force and moment on the end node),
  // gap (1), status (1: 0 separated, 1 in contact), normal (3).
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

 protected:
  BeamEndContactElement(int tag, std::vector<int> nodeTags, double radius, bool initiallyInContact);

  // Checks the nodes (ndf, distinct, i and j apart), sets the reference
  // normal and the initial status (in contact iff cSwitch 0 and within the face).
  void setUpGeometry();
  // Trial normal, gap and gradient from the nodes (allocation-free).
  void updateGeometry();
  // The status for the next step; called by commitState() after the
  // held data were refreshed. convergedGap is the step's gap (E2).
  virtual bool nextContactStatus(double convergedGap) = 0;
  bool initiallyInContact() const { return initiallyInContact_; }

  const Node& endNode() const { return *nodes()[0]; }
  const Node& soilNode() const { return *nodes()[2]; }

  bool inContact_ = false;
  bool activeInUpdate_ = false;
  double normalForce_ = 0.0;
  Vector15 mechanicalForce_ = Vector15::Zero();

 private:
  // Reference normal rotated by the end node's current rotation.
  void initializeNormal();
  // committedGap, lateralOffset and H from the committed normal and the nodes.
  void setHeldData();

  double radius_;
  bool initiallyInContact_;
  Vector3 referenceNormal_ = Vector3::UnitZ();
  Vector3 committedNormal_ = Vector3::UnitZ();
  Vector3 committedRotation_ = Vector3::Zero();
  double committedGap_ = 0.0;
  double lateralOffset_ = 0.0;
  Matrix15 gapHessian_ = Matrix15::Zero();
  // Trial state of the last update.
  Vector3 normal_ = Vector3::UnitZ();
  double gap_ = 0.0;
  Vector15 gapGradient_ = Vector15::Zero();
};

}  // namespace beamsolid
