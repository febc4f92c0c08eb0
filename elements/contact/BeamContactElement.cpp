#include "elements/contact/BeamContactElement.h"

#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

std::unique_ptr<ContactMaterial3D> cloneContactMaterial(const NDMaterial& prototype, const std::string& context) {
  std::unique_ptr<NDMaterial> copy = prototype.clone("ContactMaterial3D");
  auto* contact = dynamic_cast<ContactMaterial3D*>(copy.get());
  if (!contact)
    throw OpenSeesError(context + ": nDMaterial " + std::to_string(prototype.tag()) + " is a " +
                        prototype.className() + "; beam contact elements need a ContactMaterial3D");
  copy.release();
  return std::unique_ptr<ContactMaterial3D>(contact);
}

BeamContactElement::BeamContactElement(int tag, std::vector<int> nodeTags, double radius,
                                       std::unique_ptr<CrdTransf> transf, std::unique_ptr<ContactMaterial3D> material,
                                       bool initiallyInContact)
    : Element(tag, std::move(nodeTags)),
      material_(std::move(material)),
      radius_(radius),
      transf_(std::move(transf)),
      initiallyInContact_(initiallyInContact) {
  if (!(radius_ > 0.0)) throw OpenSeesError(context() + ": radius must be positive, got " + std::to_string(radius_));
}

void BeamContactElement::setUpGeometry() {
  requireNodeDofs(nodeA(), 6, "primary (beam) node", context());
  requireNodeDofs(nodeB(), 6, "primary (beam) node", context());
  requireNodeDofs(nodeS(), 3, "secondary (solid) node", context());
  requireDistinctNodes(nodeTags(), context());
  try {
    transf_->initialize(nodeA(), nodeB());
    geometry_.initialize(nodeA(), nodeB(), nodeS(), transf_->localAxes(), radius_);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  inContact_ = initiallyInContact_ && geometry_.inBounds();
  committedSlip_.setZero();
}

void BeamContactElement::updateGeometry() { geometry_.update(nodeA(), nodeB(), nodeS()); }

BeamContactElement::Status BeamContactElement::status() const {
  if (!activeInUpdate_) return Status::Separated;
  return material_->sliding() ? Status::Sliding : Status::Sticking;
}

void BeamContactElement::storeResponseState() {
  const BeamContactGeometry& g = geometry_;
  gapAtUpdate_ = g.gap();
  xiAtUpdate_ = g.xi();
  normalAtUpdate_ = g.normal();
  if (!activeInUpdate_) {
    frictionForce_.setZero();
    forceScalars_.setZero();
    slipIncrement_.setZero();
    return;
  }
  const Vector2& T = material_->traction();
  const double lengthXi = g.covariantBase(0).norm(), lengthPsi = g.covariantBase(1).norm();
  frictionForce_ = -(T(0) * g.contravariantBase(0) + T(1) * g.contravariantBase(1));
  forceScalars_ = Vector3(normalForce_, -T(0) / lengthXi, -T(1) / lengthPsi);
  slipIncrement_ = Vector2(g.slip()(0) * lengthXi, g.slip()(1) * lengthPsi);
}

void BeamContactElement::commitState() {
  committedSlip_ += slipIncrement_;
  slipIncrement_.setZero();
  const double convergedGap = geometry_.gap();
  material_->commitState();
  try {
    geometry_.commit(nodeA(), nodeB(), nodeS());
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  inContact_ = nextContactStatus(convergedGap);
}

void BeamContactElement::revertToLastCommit() { material_->revertToLastCommit(); }

void BeamContactElement::revertToStart() {
  material_->revertToStart();
  transf_->revertToStart();
  try {
    geometry_.initialize(nodeA(), nodeB(), nodeS(), transf_->localAxes(), radius_);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  inContact_ = initiallyInContact_ && geometry_.inBounds();
  activeInUpdate_ = false;
  normalForce_ = 0.0;
  mechanicalForce_.setZero();
  committedSlip_.setZero();
  storeResponseState();
}

bool BeamContactElement::setParameter(const std::vector<std::string>& args, double value) {
  try {
    return material_->setParameter(args, value);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
}

void BeamContactElement::updateMaterialStage(int materialTag, int stage) {
  if (materialTag != material_->tag()) return;
  try {
    material_->updateStage(stage);
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
}

Response BeamContactElement::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string what = lowerCase(args[0]);
  if (what == "force")
    return Response::named({"Fx", "Fy", "Fz"}, [this] { return withoutNegativeZeros(contactForce()); });
  if (what == "frictionforce")
    return Response::named({"Fx", "Fy", "Fz"}, [this] { return withoutNegativeZeros(frictionForce()); });
  if (what == "forcescalar")
    return Response::named({"N", "T1", "T2"}, [this] { return withoutNegativeZeros(forceScalars()); });
  // Contact actions on the beam nodes: minus the element's resisting force there.
  if (what == "masterforce" || what == "primaryforce")
    return Response::named({"Fx_1", "Fy_1", "Fz_1", "Fx_2", "Fy_2", "Fz_2"}, [this] {
      Vector v(6);
      v << -mechanicalForce_.segment<3>(0), -mechanicalForce_.segment<3>(6);
      return withoutNegativeZeros(v);
    });
  if (what == "mastermoment" || what == "primarymoment")
    return Response::named({"Mx_1", "My_1", "Mz_1", "Mx_2", "My_2", "Mz_2"}, [this] {
      Vector v(6);
      v << -mechanicalForce_.segment<3>(3), -mechanicalForce_.segment<3>(9);
      return withoutNegativeZeros(v);
    });
  if (what == "masterreaction" || what == "primaryreaction")
    return Response::named({"Fx_1", "Fy_1", "Fz_1", "Mx_1", "My_1", "Mz_1", "Fx_2", "Fy_2", "Fz_2", "Mx_2", "My_2",
                            "Mz_2"},
                           [this] { return withoutNegativeZeros(-mechanicalForce_.head<12>()); });
  if (what == "slip") return Response::named({"s_xi", "s_psi"}, [this] { return withoutNegativeZeros(totalSlip()); });
  if (what == "gap") return Response::named({"gap"}, [this] { return vectorOf({gap()}); });
  if (what == "status")
    return Response::named({"status"}, [this] { return vectorOf({double(static_cast<int>(status()))}); });
  if (what == "xi") return Response::named({"xi"}, [this] { return vectorOf({xi()}); });
  if (what == "normal") return Response::named({"nx", "ny", "nz"}, [this] { return withoutNegativeZeros(normal()); });
  return {};
}

void BeamContactElement::print(std::ostream& os) const {
  os << context() << ": nodes";
  for (int t : nodeTags()) os << ' ' << t;
  os << ", radius " << radius_ << ", geomTransf " << transf_->tag() << ", nDMaterial " << material_->tag()
     << ", xi " << geometry_.xi() << ", gap " << gapAtUpdate_ << (inContact_ ? ", in contact" : ", not in contact")
     << '\n';
}

}  // namespace beamsolid
