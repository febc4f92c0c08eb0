#pragma once
#include "elements/Element.h"
#include "materials/nd/ContactMaterial3D.h"

namespace beamsolid {

// element('zeroLengthContact3D', tag, cNode, rNode, Kn, Kt, mu, c, dir,
//         <originX, originY>): node-to-node frictional contact by penalty
// (docs/commands.md, "zeroLengthContact3D").
//
// cNode is the constrained node, rNode the retained node (OpenSees' names).
// The contact normal n is the out normal of the retained node's surface:
//   dir 1, 2, 3: n = +X, +Y, +Z;
//   dir 0: n = -e_r, pointing from the retained node towards the axis
//          through (originX, originY) parallel to Z (default origin 0, 0):
//          the retained node lies on the outer body (the soil around a pile
//          shaft), the constrained node on the inner one (the pile).
// n and the tangent basis (t1, t2) are fixed at the initial coordinates
// (small displacements; OpenSees re-evaluates the radii for dir 0, which
// differs by (tangential displacement)^2 / radius).
//
//   gap   g = g0 + n . (u_c - u_r),  g0 = n . (X_c - X_r) for dir 1-3 and
//                                    R_r - R_c (radii from the axis) for dir 0
//   normal force (compression +)  N = Kn max(-g, 0)
//   tangential relative displacement  s = T (u_c - u_r), T = [t1; t2]
//   friction: ContactMaterial3D's elastic predictor and radial return with
//   G = Kt and |F_t| <= mu N + c (identity metric), on the slip increment
//   since the last commit; an open contact (N = 0) carries no force and
//   resets the stick point.
// The element exerts N n - T^T F_t on the constrained node and the opposite
// on the retained one; the tangent is the consistent one (unsymmetric while
// sliding with mu > 0). These conventions (which node is which, the sign of
// the gap, the initial gap from the coordinates) are OpenSeesPy's, checked
// against it (tests/python/oracle_scripts/zerolength_contact.py). On purpose
// unlike OpenSeesPy: while sliding the friction force stays at mu N + c
// (OpenSeesPy's drops, a sawtooth), and friction restarts after an opening
// (OpenSeesPy keeps its old stick point).
class ZeroLengthContact3D : public Element {
 public:
  using Vector2 = Eigen::Vector2d;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Matrix23 = Eigen::Matrix<double, 2, 3>;
  enum class Status { Open = 0, Stick = 1, Slide = 2 };

  ZeroLengthContact3D(int tag, int cNode, int rNode, double Kn, double Kt, double mu, double c, int direction,
                      const Vector2& origin);

  std::string className() const override { return "zeroLengthContact3D"; }

  void update() override;
  MatrixView tangentStiff() override { return viewOf(stiffness_); }
  // Closed and sticking: Kn n n^T + Kt T^T T in the two-node pattern.
  MatrixView initialStiff() override { return viewOf(initialStiffness_); }
  VectorView resistingForce() override { return viewOf(force_); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // Names are matched case-insensitively:
  // 'force'/'forces'/'globalForce'/'globalForces' (6, resisting forces at the
  // two nodes, as in OpenSees); 'gap' (1, negative = penetration); 'status'
  // (1: 0 open, 1 stick, 2 slide); 'normalForce' (1, N, compression +);
  // 'frictionForce' (3, global friction force acting on the retained node,
  // T^T F_t); 'contactForce' (3, the whole force acting on the retained node);
  // 'forceScalar' (3: N, F_t1, F_t2); 'normal' (3, n); 'deformation'/
  // 'deformations' (3: g, s1, s2); 'slip' (2: s1, s2).
  Response setResponse(const std::vector<std::string>& args) override;
  // 'mu'/'frictionCoefficient', 'c'/'cohesion', 'Kn', 'Kt', 'friction' (1
  // frictional, 0 frictionless: a stage as ContactMaterial3D's).
  bool setParameter(const std::vector<std::string>& args, double value) override;
  bool needsGeneralSolver() const override { return mu_ > 0.0 && Kt_ > 0.0; }
  // Drawn at the retained node by the PVD recorder.
  int vertexNode() const override { return 1; }

  void print(std::ostream& os) const override;

  int direction() const { return direction_; }
  const Vector3& normal() const { return normal_; }
  // Rows t1, t2.
  const Matrix23& tangents() const { return tangents_; }
  double gap() const { return gap_; }
  double normalForce() const { return normalForce_; }
  // Friction force components F_t along t1, t2 (acting on the retained node).
  Vector2 frictionComponents() const;
  Status status() const;

 protected:
  void setDomain(Domain& domain) override;

 private:
  void formInitialStiffness();

  double Kn_, Kt_, mu_, c_;
  int direction_;
  Vector2 origin_;
  ContactMaterial3D friction_;

  Vector3 normal_ = Vector3::Zero();
  Matrix23 tangents_ = Matrix23::Zero();
  double gap0_ = 0.0;

  // Trial state.
  double gap_ = 0.0;
  double normalForce_ = 0.0;
  Vector2 slip_ = Vector2::Zero();  // s = T (u_c - u_r)
  // Committed tangential relative displacement: the start of the step's slip increment.
  Vector2 committedSlip_ = Vector2::Zero();

  Vector6 force_ = Vector6::Zero();
  Matrix6 stiffness_ = Matrix6::Zero();
  Matrix6 initialStiffness_ = Matrix6::Zero();
};

}  // namespace beamsolid
