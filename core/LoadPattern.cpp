#include "core/LoadPattern.h"

#include <algorithm>

#include "core/Domain.h"
#include "core/Node.h"
#include "elements/Element.h"

namespace beamsolid {

LoadPattern::LoadPattern(int tag, std::shared_ptr<TimeSeries> series, double scale)
    : tag_(tag), series_(std::move(series)), scale_(scale) {}

bool LoadPattern::removeSP(int nodeTag, int dof) {
  auto it = std::remove_if(sps_.begin(), sps_.end(),
                           [&](const SPConstraint& s) { return s.nodeTag == nodeTag && s.dof == dof; });
  bool removed = it != sps_.end();
  sps_.erase(it, sps_.end());
  spDofs_.erase(dofKey(nodeTag, dof));
  return removed;
}

double LoadPattern::factor(double time) const {
  return constant_ ? constFactor_ : scale_ * series_->factor(time);
}

double LoadPattern::factorSlope(double time) const {
  return constant_ ? 0.0 : scale_ * series_->slope(time);
}

void LoadPattern::setLoadConst(double time) {
  constFactor_ = factor(time);
  constant_ = true;
}

void LoadPattern::applyLoad(Domain& domain, double time) const {
  const double f = factor(time);
  for (const auto& nl : nodalLoads_)
    if (Node* n = domain.findNode(nl.nodeTag)) n->addUnbalancedLoad(nl.load, f);
  for (const auto& el : elementLoads_)
    if (Element* e = domain.findElement(el.elementTag)) e->addLoad(el.load, f);
}

void LoadPattern::removeReferencesTo(int nodeTag, int elementTag) {
  nodalLoads_.erase(std::remove_if(nodalLoads_.begin(), nodalLoads_.end(),
                                   [&](const NodalLoad& l) { return l.nodeTag == nodeTag; }),
                    nodalLoads_.end());
  sps_.erase(std::remove_if(sps_.begin(), sps_.end(),
                            [&](const SPConstraint& s) {
                              if (s.nodeTag != nodeTag) return false;
                              spDofs_.erase(dofKey(s.nodeTag, s.dof));
                              return true;
                            }),
             sps_.end());
  elementLoads_.erase(std::remove_if(elementLoads_.begin(), elementLoads_.end(),
                                     [&](const EleLoad& l) { return l.elementTag == elementTag; }),
                      elementLoads_.end());
}

}  // namespace beamsolid
