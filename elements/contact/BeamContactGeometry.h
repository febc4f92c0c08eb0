#pragma once
#include "core/Types.h"

namespace beamsolid {

class Node;

// Geometry and kinematics of one beam segment's cylindrical surface seen by
// one secondary node (beam_contact_formulation.md, C1-C12). Shared by the
// Lagrange multiplier element (BeamContact3D) and the penalty element
// (BeamContact3Dp).
//
// The 15 mechanical dofs are ordered [u_a, th_a, u_b, th_b, u_s] (beam node a,
// beam node b, secondary node s). Within a load step the projection data of
// the last commit (xi_c, H_i(xi_c), n, rho2, rho3, g^alpha, Q_c) are held, so
// the trial gap and slip are linear in the dofs with constant gradients B_n
// and B_s^alpha (C12). commit() re-projects and refreshes the held data.
class BeamContactGeometry {
 public:
  using Vector2 = Eigen::Vector2d;
  using Matrix2 = Eigen::Matrix2d;
  using Vector15 = Eigen::Matrix<double, 15, 1>;
  using Matrix15x2 = Eigen::Matrix<double, 15, 2>;

  // Frames from the beam's local axes (rows x, y, z as CrdTransf::localAxes),
  // rotated by the nodes' current rotations (C1 from the reference state),
  // then the first projection (C4-C9) from the chord projection. Throws
  // OpenSeesError (without element context) when the segment is degenerate
  // or the projection fails.
  void initialize(const Node& a, const Node& b, const Node& s, const Matrix3& localAxes, double radius);
  // Chained (pile) form: the committed nodal frames frameA, frameB (columns:
  // axis, section axes) at the nodes' current rotations are given -- by the
  // pile's shared frames (BeamContactPile) -- instead of being tracked here.
  // The projection starts from xiStart, or from the chord projection when
  // xiStart is not finite. Used at set-up and to move to another segment.
  void initialize(const Node& a, const Node& b, const Node& s, const Matrix3& frameA, const Matrix3& frameB,
                  double radius, double xiStart);

  // Trial gap (C10) and incremental slip (C11) from the nodes' trial state.
  // Allocation-free.
  void update(const Node& a, const Node& b, const Node& s);

  // After a converged step: rotate the nodal frames by the step's rotation
  // increment (C1), re-project the secondary node (C4-C5) and rebuild the
  // frame, surface, metric and gradients (C6-C9, C12). Throws OpenSeesError
  // when the projection fails.
  void commit(const Node& a, const Node& b, const Node& s);
  // The same with given nodal frames (chained form, see initialize()).
  void commit(const Node& a, const Node& b, const Node& s, const Matrix3& frameA, const Matrix3& frameB);

  // --- trial state --------------------------------------------------------------
  double gap() const { return gap_; }
  // Incremental slip s^alpha (alpha = xi, psi) since the last commit.
  const Vector2& slip() const { return slip_; }
  // Trial centerline point at the held xi_c (C3 with the C2 tangents).
  const Vector3& trialCenterlinePoint() const { return trialCenterlinePoint_; }

  // --- held data of the last commit -----------------------------------------------
  double radius() const { return radius_; }
  double length() const { return length_; }
  double xi() const { return xi_; }
  // The segment owns the node only while 0 < xi_c < 1.
  bool inBounds() const { return xi_ > 0.0 && xi_ < 1.0; }
  // n . (x_s - x_c) - R at the projection of the last commit.
  double committedGap() const { return committedGap_; }
  const Vector3& normal() const { return normal_; }
  const Vector3& centerlinePoint() const { return centerlinePoint_; }
  // Columns c1, c2, c3 of the frame at the projection (C6).
  const Matrix3& frame() const { return frame_; }
  double rho2() const { return rho2_; }
  double rho3() const { return rho3_; }
  // g_xi, g_psi (C8) and g^xi, g^psi (C9).
  const Vector3& covariantBase(int alpha) const { return covariantBase_[alpha]; }
  const Vector3& contravariantBase(int alpha) const { return contravariantBase_[alpha]; }
  const Matrix2& metric() const { return metric_; }
  // B_n = -dg/dq and B_s^alpha = ds^alpha/dq (C12), columns alpha of B_s.
  const Vector15& gapGradient() const { return gapGradient_; }
  const Matrix15x2& slipGradient() const { return slipGradient_; }
  // Nodal frames (columns: axis, then the two section axes) of the last commit.
  const Matrix3& frameA() const { return frameA_; }
  const Matrix3& frameB() const { return frameB_; }
  // Twist angle between Q_b and Q_a transported to b1.
  double twist() const { return twist_; }
  int projectionIterations() const { return projectionIterations_; }
  bool projectionUsedFallback() const { return projectionFallback_; }

  // --- the committed centerline and frame field, as functions of xi -------------------
  Vector3 centerline(double xi) const;         // phi (C3)
  Vector3 centerlineTangent(double xi) const;  // phi'
  Vector3 centerlineCurvature(double xi) const;  // phi''
  // Transported frame at xi (C6) and, if wanted, its xi-derivative.
  void frameAt(double xi, Matrix3& frame, Matrix3* derivative) const;
  // Closest point (C4) of x on the committed centerline. Newton from xiStart
  // (the previous projection) is accepted when it converges inside [0, 1];
  // otherwise (no convergence, R' >= 0, or a result beyond the segment, where
  // the extrapolated cubic may have spurious minima) the closest of 81
  // samples on [-0.5, 1.5] is refined by bracketed Newton-bisection. A
  // closest point beyond the segment comes back outside (0, 1). For a point
  // beyond the centre of curvature of a strongly bent segment two local
  // closest points may exist and the one nearer the start wins. Throws
  // OpenSeesError when the geometry is degenerate or the refinement fails.
  double project(const Vector3& x, double xiStart) const;

  static void hermite(double xi, double h[4], double dh[4], double ddh[4]);

 private:
  void updateFrames(const Node& a, const Node& b);
  void setFrames(const Node& a, const Node& b, const Matrix3& frameA, const Matrix3& frameB);
  void setLength(const Node& a, const Node& b);
  void computeTwist();
  void setProjectionData(const Node& s);
  // Adds sign * (gradient of e . (H0 x_a + H1 L a1 + H2 x_b + H3 L b1)) to B.
  void addCenterlineGradient(Vector15& B, const Vector3& e, const double h[4], double sign) const;

  double radius_ = 0.0;
  double length_ = 0.0;

  // Nodal frames and the rotations at which they were last updated (C1).
  Matrix3 frameA_ = Matrix3::Identity(), frameB_ = Matrix3::Identity();
  Vector3 thetaA_ = Vector3::Zero(), thetaB_ = Vector3::Zero();
  // Committed beam node positions.
  Vector3 xa_ = Vector3::Zero(), xb_ = Vector3::Zero();
  double twist_ = 0.0;

  // Projection data held during a step.
  double xi_ = 0.5;
  double h_[4] = {0, 0, 0, 0}, dh_[4] = {0, 0, 0, 0};
  Vector3 centerlinePoint_ = Vector3::Zero();
  Vector3 tangent_ = Vector3::Zero();  // phi'(xi_c)
  double tangentNorm_ = 1.0;
  Vector3 normal_ = Vector3::UnitX();
  Vector3 radial_ = Vector3::Zero();   // r = rho2 c2 + rho3 c3
  Vector3 offsetN_ = Vector3::Zero();  // x_s - x_c - r at the commit
  Matrix3 frame_ = Matrix3::Identity();
  double rho2_ = 0.0, rho3_ = 0.0;
  Vector3 covariantBase_[2] = {Vector3::Zero(), Vector3::Zero()};
  Vector3 contravariantBase_[2] = {Vector3::Zero(), Vector3::Zero()};
  Matrix2 metric_ = Matrix2::Identity();
  double committedGap_ = 0.0;
  Vector15 gapGradient_ = Vector15::Zero();
  Matrix15x2 slipGradient_ = Matrix15x2::Zero();
  mutable int projectionIterations_ = 0;
  mutable bool projectionFallback_ = false;

  // Trial state.
  double gap_ = 0.0;
  Vector2 slip_ = Vector2::Zero();
  Vector3 trialCenterlinePoint_ = Vector3::Zero();
};

}  // namespace beamsolid
