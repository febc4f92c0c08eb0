#include "core/Domain.h"

#include <algorithm>
#include <exception>
#include <iostream>
#include <set>

#include "core/OpenSeesError.h"

namespace beamsolid {

Domain::Domain() = default;

Domain::~Domain() {
  // Recorded data is never lost: close (and so flush) every recorder. An
  // exception leaving a destructor ends the process (std::terminate), so a
  // recorder that cannot write is reported on stderr instead.
  for (auto& [tag, r] : recorders_) {
    try {
      r->close();
    } catch (const std::exception& e) {
      std::cerr << "WARNING " << e.what() << '\n';
    }
  }
}

void Domain::addNode(std::unique_ptr<Node> node, const std::string& context) {
  const int tag = node->tag();
  // Scripts number nodes upwards: a tag above every other goes in at the end
  // without a search.
  if (!nodes_.empty() && nodes_.rbegin()->first >= tag && nodes_.count(tag))
    throw OpenSeesError(context + ": node " + std::to_string(tag) + " already exists");
  nodes_.emplace_hint(nodes_.end(), tag, std::move(node));
  const bool usageCurrent = nodeUsageStamp_ == modelStamp_;
  touch();
  if (usageCurrent) nodeUsageStamp_ = modelStamp_;  // a new node is used by nothing yet
}

Node* Domain::findNode(int tag) const {
  auto it = nodes_.find(tag);
  return it == nodes_.end() ? nullptr : it->second.get();
}

Node& Domain::node(int tag, const std::string& context) const {
  Node* n = findNode(tag);
  if (!n) throw OpenSeesError(context + ": node " + std::to_string(tag) + " does not exist");
  return *n;
}

void Domain::removeNode(int tag, const std::string& context) {
  node(tag, context);
  for (const auto& [etag, e] : elements_)
    for (int nt : e->nodeTags())
      if (nt == tag)
        throw OpenSeesError(context + ": node " + std::to_string(tag) + " is used by element " +
                            std::to_string(etag) + "; remove the element first");
  sps_.erase(std::remove_if(sps_.begin(), sps_.end(), [&](const SPConstraint& s) { return s.nodeTag == tag; }),
             sps_.end());
  for (int d = 0; d < nodes_.at(tag)->ndf(); ++d) fixedDofs_.erase(dofKey(tag, d));
  mps_.erase(std::remove_if(mps_.begin(), mps_.end(),
                            [&](const MPConstraint& m) {
                              const bool gone = m.constrainedNode == tag || m.retainedNode == tag;
                              if (gone)
                                for (int d : m.constrainedDofs) mpConstrainedDofs_.erase(dofKey(m.constrainedNode, d));
                              return gone;
                            }),
             mps_.end());
  for (auto& [ptag, p] : patterns_) p->removeReferencesTo(tag, -1);
  nodes_.erase(tag);
  touch();
}

void Domain::addElement(std::unique_ptr<Element> element, const std::string& context) {
  const int tag = element->tag();
  if (!elements_.empty() && elements_.rbegin()->first >= tag && elements_.count(tag))
    throw OpenSeesError(context + ": element " + std::to_string(tag) + " already exists");
  if (!element->supportsSpace(spaceDim()))
    throw OpenSeesError(context + ": element type " + element->className() + " does not work in a " +
                        std::to_string(spaceDim()) + "D model (-ndm " + std::to_string(spaceDim()) + ")" +
                        (spaceDim() == 3 ? std::string() : std::string(": it is a 3D element (-ndm 3)")));
  element->connect(*this);
  // (connect() may have refreshed the usage cache; this element is not in it yet.)
  const bool usageCurrent = nodeUsageStamp_ == modelStamp_;
  const Element& added = *element;
  elements_.emplace_hint(elements_.end(), tag, std::move(element));
  touch();
  if (usageCurrent) {
    for (int t : added.nodeTags()) ++nodeUsage_[t].elements;
    nodeUsageStamp_ = modelStamp_;
  }
}

void Domain::nodeMoved(int tag, const std::string& context) {
  for (const auto& [eleTag, e] : elements_) {
    const auto& nodes = e->nodeTags();
    if (std::find(nodes.begin(), nodes.end(), tag) == nodes.end()) continue;
    try {
      e->connect(*this);  // re-reads the nodes and the geometry
    } catch (const OpenSeesError& error) {
      throw OpenSeesError(context + ": element " + std::to_string(eleTag) + " cannot take the new position: " +
                          error.what());
    }
  }
  touch();
}

const Domain::Region& Domain::region(int tag, const std::string& context) const {
  auto it = regions_.find(tag);
  if (it == regions_.end()) throw OpenSeesError(context + ": region " + std::to_string(tag) + " does not exist");
  return it->second;
}

Element* Domain::findElement(int tag) const {
  auto it = elements_.find(tag);
  return it == elements_.end() ? nullptr : it->second.get();
}

Element& Domain::element(int tag, const std::string& context) const {
  Element* e = findElement(tag);
  if (!e) throw OpenSeesError(context + ": element " + std::to_string(tag) + " does not exist");
  return *e;
}

void Domain::removeElement(int tag, const std::string& context) {
  element(tag, context);
  for (auto& [ptag, p] : patterns_) p->removeReferencesTo(-1, tag);
  const bool usageCurrent = nodeUsageStamp_ == modelStamp_;
  if (usageCurrent)
    for (int t : elements_.at(tag)->nodeTags()) --nodeUsage_[t].elements;
  elements_.erase(tag);
  touch();
  if (usageCurrent) nodeUsageStamp_ = modelStamp_;
}

void Domain::elementReconnected(const Element& e, const std::vector<int>& oldTags) {
  // An element being connected (not yet added) is not counted.
  const bool counted = findElement(e.tag()) == &e;
  const bool usageCurrent = nodeUsageStamp_ == modelStamp_;
  if (usageCurrent && counted) {
    for (int t : oldTags) --nodeUsage_[t].elements;
    for (int t : e.nodeTags()) ++nodeUsage_[t].elements;
  }
  touch();
  if (usageCurrent) nodeUsageStamp_ = modelStamp_;
}

Domain::NodeUsage Domain::nodeUsage(int nodeTag) const {
  if (nodeUsageStamp_ != modelStamp_) {
    nodeUsage_.clear();
    for (const auto& [tag, e] : elements_)
      for (int t : e->nodeTags()) ++nodeUsage_[t].elements;
    for (const auto& sp : sps_) ++nodeUsage_[sp.nodeTag].constraints;
    for (const auto& [tag, p] : patterns_)
      for (const auto& sp : p->sps()) ++nodeUsage_[sp.nodeTag].constraints;
    for (const auto& mp : mps_) {
      ++nodeUsage_[mp.constrainedNode].constraints;
      ++nodeUsage_[mp.retainedNode].constraints;
    }
    nodeUsageStamp_ = modelStamp_;
  }
  auto it = nodeUsage_.find(nodeTag);
  return it == nodeUsage_.end() ? NodeUsage{} : it->second;
}

void Domain::addSP(const SPConstraint& sp, const std::string& context) {
  Node& n = node(sp.nodeTag, context);
  if (sp.dof < 0 || sp.dof >= n.ndf())
    throw OpenSeesError(context + ": dof " + std::to_string(sp.dof + 1) + " is out of range for node " +
                        std::to_string(sp.nodeTag) + " (ndf " + std::to_string(n.ndf()) + ")");
  if (!fixedDofs_.insert(dofKey(sp.nodeTag, sp.dof)).second)
    throw OpenSeesError(context + ": node " + std::to_string(sp.nodeTag) + " dof " + std::to_string(sp.dof + 1) +
                        " is already fixed");
  sps_.push_back(sp);
  touch();
}

bool Domain::removeSP(int nodeTag, int dof) {
  auto it = std::remove_if(sps_.begin(), sps_.end(),
                           [&](const SPConstraint& s) { return s.nodeTag == nodeTag && s.dof == dof; });
  bool removed = it != sps_.end();
  sps_.erase(it, sps_.end());
  fixedDofs_.erase(dofKey(nodeTag, dof));
  for (auto& [ptag, p] : patterns_) removed = p->removeSP(nodeTag, dof) || removed;
  if (removed) touch();
  return removed;
}

void Domain::addMP(MPConstraint mp, const std::string& context) {
  if (mp.retainedNode == mp.constrainedNode)
    throw OpenSeesError(context + ": retained and constrained node are the same (" +
                        std::to_string(mp.retainedNode) + ")");
  Node& r = node(mp.retainedNode, context);
  Node& c = node(mp.constrainedNode, context);
  for (int d : mp.retainedDofs)
    if (d < 0 || d >= r.ndf())
      throw OpenSeesError(context + ": dof " + std::to_string(d + 1) + " is out of range for retained node " +
                          std::to_string(r.tag()));
  for (int d : mp.constrainedDofs) {
    if (d < 0 || d >= c.ndf())
      throw OpenSeesError(context + ": dof " + std::to_string(d + 1) +
                          " is out of range for constrained node " + std::to_string(c.tag()));
    if (mpConstrainedDofs_.count(dofKey(c.tag(), d)))
      throw OpenSeesError(context + ": dof " + std::to_string(d + 1) + " of node " + std::to_string(c.tag()) +
                          " is already constrained by another multi-point constraint");
  }
  for (int d : mp.constrainedDofs) mpConstrainedDofs_.insert(dofKey(c.tag(), d));
  mp.tag = nextMPTag_++;
  mps_.push_back(std::move(mp));
  touch();
}

bool Domain::removeMP(int constrainedNode) {
  for (const MPConstraint& m : mps_)
    if (m.constrainedNode == constrainedNode)
      for (int d : m.constrainedDofs) mpConstrainedDofs_.erase(dofKey(constrainedNode, d));
  auto it = std::remove_if(mps_.begin(), mps_.end(),
                           [&](const MPConstraint& m) { return m.constrainedNode == constrainedNode; });
  bool removed = it != mps_.end();
  mps_.erase(it, mps_.end());
  if (removed) touch();
  return removed;
}

void Domain::addPattern(std::unique_ptr<LoadPattern> pattern, const std::string& context) {
  const int tag = pattern->tag();
  if (patterns_.count(tag))
    throw OpenSeesError(context + ": load pattern " + std::to_string(tag) + " already exists");
  patterns_.emplace(tag, std::move(pattern));
  touch();
}

LoadPattern* Domain::findPattern(int tag) const {
  auto it = patterns_.find(tag);
  return it == patterns_.end() ? nullptr : it->second.get();
}

LoadPattern& Domain::pattern(int tag, const std::string& context) const {
  LoadPattern* p = findPattern(tag);
  if (!p) throw OpenSeesError(context + ": load pattern " + std::to_string(tag) + " does not exist");
  return *p;
}

bool Domain::removePattern(int tag) {
  bool removed = patterns_.erase(tag) > 0;
  if (removed) touch();
  return removed;
}

std::vector<Domain::ImposedValue> Domain::imposedValues(double time) const {
  std::vector<ImposedValue> out;
  for (const auto& sp : sps_) out.push_back({sp.nodeTag, sp.dof, sp.value});
  for (const auto& [tag, p] : patterns_) {
    for (const auto& sp : p->sps()) out.push_back({sp.nodeTag, sp.dof, p->imposedValue(sp, time)});
  }
  return out;
}

int Domain::addRecorder(std::unique_ptr<Recorder> recorder) {
  const int tag = nextRecorderTag_++;
  recorders_.emplace(tag, std::move(recorder));
  return tag;
}

bool Domain::removeRecorder(int tag) {
  auto it = recorders_.find(tag);
  if (it == recorders_.end()) return false;
  // Removed even when closing fails: the failure is raised here, once.
  std::unique_ptr<Recorder> recorder = std::move(it->second);
  recorders_.erase(it);
  recorder->close();
  return true;
}

void Domain::removeRecorders() {
  // Every recorder is closed and removed even when one of them fails (a
  // failure must not leave the others open, or wipe half done); the first
  // failure is raised afterwards.
  std::map<int, std::unique_ptr<Recorder>> recorders = std::move(recorders_);
  recorders_.clear();
  std::exception_ptr firstFailure;
  for (auto& [tag, r] : recorders) {
    try {
      r->close();
    } catch (...) {
      if (!firstFailure) firstFailure = std::current_exception();
    }
  }
  if (firstFailure) std::rethrow_exception(firstFailure);
}

void Domain::record() {
  for (auto& [tag, r] : recorders_) r->record(*this, currentTime_);
}

void Domain::flushRecorders() {
  for (auto& [tag, r] : recorders_) r->flush();
}

void Domain::setRayleigh(const RayleighFactors& f) {
  rayleigh_ = f;
  regionRayleigh_ = false;
  for (auto& [tag, n] : nodes_) n->clearRegionAlphaM();
  for (auto& [tag, e] : elements_) e->clearRegionRayleigh();
  keepCommittedStiffnesses();
}

void Domain::noteRegionRayleigh() {
  regionRayleigh_ = true;
  keepCommittedStiffnesses();
}

// Factors given after an analysis damp with betaKcomm times the tangent of
// the last converged state from the next step on (OpenSees does so; checked
// with a yielded truss: same response as betaK on the committed tangent).
void Domain::keepCommittedStiffnesses() {
  if (!committedOnce_ || !anyRayleigh()) return;
  for (auto& [tag, e] : elements_)
    if (e->rayleighFactors(rayleigh_).betaKcomm != 0.0) e->keepCommittedStiffness();
}

void Domain::applyLoad(double time) {
  currentTime_ = time;
  for (auto& [tag, n] : nodes_) n->zeroUnbalancedLoad();
  for (auto& [tag, e] : elements_) e->zeroLoad();
  for (auto& [tag, p] : patterns_) p->applyLoad(*this, time);
}

void Domain::update() {
  for (auto& [tag, e] : elements_) e->update();
}

void Domain::commit() {
  for (auto& [tag, n] : nodes_) n->commitState();
  for (auto& [tag, e] : elements_) e->commitState();
  // betaKcomm damps with the stiffness of the last converged state.
  committedOnce_ = true;
  keepCommittedStiffnesses();
  committedTime_ = currentTime_;
  record();
}

void Domain::revertToLastCommit() {
  for (auto& [tag, n] : nodes_) n->revertToLastCommit();
  for (auto& [tag, e] : elements_) e->revertToLastCommit();
  currentTime_ = committedTime_;
  applyLoad(currentTime_);
  update();
}

void Domain::revertToStart() {
  for (auto& [tag, n] : nodes_) n->revertToStart();
  for (auto& [tag, e] : elements_) e->revertToStart();
  currentTime_ = committedTime_ = 0.0;
  applyLoad(0.0);
  update();
}

void Domain::initialStateAnalysis(bool on) {
  for (auto& [tag, e] : elements_) e->initialStateAnalysis(on);
  if (on) return;
  std::set<int> multipliers;
  for (auto& [tag, e] : elements_)
    for (int t : e->multiplierNodes()) multipliers.insert(t);
  for (auto& [tag, n] : nodes_)
    if (!multipliers.count(tag)) n->revertToStart();
  update();
  for (auto& [tag, e] : elements_) e->commitState();
}

void Domain::setLoadConst() {
  for (auto& [tag, p] : patterns_) p->setLoadConst(currentTime_);
}

void Domain::calculateReactions(ReactionKind kind) {
  // As OpenSees: Dynamic adds inertia and damping forces to the static
  // reaction; Rayleigh gives the Rayleigh damping forces alone; the nodal
  // mass-proportional damping alphaM m v enters all three (as OpenSees').
  const bool forces = kind != ReactionKind::Rayleigh, inertia = kind == ReactionKind::Dynamic,
             damping = kind != ReactionKind::Static;
  for (auto& [tag, n] : nodes_) {
    n->zeroReaction();
    if (forces) n->addReaction(-n->unbalancedLoad());
    const Vector& m = n->mass();
    if (inertia) n->addReaction(m.cwiseProduct(n->trialAccel()));
    if (const double alphaM = n->alphaM(rayleigh_.alphaM); alphaM != 0.0)
      n->addReaction(alphaM * m.cwiseProduct(n->trialVel()));
  }
  for (auto& [tag, e] : elements_) {
    Vector f = forces ? Vector(e->resistingForce()) : Vector::Zero(e->numDOF());
    if (inertia) f += e->inertiaForce();
    if (damping) f += e->rayleighForce(e->rayleighFactors(rayleigh_));
    int offset = 0;
    for (Node* n : e->nodes()) {
      n->addReaction(f.segment(offset, n->ndf()));
      offset += n->ndf();
    }
  }
}

bool Domain::needsGeneralSolver() const {
  return std::any_of(elements_.begin(), elements_.end(),
                     [](const auto& kv) { return kv.second->needsGeneralSolver(); });
}

}  // namespace beamsolid
