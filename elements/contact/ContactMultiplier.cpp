#include "elements/contact/ContactMultiplier.h"

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/Element.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

void ContactMultiplier::attach(const Element& owner, const Node& node, const Domain& domain, std::string context) {
  owner_ = &owner;
  node_ = &node;
  domain_ = &domain;
  context_ = std::move(context);
  requireNodeDofs(node, 3, "multiplier node", context_);
  check();
  // The stamp is taken at the first update, after the domain has finished
  // adding the element.
  checkedStamp_ = -1;
}

void ContactMultiplier::check() const {
  const int l = node_->tag();
  // The usual case in O(1): the only user is the owner (once added) and no
  // constraint touches the node; otherwise find out what is wrong and say so.
  const Domain::NodeUsage usage = domain_->nodeUsage(l);
  const int own = domain_->findElement(owner_->tag()) == owner_ ? 1 : 0;
  if (usage.elements == own && usage.constraints == 0) return;
  const std::string which = context_ + ": multiplier node " + std::to_string(l);
  for (const auto& [tag, e] : domain_->elements()) {
    if (e.get() == owner_) continue;
    for (int t : e->nodeTags())
      if (t == l)
        throw OpenSeesError(which + " is also used by element " + std::to_string(tag) + "; every " +
                            owner_->className() + " needs its own multiplier node");
  }
  for (const auto& sp : domain_->sps())
    if (sp.nodeTag == l)
      throw OpenSeesError(which + " is fixed (dof " + std::to_string(sp.dof + 1) +
                          "); the multiplier node must stay free for the contact condition to work");
  for (const auto& [ptag, p] : domain_->patterns())
    for (const auto& sp : p->sps())
      if (sp.nodeTag == l)
        throw OpenSeesError(which + " has an imposed displacement in load pattern " + std::to_string(ptag) +
                            "; the multiplier node must stay free");
  for (const auto& mp : domain_->mps())
    if (mp.constrainedNode == l || mp.retainedNode == l)
      throw OpenSeesError(which + " is tied by a multi-point constraint (" + mp.kind +
                          "); the multiplier node must stay free");
}

void ContactMultiplier::update() {
  if (!node_) return;
  // The model may have changed since the last check (elements, fixes).
  if (domain_->modelStamp() != checkedStamp_) {
    check();
    checkedStamp_ = domain_->modelStamp();
  }
  const Vector& l = node_->trialDisp();
  lambda_ = l(0);
  inert_[0] = l(1);
  inert_[1] = l(2);
  shouldRelease_ = lambda_ <= -forceTolerance_;  // C20, evaluated at every update
}

}  // namespace beamsolid
