#pragma once
#include <memory>
#include <ostream>
#include <string>

#include "core/Types.h"

namespace beamsolid {

class Node;

// Geometric transformation of a 2D beam in the x-y plane: maps the 6 global
// end dofs (ux, uy, rz at I then J) to the 3 basic deformations and basic
// forces back. The in-plane restriction of CrdTransf (3D): local x from I to
// J, local y = Z x x, and the same basic system (OpenSees order)
//   v = [eps*L, theta_i, theta_j],  q = [N, M_i, M_j]
// with theta_i = rz_i - (v_j - v_i)/L. Local end forces are A^T q + p0 with
// p0 (6, local: N, V, M at I then J) the basic system's reactions to
// element loads.
class CrdTransf2d {
 public:
  using Vector3 = Eigen::Matrix<double, 3, 1>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix3 = Eigen::Matrix<double, 3, 3>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  explicit CrdTransf2d(int tag) : tag_(tag) {}
  virtual ~CrdTransf2d() = default;
  int tag() const { return tag_; }
  virtual std::string className() const = 0;

  // Binds to the element's end nodes (ndm 2, ndf 3); throws on zero length.
  virtual void initialize(const Node& nodeI, const Node& nodeJ) = 0;
  virtual void update() = 0;
  // Path-dependent transformations (Corotational) keep committed state.
  virtual void commitState() {}
  virtual void revertToLastCommit() {}
  virtual void revertToStart() = 0;

  virtual double initialLength() const = 0;
  // Unit local x axis (cos, sin) in global coordinates.
  virtual Eigen::Vector2d axis() const = 0;

  virtual Vector3 basicTrialDisp() const = 0;
  virtual Vector6 globalResistingForce(const Vector3& q, const Vector6& p0) const = 0;
  virtual Matrix6 globalStiffMatrix(const Matrix3& kb, const Vector3& q) const = 0;
  virtual Matrix6 initialGlobalStiffMatrix(const Matrix3& kb) const = 0;
  // Local end forces without geometric terms: A^T q + p0.
  virtual Vector6 localResistingForce(const Vector3& q, const Vector6& p0) const = 0;
  // Maps global end dofs to local end dofs (rotation and joint offsets).
  virtual const Matrix6& localFromGlobal() const = 0;

  // The basic system's equilibrium on a chord of `length` (CrdTransf's
  // basicToLocal restricted to the plane).
  static Vector6 basicToLocal(const Vector3& q, const Vector6& p0, double length) {
    Vector6 p = p0;
    const double shear = (q[1] + q[2]) / length;
    p[0] -= q[0];
    p[3] += q[0];
    p[1] += shear;
    p[4] -= shear;
    p[2] += q[1];
    p[5] += q[2];
    return p;
  }

 private:
  int tag_;
};

}  // namespace beamsolid
