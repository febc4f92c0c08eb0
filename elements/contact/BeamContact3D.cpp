#include "elements/contact/BeamContact3D.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/contact/ContactSupport.h"

namespace beamsolid {

BeamContact3D::BeamContact3D(int tag, int iNode, int jNode, int sNode, int lNode, double radius,
                             std::unique_ptr<CrdTransf> transf, std::unique_ptr<ContactMaterial3D> material,
                             double gapTolerance, double forceTolerance, int cSwitch,
                             std::vector<int> pileNodeTags)
    : BeamContactElement(tag, {iNode, jNode, sNode, lNode}, radius, std::move(transf), std::move(material),
                         cSwitch == 0, std::move(pileNodeTags)),
      multiplier_(gapTolerance, forceTolerance) {}

void BeamContact3D::setDomain(Domain& domain) {
  domain_ = &domain;
  targetValid_ = false;
  setUpGeometry(domain);
  multiplier_.attach(*this, *nodes()[3], domain, context());
  update();
}

double BeamContact3D::gapTarget() {
  if (!domain_ || !domain_->transient()) {
    targetValid_ = false;
    return 0.0;
  }
  const double now = domain_->currentTime();
  if (targetValid_ && now == targetTime_) return target_;
  // gdot_n = -B_n . v_n and gddot_n = -B_n . a_n (B_n = -dg/dq, C18), from
  // the nodes' committed velocities and accelerations.
  const auto& Bn = geometry_.gapGradient();
  double gdot = 0.0, gddot = 0.0;
  const Node* nodes3[3] = {&nodeA(), &nodeB(), &nodeS()};
  int k = 0;
  for (int a = 0; a < 3; ++a) {
    const Vector& v = nodes3[a]->committedVel();
    const Vector& acc = nodes3[a]->committedAccel();
    const int n = a < 2 ? 6 : 3;
    for (int i = 0; i < n; ++i, ++k) {
      gdot -= Bn(k) * v(i);
      gddot -= Bn(k) * acc(i);
    }
  }
  // Trapezoidal rule: the target g_n + 3/4 dt gdot_n + dt^2/8 gddot_n halves
  // the normal velocity in the first step in contact and brings velocity and
  // acceleration to rest in the second (without it, holding g = g_n + dt/2
  // gdot_n stops the node in one step but leaves an acceleration of
  // -2 gdot_n/dt that alternates in sign every step and pulls on the
  // contact). In steady contact (gdot = gddot = 0) it holds g_n.
  // The penetration a landing node reached while open is kept, not pushed
  // out (working it off, even a fifth per step, fed energy into the chatter).
  const double dt = now - domain_->committedTime();
  target_ = geometry_.committedGap() + 0.75 * dt * gdot + 0.125 * dt * dt * gddot;
  targetTime_ = now;
  targetValid_ = true;
  return target_;
}

void BeamContact3D::update() {
  multiplier_.update();
  updateGeometry();
  const double lambda = multiplier_.lambda();

  force_.setZero();
  stiffness_.setZero();
  activeInUpdate_ = inContact_;
  if (inContact_) {
    const BeamContactGeometry& g = geometry_;
    material_->setIterate(g.gap(), g.slip(), lambda, g.metric());
    const Vector2& T = material_->traction();
    const auto& Bn = g.gapGradient();
    const auto& Bs = g.slipGradient();
    normalForce_ = lambda;
    mechanicalForce_.noalias() = lambda * Bn + Bs * T;  // C17
    force_.head<15>() = mechanicalForce_;
    // C18: K_qq = B_s C_ss B_s^T, K_q,lambda = B_n + B_s C_s,lambda, K_lambda,q = B_n^T.
    stiffness_.topLeftCorner<15, 15>().noalias() = Bs * material_->tangentSlip() * Bs.transpose();
    stiffness_.block<15, 1>(0, 15).noalias() = Bn + Bs * material_->tangentNormal();
    stiffness_.block<1, 15>(15, 0) = Bn.transpose();
  } else {
    material_->release();
    normalForce_ = 0.0;
    mechanicalForce_.setZero();
  }
  multiplier_.setRows(force_, stiffness_, inContact_, inContact_ ? geometry_.gap() - gapTarget() : geometry_.gap());
  storeResponseState();
}

bool BeamContact3D::nextContactStatus(double convergedGap) {
  // A chained element owns its node anywhere along the pile (hand-over);
  // a single-segment element only while the projection is in bounds.
  return multiplier_.nextStatus(inContact_, convergedGap, geometry_.committedGap(), ownsNode());
}

namespace {

std::unique_ptr<Element> buildBeamContact3D(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element BeamContact3D " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const int sNode = args.nextInt("sNode");
  const int lNode = args.nextInt("lNode");
  const double radius = readPositive(args, "radius");
  const int transfTag = args.nextInt("transfTag");
  const int matTag = args.nextInt("matTag");
  const double gapTol = readNonNegative(args, "gapTol");
  const double forceTol = readNonNegative(args, "forceTol");
  const int cSwitch = args.nextIsString() ? 0 : readContactSwitch(args, "cSwitch");
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
