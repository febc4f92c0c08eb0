#include "core/UniformExcitation.h"

#include "core/Domain.h"
#include "core/Node.h"
#include "elements/Element.h"

namespace beamsolid {

namespace {
// Any given series serves as the base pattern's (getLoadFactor) series.
std::shared_ptr<TimeSeries> firstOf(const std::shared_ptr<TimeSeries>& a, const std::shared_ptr<TimeSeries>& b,
                                    const std::shared_ptr<TimeSeries>& c) {
  return a ? a : (b ? b : c);
}
}  // namespace

UniformExcitation::UniformExcitation(int tag, int dof, std::shared_ptr<TimeSeries> accel,
                                     std::shared_ptr<TimeSeries> vel, std::shared_ptr<TimeSeries> disp, double fact,
                                     double vel0)
    : LoadPattern(tag, firstOf(accel, vel, disp), fact), dof_(dof), accel_(std::move(accel)), vel_(std::move(vel)),
      disp_(std::move(disp)), fact_(fact), vel0_(vel0) {}

double UniformExcitation::groundAccel(double time) const { return fact_ * value(accel_, frozen_ ? frozenTime_ : time); }
double UniformExcitation::groundVel(double time) const { return fact_ * value(vel_, frozen_ ? frozenTime_ : time); }
double UniformExcitation::groundDisp(double time) const { return fact_ * value(disp_, frozen_ ? frozenTime_ : time); }

void UniformExcitation::setLoadConst(double time) {
  LoadPattern::setLoadConst(time);
  frozen_ = true;
  frozenTime_ = time;
}

void UniformExcitation::applyLoad(Domain& domain, double time) const {
  const double ag = groundAccel(time);
  if (ag == 0.0) return;
  for (const auto& [tag, node] : domain.nodes()) {
    if (node->ndf() <= dof_ || node->mass().size() <= dof_) continue;
    const double m = node->mass()[dof_];
    if (m == 0.0) continue;
    Vector p = Vector::Zero(node->ndf());
    p[dof_] = -m;
    node->addUnbalancedLoad(p, ag);
  }
  for (const auto& [tag, element] : domain.elements()) {
    const MatrixView M = element->massMatrix();
    if (M.size() == 0 || M.isZero(0.0)) continue;
    // r_e: 1 at dof `dir` of each of the element's nodes.
    Vector r = Vector::Zero(M.cols());
    int offset = 0;
    for (const Node* n : element->nodes()) {
      if (n->ndf() > dof_ && offset + dof_ < r.size()) r[offset + dof_] = 1.0;
      offset += n->ndf();
    }
    const Vector f = -(M * r);
    offset = 0;
    for (Node* n : element->nodes()) {
      if (offset + n->ndf() <= f.size()) n->addUnbalancedLoad(f.segment(offset, n->ndf()), ag);
      offset += n->ndf();
    }
  }
}

void UniformExcitation::applyInitialVelocity(Domain& domain) const {
  if (vel0_ == 0.0) return;
  for (const auto& [tag, node] : domain.nodes()) {
    if (node->ndf() <= dof_) continue;
    bool fixed = false;
    for (const auto& sp : domain.sps()) fixed = fixed || (sp.nodeTag == tag && sp.dof == dof_);
    if (!fixed) node->setVelocity(dof_, vel0_);
  }
}

}  // namespace beamsolid
