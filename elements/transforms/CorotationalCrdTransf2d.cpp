#include "elements/transforms/CorotationalCrdTransf2d.h"

#include <algorithm>
#include <cmath>

#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {

// An angle brought to (-pi, pi].
double wrapped(double angle) { return std::atan2(std::sin(angle), std::cos(angle)); }

Eigen::Vector2d rotated(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

CorotationalCrdTransf2d::CorotationalCrdTransf2d(int tag, const Vector2& jointOffsetI, const Vector2& jointOffsetJ)
    : CrdTransf2d(tag), offset_{jointOffsetI, jointOffsetJ} {}

std::string CorotationalCrdTransf2d::context() const { return "geomTransf Corotational " + std::to_string(tag()); }

void CorotationalCrdTransf2d::initialize(const Node& nodeI, const Node& nodeJ) {
  for (const Node* n : {&nodeI, &nodeJ})
    if (n->ndf() != 3)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, a 2D beam needs 3 (ux, uy, rz)");
  node_[0] = &nodeI;
  node_[1] = &nodeJ;
  const Vector2 endI = nodeI.crd().head<2>() + offset_[0];
  const Vector2 endJ = nodeJ.crd().head<2>() + offset_[1];
  const Vector2 chord = endJ - endI;
  initialLength_ = chord.norm();
  if (initialLength_ == 0.0 || initialLength_ <= 1e-12 * std::max(endI.norm(), endJ.norm()))
    throw OpenSeesError(context() + ": element has zero length: the ends at nodes " + std::to_string(nodeI.tag()) +
                        " and " + std::to_string(nodeJ.tag()) + " coincide");
  initialAxis_ = chord / initialLength_;
  // Local from global of the undeformed configuration (LinearCrdTransf2d's).
  const double c = initialAxis_.x(), s = initialAxis_.y();
  initialLocalFromGlobal_.setZero();
  for (int k = 0; k < 2; ++k) {
    const Vector2& d = offset_[k];
    initialLocalFromGlobal_.block<3, 3>(3 * k, 3 * k) << c, s, -c * d.y() + s * d.x(), -s, c, s * d.y() + c * d.x(),
        0.0, 0.0, 1.0;
  }
  update();
}

void CorotationalCrdTransf2d::update() {
  if (!node_[0]) throw OpenSeesError(context() + ": update() before initialize()");
  Vector2 end[2];
  double rotation[2];
  for (int k = 0; k < 2; ++k) {
    const Vector& u = node_[k]->trialDisp();
    rotation[k] = u[2];
    arm_[k] = rotated(offset_[k], rotation[k]);
    end[k] = node_[k]->crd().head<2>() + u.head<2>() + arm_[k];
  }
  const Vector2 chord = end[1] - end[0];
  length_ = chord.norm();
  if (!(length_ > 0.0))
    throw OpenSeesError(context() + ": the deformed chord has zero length (the element ends coincide)");
  chord_ = chord / length_;
  const double c = chord_.x(), s = chord_.y();
  // Chord rotation beta from the initial chord: sin and cos of the angle
  // between the two unit vectors, so no branch of atan2 is crossed at +-pi.
  const double beta = std::atan2(initialAxis_.x() * s - initialAxis_.y() * c,
                                 initialAxis_.x() * c + initialAxis_.y() * s);
  // Ln - L0 without cancellation when the two are close.
  const double L0 = initialLength_;
  basic_[0] = (chord.squaredNorm() - L0 * L0) / (length_ + L0);
  basic_[1] = wrapped(rotation[0] - beta);
  basic_[2] = wrapped(rotation[1] - beta);

  // B = dv/d(end dofs): dLn = r.(dxJ - dxI), dbeta = z.(dxJ - dxI)/Ln.
  const double zx = -s / length_, zy = c / length_;
  basicFromEnd_.setZero();
  basicFromEnd_.row(0) << -c, -s, 0.0, c, s, 0.0;
  basicFromEnd_.row(1) << zx, zy, 1.0, -zx, -zy, 0.0;
  basicFromEnd_.row(2) << zx, zy, 0.0, -zx, -zy, 1.0;

  // d(end)/d(node): the arm turns with the node, d(arm) = dtheta Z x arm.
  endFromNode_.setIdentity();
  for (int k = 0; k < 2; ++k) {
    endFromNode_(3 * k, 3 * k + 2) = -arm_[k].y();
    endFromNode_(3 * k + 1, 3 * k + 2) = arm_[k].x();
  }
  Matrix6 rotation6 = Matrix6::Zero();
  for (int k = 0; k < 2; ++k) {
    rotation6.block<2, 2>(3 * k, 3 * k) << c, s, -s, c;
    rotation6(3 * k + 2, 3 * k + 2) = 1.0;
  }
  localFromGlobal_ = rotation6 * endFromNode_;
}

void CorotationalCrdTransf2d::revertToStart() {
  if (node_[0]) update();
}

CorotationalCrdTransf2d::Vector6 CorotationalCrdTransf2d::localResistingForce(const Vector3& q,
                                                                              const Vector6& p0) const {
  return basicToLocal(q, p0, length_);
}

CorotationalCrdTransf2d::Vector6 CorotationalCrdTransf2d::endForce(const Vector3& q) const {
  return basicFromEnd_.transpose() * q;
}

CorotationalCrdTransf2d::Vector6 CorotationalCrdTransf2d::globalResistingForce(const Vector3& q,
                                                                               const Vector6& p0) const {
  // p0 (the simple-support reactions of element loads) goes to the nodes as
  // in the Linear transformation, with the initial axis and arms, as OpenSees
  // does: the loads keep their initial direction (a beam's gravity load
  // stays vertical) and add nothing to the tangent.
  return endFromNode_.transpose() * endForce(q) + initialLocalFromGlobal_.transpose() * p0;
}

CorotationalCrdTransf2d::Matrix6 CorotationalCrdTransf2d::globalStiffMatrix(const Matrix3& kb,
                                                                            const Vector3& q) const {
  // Material part and the variation of B on the end translations.
  Matrix6 k = basicFromEnd_.transpose() * kb * basicFromEnd_;
  const Vector2 r = chord_;
  const Vector2 z(-r.y(), r.x());
  const Eigen::Matrix2d geometric =
      (q[0] / length_) * (z * z.transpose()) + ((q[1] + q[2]) / (length_ * length_)) * (r * z.transpose() + z * r.transpose());
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) k.block<2, 2>(3 * a, 3 * b) += (a == b ? 1.0 : -1.0) * geometric;
  Matrix6 global = endFromNode_.transpose() * k * endFromNode_;
  // The arm's turning: d/dtheta of (-arm_y fx + arm_x fy) = -(arm . f).
  const Vector6 f = endForce(q);
  for (int e = 0; e < 2; ++e) global(3 * e + 2, 3 * e + 2) -= arm_[e].dot(f.segment<2>(3 * e));
  return global;
}

CorotationalCrdTransf2d::Matrix6 CorotationalCrdTransf2d::initialGlobalStiffMatrix(const Matrix3& kb) const {
  // B and the arms of the undeformed configuration.
  const double c = initialAxis_.x(), s = initialAxis_.y();
  const double zx = -s / initialLength_, zy = c / initialLength_;
  Eigen::Matrix<double, 3, 6> b;
  b.row(0) << -c, -s, 0.0, c, s, 0.0;
  b.row(1) << zx, zy, 1.0, -zx, -zy, 0.0;
  b.row(2) << zx, zy, 0.0, -zx, -zy, 1.0;
  Matrix6 t = Matrix6::Identity();
  for (int k = 0; k < 2; ++k) {
    t(3 * k, 3 * k + 2) = -offset_[k].y();
    t(3 * k + 1, 3 * k + 2) = offset_[k].x();
  }
  const Eigen::Matrix<double, 3, 6> a = b * t;
  return a.transpose() * kb * a;
}

}  // namespace beamsolid
