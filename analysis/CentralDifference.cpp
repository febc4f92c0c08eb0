#include "analysis/CentralDifference.h"

#include <memory>

#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

int CentralDifference::newStep(AnalysisModel& model) {
  if (dt_ <= 0.0) return -1;
  const double dt = dt_;
  cK_ = 0.0, cC_ = 0.5 / dt, cM_ = 1.0 / (dt * dt);
  updates_ = 0;
  const DofMap& map = model.dofMap();
  const int n = map.numFullDofs();
  current_.resize(n), next_.resize(n);
  // The first step (or after a renumbering) starts at rest: U_n-1 = U_n.
  const bool start = static_cast<int>(previous_.size()) != n;
  if (start) previous_.resize(n);
  for (int f = 0; f < n; ++f) {
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    current_[f] = next_[f] = node.committedDisp()[d];
    if (start) previous_[f] = current_[f];
    node.setTrialResponse(d, current_[f], cC_ * (next_[f] - previous_[f]),
                          cM_ * (next_[f] - 2.0 * current_[f] + previous_[f]));
  }
  Domain& domain = model.domain();
  timeAtStart_ = domain.currentTime();
  domain.applyLoad(timeAtStart_);
  model.enforcePrescribed();
  domain.update();
  return 0;
}

int CentralDifference::update(AnalysisModel& model, const Vector& x) {
  if (++updates_ > 1) return -1;  // an iterating algorithm: OpenSees' scheme is linear
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f) {
    double dx = 0.0;
    for (auto* t = map.fullTermsBegin(f); t != map.fullTermsEnd(f); ++t) dx += t->coefficient * x[t->equation];
    if (dx == 0.0) continue;
    next_[f] += dx;
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    node.setTrialResponse(d, current_[f], node.trialVel()[d] + cC_ * dx, node.trialAccel()[d] + cM_ * dx);
  }
  model.domain().update();
  return 0;
}

void CentralDifference::commit(AnalysisModel& model, int) {
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f) {
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    // What OpenSees reports at t_n+1 (checked against OpenSeesPy): the
    // velocity advanced by dt A_n, the acceleration as its difference
    // quotient; the next step recomputes both from the displacements.
    const double v = node.trialVel()[d] + dt_ * node.trialAccel()[d];
    node.setTrialResponse(d, next_[f], v, (v - node.committedVel()[d]) / dt_);
  }
  previous_ = current_;
  Domain& domain = model.domain();
  domain.applyLoad(timeAtStart_ + dt_);
  domain.update();
}

namespace {
std::unique_ptr<Integrator> buildCentralDifference(CommandArgs& args, Domain&) {
  args.expectEnd();
  return std::make_unique<CentralDifference>();
}
void registerCentralDifference(Registry& r) { r.integrators.add("CentralDifference", &buildCentralDifference); }
}  // namespace
BEAMSOLID_REGISTER(registerCentralDifference);

}  // namespace beamsolid
