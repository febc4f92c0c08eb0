#include "elements/contact/BeamContact3D.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

BeamContact3D::BeamContact3D(int tag, int iNode, int jNode, int sNode, int lNode, double radius,
                             std::unique_ptr<CrdTransf> transf, std::unique_ptr<ContactMaterial3D> material,
                             double gapTolerance, double forceTolerance, int cSwitch,
                             std::vector<int> pileNodeTags)
    : BeamContactElement(tag, {iNode, jNode, sNode, lNode}, radius, std::move(transf), std::move(material),
                         cSwitch == 0, std::move(pileNodeTags)),
      gapTolerance_(gapTolerance),
      forceTolerance_(forceTolerance) {}

void BeamContact3D::setDomain(Domain& domain) {
  const Node& l = *nodes()[3];
  if (l.ndf() != 3)
    throw OpenSeesError(context() + ": multiplier node " + std::to_string(l.tag()) + " has " +
                        std::to_string(l.ndf()) + " dofs, expected 3");
  setUpGeometry(domain);
  domain_ = &domain;
  checkMultiplierNode();
  checkedStamp_ = domain.modelStamp();  // checked; adding the element changes the stamp again
  update();
}

void BeamContact3D::checkMultiplierNode() const {
  const int l = nodeTags()[3];
  // The usual case in O(1): the only user is this element (once added) and
  // no constraint touches the node; otherwise find out what is wrong.
  const Domain::NodeUsage usage = domain_->nodeUsage(l);
  const int own = domain_->findElement(tag()) == this ? 1 : 0;
  if (usage.elements == own && usage.constraints == 0) return;
  const std::string which = ": multiplier node " + std::to_string(l);
  for (const auto& [tag, e] : domain_->elements()) {
    if (e.get() == this) continue;
    for (int t : e->nodeTags())
      if (t == l)
        throw OpenSeesError(context() + which + " is also used by element " + std::to_string(tag) +
                            "; every BeamContact3D needs its own multiplier node");
  }
  for (const auto& sp : domain_->sps())
    if (sp.nodeTag == l)
      throw OpenSeesError(context() + which + " is fixed (dof " + std::to_string(sp.dof + 1) +
                          "); the multiplier node must stay free for the contact condition to work");
  for (const auto& [ptag, p] : domain_->patterns())
    for (const auto& sp : p->sps())
      if (sp.nodeTag == l)
        throw OpenSeesError(context() + which + " has an imposed displacement in load pattern " +
                            std::to_string(ptag) + "; the multiplier node must stay free");
  for (const auto& mp : domain_->mps())
    if (mp.constrainedNode == l || mp.retainedNode == l)
      throw OpenSeesError(context() + which + " is tied by a multi-point constraint (" + mp.kind +
                          "); the multiplier node must stay free");
}

double BeamContact3D::lambda() const { return nodes()[3]->trialDisp()(0); }

void BeamContact3D::update() {
  // The model may have changed since the last check (elements, fixes):
  // the Domain's node-usage count makes the check O(1).
  if (domain_ && domain_->modelStamp() != checkedStamp_) {
    checkMultiplierNode();
    checkedStamp_ = domain_->modelStamp();
  }
  updateGeometry();
  const Vector& l = nodes()[3]->trialDisp();
  const double lambda = l(0);
  shouldRelease_ = lambda <= -forceTolerance_;  // C20, evaluated at every update

  force_.setZero();
  stiffness_.setZero();
  activeInUpdate_ = inContact_;
  if (inContact_) {
    const BeamContactGeometry& g = geometry_;
    material_->setTrialState(g.gap(), g.slip(), lambda, g.metric());
    const Vector2& T = material_->traction();
    const auto& Bn = g.gapGradient();
    const auto& Bs = g.slipGradient();
    normalForce_ = lambda;
    mechanicalForce_.noalias() = lambda * Bn + Bs * T;  // C17
    force_.head<15>() = mechanicalForce_;
    force_(15) = -g.gap();
    // C18: K_qq = B_s C_ss B_s^T, K_q,lambda = B_n + B_s C_s,lambda, K_lambda,q = B_n^T.
    stiffness_.topLeftCorner<15, 15>().noalias() = Bs * material_->tangentSlip() * Bs.transpose();
    stiffness_.block<15, 1>(0, 15).noalias() = Bn + Bs * material_->tangentNormal();
    stiffness_.block<1, 15>(15, 0) = Bn.transpose();
  } else {
    material_->release();
    normalForce_ = 0.0;
    mechanicalForce_.setZero();
    force_(15) = lambda;
    stiffness_(15, 15) = 1.0;
  }
  // The two inert multiplier dofs.
  force_(16) = l(1);
  force_(17) = l(2);
  stiffness_(16, 16) = 1.0;
  stiffness_(17, 17) = 1.0;
  storeResponseState();
}

bool BeamContact3D::nextContactStatus(double convergedGap) {
  const double gap = inContact_ ? convergedGap : geometry_.committedGap();
  const bool wasInContact = gap < gapTolerance_;
  return wasInContact && !shouldRelease_ && ownsNode();
}

namespace {

std::unique_ptr<Element> buildBeamContact3D(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element BeamContact3D " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const int sNode = args.nextInt("sNode");
  const int lNode = args.nextInt("lNode");
  std::size_t at = args.position();
  const double radius = args.nextDouble("radius");
  if (!(radius > 0.0)) args.failAt(at, "radius", "a positive number");
  const int transfTag = args.nextInt("transfTag");
  const int matTag = args.nextInt("matTag");
  at = args.position();
  const double gapTol = args.nextDouble("gapTol");
  if (!(gapTol >= 0.0)) args.failAt(at, "gapTol", "a number >= 0");
  at = args.position();
  const double forceTol = args.nextDouble("forceTol");
  if (!(forceTol >= 0.0)) args.failAt(at, "forceTol", "a number >= 0");
  int cSwitch = 0;
  if (!args.done() && !args.nextIsString()) {
    at = args.position();
    cSwitch = args.nextInt("cSwitch");
    if (cSwitch != 0 && cSwitch != 1)
      args.failAt(at, "cSwitch", "0 (initially in contact) or 1 (initially not in contact)");
  }
  std::vector<int> pile;
  if (args.nextFlag("-pile")) pile = args.nextInts("pile beam node tags", 2);
  args.expectEnd();
  auto transf = domain.geomTransfs.get(transfTag, args.context()).clone();
  auto material = cloneContactMaterial(domain.ndMaterials.get(matTag, args.context()), args.context());
  return std::make_unique<BeamContact3D>(tag, iNode, jNode, sNode, lNode, radius, std::move(transf),
                                         std::move(material), gapTol, forceTol, cSwitch, std::move(pile));
}

void registerBeamContact3D(Registry& r) { r.elements.add("BeamContact3D", &buildBeamContact3D); }

}  // namespace

BEAMSOLID_REGISTER(registerBeamContact3D);

}  // namespace beamsolid
