#include "analysis/ExplicitDifference.h"

#include <memory>

#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

int ExplicitDifference::newStep(AnalysisModel& model) {
  if (dt_ <= 0.0) return -1;
  cK_ = 0.0, cC_ = 0.0, cM_ = 1.0;  // the unknown is A_n+1 and the matrix M
  updates_ = 0;
  const DofMap& map = model.dofMap();
  const int n = map.numFullDofs();
  if (static_cast<int>(halfVel_.size()) != n) halfVel_.assign(n, 0.0);  // at rest: U_n-1 = U_n
  nextHalfVel_.resize(n), accelAtStart_.resize(n);
  for (int f = 0; f < n; ++f) {
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    accelAtStart_[f] = node.committedAccel()[d];
    nextHalfVel_[f] = halfVel_[f] + dt_ * accelAtStart_[f];
    // The residual P - F - M A - C V is formed at A = 0: the solve gives A_n+1.
    node.setTrialResponse(d, node.committedDisp()[d] + dt_ * nextHalfVel_[f], nextHalfVel_[f], 0.0);
  }
  Domain& domain = model.domain();
  domain.applyLoad(domain.currentTime() + dt_);
  model.enforcePrescribed();
  domain.update();
  return 0;
}

int ExplicitDifference::update(AnalysisModel& model, const Vector& x) {
  if (++updates_ > 1) return -1;  // an iterating algorithm: the scheme is explicit
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f) {
    double dx = 0.0;
    for (auto* t = map.fullTermsBegin(f); t != map.fullTermsEnd(f); ++t) dx += t->coefficient * x[t->equation];
    if (dx == 0.0) continue;
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    node.setTrialResponse(d, node.trialDisp()[d], node.trialVel()[d], node.trialAccel()[d] + dx);
  }
  return 0;
}

void ExplicitDifference::commit(AnalysisModel& model, int) {
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f) {
    Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    const double a = node.trialAccel()[d];
    node.setTrialResponse(d, node.trialDisp()[d], nextHalfVel_[f] + dt_ * (3.0 * a + accelAtStart_[f]) / 8.0, a);
  }
  halfVel_ = nextHalfVel_;
}

namespace {
std::unique_ptr<Integrator> buildExplicitDifference(CommandArgs& args, Domain&) {
  args.expectEnd();
  return std::make_unique<ExplicitDifference>();
}
void registerExplicitDifference(Registry& r) { r.integrators.add("ExplicitDifference", &buildExplicitDifference); }
}  // namespace
BEAMSOLID_REGISTER(registerExplicitDifference);

}  // namespace beamsolid
