#include "elements/contact/BeamEndContactElement.h"

#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

namespace {

Vector3 position(const Node& n) { return n.crd() + n.trialDisp().head<3>(); }
Vector3 rotation(const Node& n) { return n.trialDisp().segment<3>(3); }

Matrix3 skew(const Vector3& v) {
  Matrix3 s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace

BeamEndContactElement::BeamEndContactElement(int tag, std::vector<int> nodeTags, double radius,
                                             bool initiallyInContact)
    : Element(tag, std::move(nodeTags)), radius_(radius), initiallyInContact_(initiallyInContact) {
  if (!(radius_ > 0.0)) throw OpenSeesError(context() + ": radius must be positive, got " + std::to_string(radius_));
}

void BeamEndContactElement::setUpGeometry() {
  requireDistinctNodes(nodeTags(), context());
  requireNodeDofs(endNode(), 6, "beam end node", context());
  requireNodeDofs(*nodes()[1], 6, "beam node", context());
  requireNodeDofs(soilNode(), 3, "secondary (solid) node", context());
  const Vector3 axis = endNode().crd() - nodes()[1]->crd();
  if (!(axis.norm() > 0.0))
    throw OpenSeesError(context() + ": the beam nodes " + std::to_string(nodeTags()[0]) + " and " +
                        std::to_string(nodeTags()[1]) + " coincide; the end face normal is undefined");
  referenceNormal_ = axis.normalized();
  initializeNormal();
  inContact_ = initiallyInContact_ && withinFace();
  updateGeometry();
}

void BeamEndContactElement::initializeNormal() {
  committedRotation_ = rotation(endNode());
  committedNormal_ = rotationExp(committedRotation_) * referenceNormal_;
  setHeldData();
}

void BeamEndContactElement::setHeldData() {
  const Vector3 d = position(soilNode()) - position(endNode());
  const Vector3& n = committedNormal_;
  committedGap_ = n.dot(d);
  lateralOffset_ = (d - committedGap_ * n).norm();  // E7
  // E4: g contains dth . (n_n x d) = dth^T S d with S = skew(n_n) and
  // d = x_s - x_i, so the only second derivatives are the th_i-u blocks.
  const Matrix3 S = skew(n);
  gapHessian_.setZero();
  gapHessian_.block<3, 3>(3, 12) = S;
  gapHessian_.block<3, 3>(3, 0) = -S;
  gapHessian_.block<3, 3>(12, 3) = S.transpose();
  gapHessian_.block<3, 3>(0, 3) = -S.transpose();
}

void BeamEndContactElement::updateGeometry() {
  const Vector3 d = position(soilNode()) - position(endNode());
  const Vector3 dTheta = rotation(endNode()) - committedRotation_;
  normal_ = committedNormal_ + dTheta.cross(committedNormal_);  // E1
  gap_ = normal_.dot(d);                                         // E2
  // E3: B = -dg/dq; g = n_n . d + dth . (n_n x d).
  gapGradient_.setZero();
  gapGradient_.segment<3>(0) = normal_;
  gapGradient_.segment<3>(3) = d.cross(committedNormal_);
  gapGradient_.segment<3>(12) = -normal_;
}

void BeamEndContactElement::commitState() {
  const double convergedGap = gap_;
  // C1: turn the face with the step's rotation increment of the end node.
  const Vector3 theta = rotation(endNode());
  committedNormal_ = (rotationExp(theta - committedRotation_) * committedNormal_).normalized();
  committedRotation_ = theta;
  setHeldData();
  inContact_ = nextContactStatus(convergedGap);
}

void BeamEndContactElement::revertToStart() {
  initializeNormal();
  inContact_ = initiallyInContact_ && withinFace();
  activeInUpdate_ = false;
  normalForce_ = 0.0;
  mechanicalForce_.setZero();
  updateGeometry();
}

Response BeamEndContactElement::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string what = lowerCase(args[0]);
  if (what == "force")
    return Response::named({"Fx", "Fy", "Fz"}, [this] { return withoutNegativeZeros(contactForce()); });
  if (what == "forcescalar")
    return Response::named({"N"}, [this] { return withoutNegativeZeros(vectorOf({normalForce_})); });
  // Contact action on the end node: minus the element's resisting force there.
  if (what == "masterforce" || what == "primaryforce")
    return Response::named({"Fx", "Fy", "Fz", "Mx", "My", "Mz"},
                           [this] { return withoutNegativeZeros(-mechanicalForce_.head<6>()); });
  if (what == "gap") return Response::named({"gap"}, [this] { return withoutNegativeZeros(vectorOf({gap_})); });
  if (what == "status") return Response::named({"status"}, [this] { return vectorOf({double(status())}); });
  if (what == "normal") return Response::named({"nx", "ny", "nz"}, [this] { return withoutNegativeZeros(normal_); });
  return {};
}

void BeamEndContactElement::print(std::ostream& os) const {
  os << context() << ": nodes";
  for (int t : nodeTags()) os << ' ' << t;
  os << ", radius " << radius_ << ", normal (" << committedNormal_.transpose() << "), gap " << gap_
     << ", lateral offset " << lateralOffset_ << (inContact_ ? ", in contact" : ", not in contact") << '\n';
}

}  // namespace beamsolid
