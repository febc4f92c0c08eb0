#include "elements/contact/BeamContactElement.h"

#include <algorithm>
#include <cctype>
#include <limits>

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

std::unique_ptr<ContactMaterial3D> cloneContactMaterial(const NDMaterial& prototype, const std::string& context) {
  std::unique_ptr<NDMaterial> copy = prototype.clone("ContactMaterial3D");
  auto* contact = dynamic_cast<ContactMaterial3D*>(copy.get());
  if (!contact)
    throw OpenSeesError(context + ": nDMaterial " + std::to_string(prototype.tag()) + " (" + prototype.className() +
                        ") is not a ContactMaterial3D; beam contact elements need a ContactMaterial3D");
  copy.release();
  return std::unique_ptr<ContactMaterial3D>(contact);
}

BeamContactElement::BeamContactElement(int tag, std::vector<int> nodeTags, double radius,
                                       std::unique_ptr<CrdTransf> transf, std::unique_ptr<ContactMaterial3D> material,
                                       bool initiallyInContact, std::vector<int> pileNodeTags)
    : Element(tag, std::move(nodeTags)),
      material_(std::move(material)),
      radius_(radius),
      transf_(std::move(transf)),
      initiallyInContact_(initiallyInContact),
      pileNodeTags_(std::move(pileNodeTags)) {
  if (!(radius_ > 0.0)) throw OpenSeesError(context() + ": radius must be positive, got " + std::to_string(radius_));
}

void BeamContactElement::setUpGeometry(Domain& domain) {
  requireNodeDofs(nodeA(), 6, "primary (beam) node", context());
  requireNodeDofs(nodeB(), 6, "primary (beam) node", context());
  requireNodeDofs(nodeS(), 3, "secondary (solid) node", context());
  requireDistinctNodes(nodeTags(), context());
  const auto& tags = nodeTags();
  if (!pileNodeTags_.empty()) {
    pile_ = domain.sharedObject<BeamContactPile>(BeamContactPile::key(transf_->tag(), pileNodeTags_), [&] {
      return std::make_shared<BeamContactPile>(domain, pileNodeTags_, *transf_, context());
    });
    segment_ = pile_->segmentOf(tags[0], tags[1]);
    if (segment_ < 0)
      throw OpenSeesError(context() + ": iNode " + std::to_string(tags[0]) + " and jNode " + std::to_string(tags[1]) +
                          " must be consecutive nodes of the -pile list, in its order");
    for (std::size_t k = 2; k < tags.size(); ++k)
      for (int p : pileNodeTags_)
        if (tags[k] == p)
          throw OpenSeesError(context() + ": node " + std::to_string(p) +
                              " is a pile node; the secondary and multiplier nodes must not be");
    try {
      pile_->synchronize();
      initializeOnPile(std::numeric_limits<double>::quiet_NaN());
      Vector3 base[2] = {geometry_.covariantBase(0), geometry_.covariantBase(1)};
      handOver(base);  // to the segment that holds the node's projection
    } catch (const OpenSeesError& e) {
      throw OpenSeesError(context() + ": " + e.what());
    }
    initialSegment_ = segment_;
    handOvers_ = 0;
  } else {
    try {
      transf_->initialize(nodeA(), nodeB());
      geometry_.initialize(nodeA(), nodeB(), nodeS(), transf_->localAxes(), radius_);
    } catch (const OpenSeesError& e) {
      throw OpenSeesError(context() + ": " + e.what());
    }
  }
  inContact_ = initiallyInContact_ && ownsNode(kHandOverTolerance);
  committedSlip_.setZero();
}

void BeamContactElement::initializeOnPile(double xiStart) {
  geometry_.initialize(nodeA(), nodeB(), nodeS(), pile_->frame(segment_, segment_),
                       pile_->frame(segment_ + 1, segment_), radius_, xiStart);
}

bool BeamContactElement::ownsNode(double endAllowance) const {
  if (!pile_) return geometry_.inBounds();
  const double xi = geometry_.xi();
  if (segment_ == 0 && xi < -endAllowance) return false;
  if (segment_ == pile_->numSegments() - 1 && xi > 1.0 + endAllowance) return false;
  return true;
}

int BeamContactElement::handOver(Vector3 base[2]) {
  const int last = pile_->numSegments() - 1;
  int moved = 0;
  while (moved <= last) {
    const double xi = geometry_.xi();
    const int direction = xi > 1.0 + kHandOverTolerance ? 1 : xi < -kHandOverTolerance ? -1 : 0;
    const int next = segment_ + direction;
    if (direction == 0 || next < 0 || next > last) break;  // held here, or beyond the pile's end
    // Start the projection where the node continues on the next segment.
    const double scale = pile_->segmentLength(segment_) / pile_->segmentLength(next);
    const double xiStart = direction > 0 ? (xi - 1.0) * scale : 1.0 + xi * scale;
    BeamContactGeometry candidate = geometry_;
    candidate.initialize(pile_->node(next), pile_->node(next + 1), nodeS(), pile_->frame(next, next),
                         pile_->frame(next + 1, next), radius_, xiStart);
    // Outside a kink the node may lie beyond both segments (its closest pile
    // point is the shared node): keep the current owner rather than letting
    // the node flip between the two at every commit.
    const double xiNext = candidate.xi();
    if (direction > 0 ? xiNext < -kHandOverTolerance : xiNext > 1.0 + kHandOverTolerance) break;
    // The friction state in the new surface coordinates: map(beta, alpha) =
    // g'^beta . g_alpha keeps the physical elastic slip s_e^alpha g_alpha.
    Matrix2 map;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) map(b, a) = candidate.contravariantBase(b).dot(base[a]);
    material_->changeSurfaceCoordinates(map, candidate.metric());
    base[0] = candidate.covariantBase(0);
    base[1] = candidate.covariantBase(1);
    geometry_ = candidate;
    segment_ = next;
    ++moved;
  }
  if (moved > 0) {
    std::vector<int> tags = nodeTags();
    tags[0] = pile_->nodeTags()[segment_];
    tags[1] = pile_->nodeTags()[segment_ + 1];
    reconnect(std::move(tags));
    handOvers_ += moved;
  }
  return moved;
}

void BeamContactElement::updateGeometry() { geometry_.update(nodeA(), nodeB(), nodeS()); }

BeamContactElement::Status BeamContactElement::status() const {
  if (!activeInUpdate_) return Status::Separated;
  return material_->sliding() || slidingAcrossHandOver_ ? Status::Sliding : Status::Sticking;
}

void BeamContactElement::storeResponseState() {
  const BeamContactGeometry& g = geometry_;
  slidingAcrossHandOver_ = false;
  gapAtUpdate_ = g.gap();
  xiAtUpdate_ = g.xi();
  normalAtUpdate_ = g.normal();
  if (!activeInUpdate_) {
    frictionForce_.setZero();
    forceScalars_.setZero();
    slipIncrement_.setZero();
    surfaceTraction_.setZero();
    surfaceSlip_.setZero();
    return;
  }
  const Vector2& T = material_->traction();
  const double lengthXi = g.covariantBase(0).norm(), lengthPsi = g.covariantBase(1).norm();
  frictionForce_ = -(T(0) * g.contravariantBase(0) + T(1) * g.contravariantBase(1));
  forceScalars_ = Vector3(normalForce_, -T(0) / lengthXi, -T(1) / lengthPsi);
  slipIncrement_ = Vector2(g.slip()(0) * lengthXi, g.slip()(1) * lengthPsi);
  surfaceTraction_ = T;
  surfaceSlip_ = g.slip();
}

void BeamContactElement::commitState() {
  committedSlip_ += slipIncrement_;
  slipIncrement_.setZero();
  const double convergedGap = geometry_.gap();
  const bool convergedSliding = status() == Status::Sliding;
  // The base the step's elastic slip is expressed in (held projection data):
  // the hand-over maps the friction state from it, not from the re-projected
  // one, whose metric differs slightly on a stretched or bent segment.
  Vector3 heldBase[2] = {geometry_.covariantBase(0), geometry_.covariantBase(1)};
  material_->commitState();
  int moved = 0;
  try {
    if (pile_) {
      pile_->synchronize();  // the frames advance once per commit, whichever element comes first
      geometry_.commit(nodeA(), nodeB(), nodeS(), pile_->frame(segment_, segment_),
                       pile_->frame(segment_ + 1, segment_));
      moved = handOver(heldBase);
    } else {
      geometry_.commit(nodeA(), nodeB(), nodeS());
    }
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  const bool nextStatus = nextContactStatus(convergedGap);
  // Forces and tangent on the new segment's dofs before anything reads them
  // (an integrator may form the tangent before the step's first update). They
  // are evaluated with the step's status, so that a handed-over element, like
  // every other one, shows the converged state until the next step's first
  // update, also when its status changes at this commit.
  if (moved > 0) {
    update();
    slidingAcrossHandOver_ = convergedSliding && activeInUpdate_;
  }
  inContact_ = nextStatus;
}

void BeamContactElement::revertToLastCommit() { material_->revertToLastCommit(); }

void BeamContactElement::revertToStart() {
  material_->revertToStart();
  try {
    if (pile_) {
      pile_->revertToStart();
      if (segment_ != initialSegment_) {
        segment_ = initialSegment_;
        std::vector<int> tags = nodeTags();
        tags[0] = pile_->nodeTags()[segment_];
        tags[1] = pile_->nodeTags()[segment_ + 1];
        reconnect(std::move(tags));
      }
      handOvers_ = 0;
      pile_->synchronize();
      initializeOnPile(std::numeric_limits<double>::quiet_NaN());
    } else {
      transf_->revertToStart();
      geometry_.initialize(nodeA(), nodeB(), nodeS(), transf_->localAxes(), radius_);
    }
  } catch (const OpenSeesError& e) {
    throw OpenSeesError(context() + ": " + e.what());
  }
  inContact_ = initiallyInContact_ && ownsNode(kHandOverTolerance);
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
  // OpenSees reports the friction acting on the pile (a pile pulled up reads
  // a downward force); the friction acting on the soil node is ours.
  if (what == "frictionforce")
    return Response::named({"Fx", "Fy", "Fz"}, [this] { return withoutNegativeZeros(Vector3(-frictionForce())); });
  if (what == "soilfrictionforce")
    return Response::named({"Fx", "Fy", "Fz"}, [this] { return withoutNegativeZeros(frictionForce()); });
  if (what == "forcescalar")
    return Response::named({"N", "T1", "T2"}, [this] { return withoutNegativeZeros(surfaceForceScalars()); });
  if (what == "physicalforcescalar")
    return Response::named({"N", "T_axial", "T_circ"}, [this] { return withoutNegativeZeros(forceScalars()); });
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
  if (what == "slip") return Response::named({"s_xi", "s_psi"}, [this] { return withoutNegativeZeros(surfaceSlip()); });
  if (what == "totalslip")
    return Response::named({"s_axial", "s_circ"}, [this] { return withoutNegativeZeros(totalSlip()); });
  if (what == "gap") return Response::named({"gap"}, [this] { return vectorOf({gap()}); });
  if (what == "status")
    return Response::named({"status"}, [this] { return vectorOf({double(static_cast<int>(status()))}); });
  if (what == "xi") return Response::named({"xi"}, [this] { return vectorOf({xi()}); });
  if (what == "normal") return Response::named({"nx", "ny", "nz"}, [this] { return withoutNegativeZeros(normal()); });
  if (what == "segment")
    return Response::named({"iNode", "jNode"},
                           [this] { return vectorOf({double(nodeTags()[0]), double(nodeTags()[1])}); });
  if (what == "handovers")
    return Response::named({"handovers"}, [this] { return vectorOf({double(handOvers_)}); });
  return {};
}

void BeamContactElement::print(std::ostream& os) const {
  os << context() << ": nodes";
  for (int t : nodeTags()) os << ' ' << t;
  os << ", radius " << radius_ << ", geomTransf " << transf_->tag() << ", nDMaterial " << material_->tag()
     << ", xi " << geometry_.xi() << ", gap " << gapAtUpdate_ << (inContact_ ? ", in contact" : ", not in contact");
  if (pile_)
    os << ", pile segment " << segment_ + 1 << " of " << pile_->numSegments() << ", " << handOvers_ << " hand-overs";
  os << '\n';
}

}  // namespace beamsolid
