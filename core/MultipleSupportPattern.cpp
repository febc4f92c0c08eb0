#include "core/MultipleSupportPattern.h"

#include "core/ConstantSeries.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

MultipleSupportPattern::MultipleSupportPattern(int tag)
    : LoadPattern(tag, std::make_shared<ConstantSeries>(-1, 1.0)) {}

void MultipleSupportPattern::addGroundMotion(std::unique_ptr<GroundMotion> motion, const std::string& context) {
  const int tag = motion->tag();
  if (motions_.count(tag))
    throw OpenSeesError(context + ": ground motion " + std::to_string(tag) + " already exists in pattern " +
                        std::to_string(this->tag()));
  motions_.emplace(tag, std::move(motion));
}

const GroundMotion& MultipleSupportPattern::groundMotion(int tag, const std::string& context) const {
  auto it = motions_.find(tag);
  if (it == motions_.end())
    throw OpenSeesError(context + ": ground motion " + std::to_string(tag) + " does not exist in pattern " +
                        std::to_string(this->tag()));
  return *it->second;
}

void MultipleSupportPattern::addImposedMotion(int nodeTag, int dof, int gmTag, const std::string& context) {
  groundMotion(gmTag, context);
  addSP(SPConstraint{nodeTag, dof, 0.0, tag()});
  motionOf_[{nodeTag, dof}] = gmTag;
}

double MultipleSupportPattern::imposedValue(const SPConstraint& sp, double time) const {
  auto it = motionOf_.find({sp.nodeTag, sp.dof});
  if (it == motionOf_.end()) return factor(time) * sp.value;
  return motions_.at(it->second)->disp(time);
}

void MultipleSupportPattern::applyLoad(Domain& domain, double time) const {
  LoadPattern::applyLoad(domain, time);
  for (const auto& [key, gmTag] : motionOf_) {
    Node* n = domain.findNode(key.first);
    if (!n) continue;
    const GroundMotion& gm = *motions_.at(gmTag);
    Vector v = n->trialVel(), a = n->trialAccel();
    v[key.second] = gm.vel(time);
    a[key.second] = gm.accel(time);
    n->setTrialVel(v);
    n->setTrialAccel(a);
  }
}

}  // namespace beamsolid
