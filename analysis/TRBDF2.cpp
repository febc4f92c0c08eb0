#include "analysis/TRBDF2.h"

#include <memory>

#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

int TRBDF2::newStep(AnalysisModel& model) {
  if (dt_ <= 0.0) return -1;
  const double dt = dt_;
  const DofMap& map = model.dofMap();
  const int n = map.numFullDofs();
  if (static_cast<int>(uPrev_.size()) != n) step_ = 0;
  u1_.resize(n), v1_.resize(n), a1_.resize(n), uLast_.resize(n), vLast_.resize(n);
  if (backward()) {
    cv_ = 1.5 / dt, ca_ = cv_ * cv_;
  } else {
    cv_ = 2.0 / dt, ca_ = 4.0 / (dt * dt);
  }
  cK_ = 1.0, cC_ = cv_, cM_ = ca_;
  for (int f = 0; f < n; ++f) {
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    const double u = node.committedDisp()[d], v = node.committedVel()[d], a = node.committedAccel()[d];
    uLast_[f] = u, vLast_[f] = v;
    u1_[f] = u;
    if (backward()) {
      v1_[f] = (3.0 * u - 4.0 * u + uPrev_[f]) / (2.0 * dt);
      a1_[f] = (3.0 * v1_[f] - 4.0 * v + vPrev_[f]) / (2.0 * dt);
    } else {
      v1_[f] = -v;  // trapezoidal with U_n+1 = U_n
      a1_[f] = -4.0 * v / dt - a;
    }
    node.setTrialResponse(d, u1_[f], v1_[f], a1_[f]);
  }
  Domain& domain = model.domain();
  domain.applyLoad(domain.currentTime() + dt);
  model.enforcePrescribed();
  domain.update();
  return 0;
}

int TRBDF2::update(AnalysisModel& model, const Vector& x) {
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f) {
    double dx = 0.0;
    for (auto* t = map.fullTermsBegin(f); t != map.fullTermsEnd(f); ++t) dx += t->coefficient * x[t->equation];
    if (dx == 0.0) continue;
    u1_[f] += dx;
    v1_[f] += cv_ * dx;
    a1_[f] += ca_ * dx;
    map.nodeOfFull(f)->setTrialResponse(map.dofOfFull(f), u1_[f], v1_[f], a1_[f]);
  }
  model.domain().update();
  return 0;
}

void TRBDF2::commit(AnalysisModel&, int) {
  uPrev_ = uLast_;
  vPrev_ = vLast_;
  ++step_;
}

namespace {
std::unique_ptr<Integrator> buildTRBDF2(CommandArgs& args, Domain&) {
  args.expectEnd();
  return std::make_unique<TRBDF2>();
}
void registerTRBDF2(Registry& r) { r.integrators.add("TRBDF2", &buildTRBDF2); }
}  // namespace
BEAMSOLID_REGISTER(registerTRBDF2);

}  // namespace beamsolid
