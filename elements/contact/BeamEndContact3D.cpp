#include "elements/contact/BeamEndContact3D.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

BeamEndContact3D::BeamEndContact3D(int tag, int iNode, int jNode, int sNode, int lNode, double radius,
                                   double gapTolerance, double forceTolerance, int cFlag)
    : BeamEndContactElement(tag, {iNode, jNode, sNode, lNode}, radius, cFlag == 0),
      multiplier_(gapTolerance, forceTolerance) {}

void BeamEndContact3D::setDomain(Domain& domain) {
  setUpGeometry();
  multiplier_.attach(*this, *nodes()[3], domain, context());
  update();
}

void BeamEndContact3D::update() {
  multiplier_.update();
  updateGeometry();
  force_.setZero();
  stiffness_.setZero();
  activeInUpdate_ = inContact_;
  if (inContact_) {
    const double lambda = multiplier_.lambda();
    const Vector15& B = gapGradient();
    normalForce_ = lambda;
    mechanicalForce_ = lambda * B;  // E5
    force_.head<15>() = mechanicalForce_;
    stiffness_.topLeftCorner<15, 15>() = -lambda * gapHessian();
    stiffness_.block<15, 1>(0, 15) = B;
    stiffness_.block<1, 15>(15, 0) = B.transpose();
  } else {
    normalForce_ = 0.0;
    mechanicalForce_.setZero();
  }
  multiplier_.setRows(force_, stiffness_, inContact_, gap());
}

bool BeamEndContact3D::nextContactStatus(double convergedGap) {
  return multiplier_.nextStatus(inContact_, convergedGap, committedGap(), withinFace());
}

namespace {

std::unique_ptr<Element> buildBeamEndContact3D(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element BeamEndContact3D " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const int sNode = args.nextInt("sNode");
  const int lNode = args.nextInt("lNode");
  const double radius = readPositive(args, "radius");
  const double gapTol = readNonNegative(args, "gapTol");
  const double forceTol = readNonNegative(args, "forceTol");
  const int cFlag = readContactSwitch(args, "cFlag");
  args.expectEnd();
  return std::make_unique<BeamEndContact3D>(tag, iNode, jNode, sNode, lNode, radius, gapTol, forceTol, cFlag);
}

void registerBeamEndContact3D(Registry& r) { r.elements.add("BeamEndContact3D", &buildBeamEndContact3D); }

}  // namespace

BEAMSOLID_REGISTER(registerBeamEndContact3D);

}  // namespace beamsolid
