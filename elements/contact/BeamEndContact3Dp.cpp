#include "elements/contact/BeamEndContact3Dp.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

BeamEndContact3Dp::BeamEndContact3Dp(int tag, int iNode, int jNode, int sNode, double radius, double penalty,
                                     int cFlag)
    : BeamEndContactElement(tag, {iNode, jNode, sNode}, radius, cFlag == 0), penalty_(penalty), activated_(cFlag == 0) {
  if (!(penalty_ > 0.0))
    throw OpenSeesError(context() + ": penalty must be positive, got " + std::to_string(penalty_));
}

void BeamEndContact3Dp::setDomain(Domain&) {
  setUpGeometry();
  update();
}

void BeamEndContact3Dp::update() {
  updateGeometry();
  stiffness_.setZero();
  activeInUpdate_ = inContact_ && gap() < 0.0;
  if (!activeInUpdate_) {
    normalForce_ = 0.0;
    mechanicalForce_.setZero();
    return;
  }
  // E6: t_n = kappa <-g>, dt_n/dq = kappa B^T, and B varies with q through H.
  const Vector15& B = gapGradient();
  const double tn = -penalty_ * gap();
  normalForce_ = tn;
  mechanicalForce_ = tn * B;
  stiffness_.noalias() = penalty_ * B * B.transpose();
  stiffness_ -= tn * gapHessian();
}

bool BeamEndContact3Dp::nextContactStatus(double) {
  if (committedGap() < 0.0) activated_ = true;
  return activated_ && withinFace();
}

void BeamEndContact3Dp::revertToStart() {
  activated_ = initiallyInContact();
  BeamEndContactElement::revertToStart();
}

namespace {

std::unique_ptr<Element> buildBeamEndContact3Dp(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element BeamEndContact3Dp " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const int sNode = args.nextInt("sNode");
  const double radius = readPositive(args, "radius");
  const double penalty = readPositive(args, "penalty");
  const int cFlag = readContactSwitch(args, "cFlag");
  args.expectEnd();
  return std::make_unique<BeamEndContact3Dp>(tag, iNode, jNode, sNode, radius, penalty, cFlag);
}

void registerBeamEndContact3Dp(Registry& r) { r.elements.add("BeamEndContact3Dp", &buildBeamEndContact3Dp); }

}  // namespace

BEAMSOLID_REGISTER(registerBeamEndContact3Dp);

}  // namespace beamsolid
