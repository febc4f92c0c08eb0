#pragma once
#include <memory>
#include <ostream>
#include <string>

#include "core/Types.h"

namespace beamsolid {

class Node;

// Geometric transformation of a 3D beam (geomTransf): maps the 12 global end
// dofs to the 6 basic deformations [axial, thz_i, thz_j, thy_i, thy_j, twist]
// (OpenSees' basic system) and basic forces back to global forces and
// stiffness. One prototype per geomTransf tag; each element owns a clone.
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

  virtual Vector6 basicTrialDisp() const = 0;
  virtual Vector6 basicIncrDisp() const = 0;
  // Global end forces from basic forces q plus fixed-end forces p0 (local, 12).
  virtual Vector12 globalResistingForce(const Vector6& q, const Vector12& p0) const = 0;
  virtual Matrix12 globalStiffMatrix(const Matrix6& kb, const Vector6& q) const = 0;
  virtual Matrix12 initialGlobalStiffMatrix(const Matrix6& kb) const = 0;
  // Local end forces (12) from basic forces and fixed-end forces.
  virtual Vector12 localResistingForce(const Vector6& q, const Vector12& p0) const = 0;

  virtual void print(std::ostream& os) const { os << "geomTransf " << tag_ << " type " << className() << '\n'; }

 private:
  int tag_;
};

}  // namespace beamsolid
