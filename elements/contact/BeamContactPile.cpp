#include "elements/contact/BeamContactPile.h"

#include <set>

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/transforms/CrdTransf.h"

namespace beamsolid {

namespace {

// exp(skew(w)): the rotation by |w| about w (C1).
Matrix3 expSkew(const Vector3& w) {
  const double angle = w.norm();
  if (angle == 0.0) return Matrix3::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

}  // namespace

BeamContactPile::BeamContactPile(const Domain& domain, std::vector<int> nodeTags, const CrdTransf& transf,
                                 const std::string& context)
    : domain_(domain), context_(context), tags_(std::move(nodeTags)) {
  if (tags_.size() < 2)
    throw OpenSeesError(context_ + ": -pile needs the pile's beam nodes in order (at least two), got " +
                        std::to_string(tags_.size()));
  std::set<int> seen;
  for (int t : tags_)
    if (!seen.insert(t).second)
      throw OpenSeesError(context_ + ": -pile lists node " + std::to_string(t) + " twice");
  resolveNodes();
  for (const Node* n : nodes_)
    if (n->ndf() != 6)
      throw OpenSeesError(context_ + ": pile node " + std::to_string(n->tag()) + " has " +
                          std::to_string(n->ndf()) + " dofs, expected 6");
  std::unique_ptr<CrdTransf> copy = transf.clone();
  for (int s = 0; s + 1 < numNodes(); ++s) {
    const Node& a = *nodes_[s];
    const Node& b = *nodes_[s + 1];
    const double length = (b.crd() - a.crd()).norm();
    if (!(length > 0.0))
      throw OpenSeesError(context_ + ": pile nodes " + std::to_string(a.tag()) + " and " + std::to_string(b.tag()) +
                          " coincide");
    try {
      copy->initialize(a, b);
    } catch (const OpenSeesError& e) {
      throw OpenSeesError(context_ + ": pile segment " + std::to_string(a.tag()) + "-" + std::to_string(b.tag()) +
                          ": " + e.what());
    }
    lengths_.push_back(length);
    referenceAxes_.push_back(copy->localAxes().transpose());
  }
  rotations_.assign(tags_.size(), Matrix3::Identity());
  thetas_.assign(tags_.size(), Vector3::Zero());
}

std::string BeamContactPile::key(int transfTag, const std::vector<int>& nodeTags) {
  std::string k = "BeamContactPile/" + std::to_string(transfTag) + ":";
  for (int t : nodeTags) k += std::to_string(t) + ",";
  return k;
}

void BeamContactPile::resolveNodes() const {
  if (resolvedStamp_ == domain_.modelStamp()) return;
  nodes_.clear();
  for (int t : tags_) {
    const Node* n = domain_.findNode(t);
    if (!n) throw OpenSeesError(context_ + ": pile node " + std::to_string(t) + " does not exist");
    nodes_.push_back(n);
  }
  resolvedStamp_ = domain_.modelStamp();
}

int BeamContactPile::segmentOf(int iNode, int jNode) const {
  for (int s = 0; s + 1 < numNodes(); ++s)
    if (tags_[s] == iNode && tags_[s + 1] == jNode) return s;
  return -1;
}

const Node& BeamContactPile::node(int k) const {
  resolveNodes();
  return *nodes_[k];
}

void BeamContactPile::synchronize() {
  resolveNodes();
  for (std::size_t k = 0; k < tags_.size(); ++k) {
    const Vector3 theta = nodes_[k]->trialDisp().segment<3>(3);
    if (theta == thetas_[k]) continue;
    rotations_[k] = expSkew(theta - thetas_[k]) * rotations_[k];
    thetas_[k] = theta;
  }
}

void BeamContactPile::revertToStart() {
  rotations_.assign(tags_.size(), Matrix3::Identity());
  thetas_.assign(tags_.size(), Vector3::Zero());
}

}  // namespace beamsolid
