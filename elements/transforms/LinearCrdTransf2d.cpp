#include "elements/transforms/LinearCrdTransf2d.h"

#include <algorithm>

#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

LinearCrdTransf2d::LinearCrdTransf2d(int tag, const Eigen::Vector2d& jointOffsetI,
                                     const Eigen::Vector2d& jointOffsetJ)
    : CrdTransf2d(tag), offsetI_(jointOffsetI), offsetJ_(jointOffsetJ) {}

std::string LinearCrdTransf2d::context() const {
  return "geomTransf " + className() + " " + std::to_string(tag());
}

void LinearCrdTransf2d::initialize(const Node& nodeI, const Node& nodeJ) {
  for (const Node* n : {&nodeI, &nodeJ})
    if (n->ndf() != 3)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, a 2D beam needs 3 (ux, uy, rz)");
  nodeI_ = &nodeI;
  nodeJ_ = &nodeJ;
  const Eigen::Vector2d endI = nodeI.crd().head<2>() + offsetI_;
  const Eigen::Vector2d endJ = nodeJ.crd().head<2>() + offsetJ_;
  const Eigen::Vector2d chord = endJ - endI;
  length_ = chord.norm();
  if (length_ == 0.0 || length_ <= 1e-12 * std::max(endI.norm(), endJ.norm()))
    throw OpenSeesError(context() + ": element has zero length: the ends at nodes " + std::to_string(nodeI.tag()) +
                        " and " + std::to_string(nodeJ.tag()) + " coincide");
  axis_ = chord / length_;
  const double c = axis_.x(), s = axis_.y();

  // Local (u, v) = R (u_end), u_end = u + theta Z x offset = (ux - theta dy, uy + theta dx).
  localFromGlobal_.setZero();
  const Eigen::Vector2d* offsets[2] = {&offsetI_, &offsetJ_};
  for (int end = 0; end < 2; ++end) {
    const int k = 3 * end;
    const Eigen::Vector2d& d = *offsets[end];
    localFromGlobal_(k, k) = c;
    localFromGlobal_(k, k + 1) = s;
    localFromGlobal_(k, k + 2) = -c * d.y() + s * d.x();
    localFromGlobal_(k + 1, k) = -s;
    localFromGlobal_(k + 1, k + 1) = c;
    localFromGlobal_(k + 1, k + 2) = s * d.y() + c * d.x();
    localFromGlobal_(k + 2, k + 2) = 1.0;
  }
  Eigen::Matrix<double, 3, 6> a = Eigen::Matrix<double, 3, 6>::Zero();
  const double invL = 1.0 / length_;
  a(0, 0) = -1.0;
  a(0, 3) = 1.0;
  a(1, 1) = a(2, 1) = invL;
  a(1, 4) = a(2, 4) = -invL;
  a(1, 2) = 1.0;
  a(2, 5) = 1.0;
  basicFromGlobal_ = a * localFromGlobal_;
  update();
}

void LinearCrdTransf2d::update() {
  if (!nodeI_) throw OpenSeesError(context() + ": update() before initialize()");
  Vector6 u;
  u.head<3>() = nodeI_->trialDisp().head<3>();
  u.tail<3>() = nodeJ_->trialDisp().head<3>();
  localTrial_ = localFromGlobal_ * u;
  basicTrial_ = basicFromGlobal_ * u;
}

void LinearCrdTransf2d::revertToStart() {
  localTrial_.setZero();
  basicTrial_.setZero();
}

LinearCrdTransf2d::Vector6 LinearCrdTransf2d::localResistingForce(const Vector3& q, const Vector6& p0) const {
  return basicToLocal(q, p0, length_);
}

LinearCrdTransf2d::Vector6 LinearCrdTransf2d::globalResistingForce(const Vector3& q, const Vector6& p0) const {
  return localFromGlobal_.transpose() * basicToLocal(q, p0, length_);
}

LinearCrdTransf2d::Matrix6 LinearCrdTransf2d::globalStiffMatrix(const Matrix3& kb, const Vector3&) const {
  return initialGlobalStiffMatrix(kb);
}

LinearCrdTransf2d::Matrix6 LinearCrdTransf2d::initialGlobalStiffMatrix(const Matrix3& kb) const {
  const Eigen::Matrix<double, 3, 6> kbA = kb * basicFromGlobal_;
  return basicFromGlobal_.transpose() * kbA;
}

}  // namespace beamsolid
