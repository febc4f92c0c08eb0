#pragma once
#include <memory>
#include <ostream>
#include <string>

#include "core/Types.h"

namespace beamsolid {

class Node;
class CrdTransf2d;

// Geometric transformation of a 3D beam (geomTransf): maps the 12 global end
// dofs to the 6 basic deformations and basic forces back to global forces and
// stiffness. One prototype per geomTransf tag; each element owns a clone.
//
// Local axes (OpenSees convention): x runs from end I to end J (the ends are
// the nodes moved by the rigid joint offsets), y = vecxz x x (normalized),
// z = x x y, so local z lies in the plane of x and vecxz.
//
// Basic system (simply supported, axially fixed at I), OpenSees order:
//   v = [eps*L, thz_i, thz_j, thy_i, thy_j, twist]      deformations
//   q = [N, Mz_i, Mz_j, My_i, My_j, T]                  forces (N tension +)
// with, in local end displacements (u, v, w, rx, ry, rz at I then J),
//   thz_i = rz_i - (v_j - v_i)/L,  thy_i = ry_i + (w_j - w_i)/L  (same at j).
// Local end forces are A^T q + p0, where p0 (12, local, same dof order) holds
// the reactions of the basic system under element loads that q cannot carry
// (transverse simple-support reactions, the axial reaction at I).
class CrdTransf {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Vector12 = Eigen::Matrix<double, 12, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Matrix12 = Eigen::Matrix<double, 12, 12>;

  explicit CrdTransf(int tag) : tag_(tag) {}
  virtual ~CrdTransf() = default;
  int tag() const { return tag_; }
  virtual std::string className() const = 0;
  virtual std::unique_ptr<CrdTransf> clone() const = 0;

  // Binds the clone to the element's end nodes; throws when vecxz is
  // parallel to the element axis or the element has zero length.
  virtual void initialize(const Node& nodeI, const Node& nodeJ) = 0;
  virtual void update() = 0;
  virtual void commitState() {}
  virtual void revertToLastCommit() {}
  virtual void revertToStart() {}

  virtual double initialLength() const = 0;
  virtual double deformedLength() const = 0;
  // Rows are the local x, y, z axes in global coordinates (initial).
  virtual Matrix3 localAxes() const = 0;
  // The user's vecxz.
  virtual Vector3 vecxz() const = 0;

  // Basic deformations of the trial state, their increment since the last
  // commit, and their change since the previous update() (for elements that
  // iterate on the increment, e.g. force-based beams).
  virtual Vector6 basicTrialDisp() const = 0;
  virtual Vector6 basicIncrDisp() const = 0;
  virtual Vector6 basicIncrDeltaDisp() const = 0;
  // Global end forces from basic forces q plus fixed-end forces p0 (local, 12).
  virtual Vector12 globalResistingForce(const Vector6& q, const Vector12& p0) const = 0;
  virtual Matrix12 globalStiffMatrix(const Matrix6& kb, const Vector6& q) const = 0;
  virtual Matrix12 initialGlobalStiffMatrix(const Matrix6& kb) const = 0;
  // Local end forces (12) from basic forces and fixed-end forces.
  virtual Vector12 localResistingForce(const Vector6& q, const Vector12& p0) const = 0;

  virtual void print(std::ostream& os) const { os << "geomTransf " << tag_ << " type " << className() << '\n'; }

  // The 2D transformation this definition stands for in a 2D model (a
  // geomTransf defined there has vecxz = Z), or null where there is none.
  virtual std::unique_ptr<CrdTransf2d> planar() const;

  // Local end forces A^T q + p0 of the basic system on a chord of `length`:
  // the equilibrium every transformation starts from (geometric terms, such
  // as PDelta's chord shear, are added by the caller).
  static Vector12 basicToLocal(const Vector6& q, const Vector12& p0, double length) {
    Vector12 p = p0;
    const double shearY = (q[1] + q[2]) / length;
    const double shearZ = (q[3] + q[4]) / length;
    p[0] -= q[0];
    p[6] += q[0];
    p[1] += shearY;
    p[7] -= shearY;
    p[2] -= shearZ;
    p[8] += shearZ;
    p[3] -= q[5];
    p[9] += q[5];
    p[4] += q[3];
    p[10] += q[4];
    p[5] += q[1];
    p[11] += q[2];
    return p;
  }

 private:
  int tag_;
};

}  // namespace beamsolid
