#include "elements/contact/BeamContact3Dp.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

BeamContact3Dp::BeamContact3Dp(int tag, int iNode, int jNode, int sNode, double radius,
                               std::unique_ptr<CrdTransf> transf, std::unique_ptr<ContactMaterial3D> material,
                               double penalty, int cSwitch, std::vector<int> pileNodeTags)
    : BeamContactElement(tag, {iNode, jNode, sNode}, radius, std::move(transf), std::move(material), cSwitch == 0,
                         std::move(pileNodeTags)),
      penalty_(penalty),
      activated_(cSwitch == 0) {
  if (!(penalty_ > 0.0))
    throw OpenSeesError(context() + ": penalty must be positive, got " + std::to_string(penalty_));
}

void BeamContact3Dp::setDomain(Domain& domain) {
  setUpGeometry(domain);
  update();
}

void BeamContact3Dp::update() {
  updateGeometry();
  const BeamContactGeometry& g = geometry_;
  stiffness_.setZero();
  activeInUpdate_ = inContact_ && g.gap() < 0.0;
  if (!activeInUpdate_) {
    material_->release();
    normalForce_ = 0.0;
    mechanicalForce_.setZero();
    storeResponseState();
    return;
  }
  // C19: t_n = kappa <-g>.
  const double tn = -penalty_ * g.gap();
  material_->setIterate(g.gap(), g.slip(), tn, g.metric());
  const auto& Bn = g.gapGradient();
  const auto& Bs = g.slipGradient();
  normalForce_ = tn;
  mechanicalForce_.noalias() = tn * Bn + Bs * material_->traction();
  // dt_n/dq = kappa B_n^T; friction depends on t_n through C_sn.
  stiffness_.noalias() = penalty_ * Bn * Bn.transpose();
  stiffness_.noalias() += Bs * material_->tangentSlip() * Bs.transpose();
  stiffness_.noalias() += (penalty_ * Bs * material_->tangentNormal()) * Bn.transpose();
  storeResponseState();
}

bool BeamContact3Dp::nextContactStatus(double) {
  if (geometry_.committedGap() < 0.0) activated_ = true;
  return activated_ && ownsNode();
}

void BeamContact3Dp::revertToStart() {
  activated_ = initiallyInContact();
  BeamContactElement::revertToStart();
}

namespace {

std::unique_ptr<Element> buildBeamContact3Dp(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element BeamContact3Dp " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const int sNode = args.nextInt("sNode");
  const double radius = readPositive(args, "radius");
  const int transfTag = args.nextInt("transfTag");
  const int matTag = args.nextInt("matTag");
  const double penalty = readPositive(args, "penalty");
  const int cSwitch = args.nextIsString() ? 0 : readContactSwitch(args, "cSwitch");
  std::vector<int> pile;
  if (args.nextFlag("-pile")) pile = args.nextInts("pile beam node tags", 2);
  args.expectEnd();
  auto transf = domain.geomTransfs.get(transfTag, args.context()).clone();
  auto material = cloneContactMaterial(domain.ndMaterials.get(matTag, args.context()), args.context());
  return std::make_unique<BeamContact3Dp>(tag, iNode, jNode, sNode, radius, std::move(transf), std::move(material),
                                          penalty, cSwitch, std::move(pile));
}

void registerBeamContact3Dp(Registry& r) { r.elements.add("BeamContact3Dp", &buildBeamContact3Dp); }

}  // namespace

BEAMSOLID_REGISTER(registerBeamContact3Dp);

}  // namespace beamsolid
