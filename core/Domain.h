#pragma once
#include <functional>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/Constraints.h"
#include "core/LoadPattern.h"
#include "core/Node.h"
#include "core/ModalDamping.h"
#include "core/RayleighFactors.h"
#include "core/Recorder.h"
#include "core/TaggedStore.h"
#include "core/TimeSeries.h"
#include "elements/Element.h"
#include "elements/transforms/CrdTransf.h"
#include "materials/nd/NDMaterial.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

class BeamSection;
class BeamIntegration;

// The model and nothing about solving it: nodes, elements, constraints,
// load patterns, recorders, and the definitions (materials, transforms,
// time series) that commands refer to by tag.
class Domain {
 public:
  Domain();
  ~Domain();

  // --- model space --------------------------------------------------------
  // model('basic', '-ndm', ndm, '-ndf', ndf). 0 until a model command: code
  // that builds a Domain directly gets 3D (spaceDim() is then 3).
  int ndm() const { return ndm_; }
  int ndf() const { return ndf_; }
  int spaceDim() const { return ndm_ == 0 ? 3 : ndm_; }
  void setModelSpace(int ndm, int ndf) {
    ndm_ = ndm;
    ndf_ = ndf;
  }

  // --- nodes and elements -------------------------------------------------
  void addNode(std::unique_ptr<Node> node, const std::string& context);
  Node* findNode(int tag) const;
  Node& node(int tag, const std::string& context) const;
  const std::map<int, std::unique_ptr<Node>>& nodes() const { return nodes_; }
  void removeNode(int tag, const std::string& context);

  // Connects the element (resolving its nodes) and adds it; an element that
  // does not work in the model's space (Element::supportsSpace) is an error.
  void addElement(std::unique_ptr<Element> element, const std::string& context);
  Element* findElement(int tag) const;
  Element& element(int tag, const std::string& context) const;
  const std::map<int, std::unique_ptr<Element>>& elements() const { return elements_; }
  void removeElement(int tag, const std::string& context);
  // Called by Element::reconnect() after element e changed its nodes from
  // oldTags to e.nodeTags(): keeps the node-usage counts and touches the model.
  void elementReconnected(const Element& e, const std::vector<int>& oldTags);

  // How many element node slots refer to a node, and how many constraints
  // involve it (fix/sp, imposed displacements of load patterns, either end of
  // a multi-point constraint). Cached: rebuilt at most once per model stamp
  // and kept current through addNode/addElement/removeElement/reconnect, so
  // per-element checks (e.g. "this multiplier node is mine alone") cost O(1)
  // instead of a scan of the whole model.
  struct NodeUsage {
    int elements = 0;
    int constraints = 0;
  };
  NodeUsage nodeUsage(int nodeTag) const;

  // Objects that several elements share (e.g. the nodal frames of a pile
  // along which contact elements hand their nodes over), found by a key the
  // element type chooses (prefix it with the type's name). The Domain holds
  // them weakly: an object lives as long as an element holds it. make() is
  // called when no live object has the key.
  template <class T>
  std::shared_ptr<T> sharedObject(const std::string& key, const std::function<std::shared_ptr<T>()>& make) {
    if (auto existing = sharedObjects_[key].lock()) return std::static_pointer_cast<T>(existing);
    std::shared_ptr<T> made = make();
    sharedObjects_[key] = made;
    return made;
  }

  // --- constraints ----------------------------------------------------------
  // Homogeneous or fixed-value constraints from fix/fixX/...; an existing
  // constraint on the same dof is an error.
  void addSP(const SPConstraint& sp, const std::string& context);
  bool removeSP(int nodeTag, int dof);
  const std::vector<SPConstraint>& sps() const { return sps_; }
  // Whether fix/sp (not a pattern's sp) constrains this dof.
  bool isFixed(int nodeTag, int dof) const { return fixedDofs_.count(dofKey(nodeTag, dof)) > 0; }
  void addMP(MPConstraint mp, const std::string& context);
  bool removeMP(int constrainedNode);
  const std::vector<MPConstraint>& mps() const { return mps_; }

  // --- load patterns ----------------------------------------------------------
  void addPattern(std::unique_ptr<LoadPattern> pattern, const std::string& context);
  LoadPattern* findPattern(int tag) const;
  LoadPattern& pattern(int tag, const std::string& context) const;
  const std::map<int, std::unique_ptr<LoadPattern>>& patterns() const { return patterns_; }
  bool removePattern(int tag);
  // Every imposed-displacement SP of the patterns, with its current value.
  struct ImposedValue {
    int nodeTag;
    int dof;
    double value;
  };
  std::vector<ImposedValue> imposedValues(double time) const;

  // --- definitions referred to by tag ---------------------------------------
  TaggedStore<UniaxialMaterial> uniaxialMaterials{"uniaxialMaterial"};
  TaggedStore<NDMaterial> ndMaterials{"nDMaterial"};
  TaggedStore<CrdTransf> geomTransfs{"geomTransf"};
  TaggedStore<TimeSeries> timeSeries{"timeSeries"};
  // Prototypes that beam-column elements copy (sections) or read (rules).
  TaggedStore<BeamSection> sections{"section"};
  TaggedStore<BeamIntegration> beamIntegrations{"beamIntegration"};

  // --- recorders ---------------------------------------------------------------
  int addRecorder(std::unique_ptr<Recorder> recorder);
  bool removeRecorder(int tag);
  void removeRecorders();
  const std::map<int, std::unique_ptr<Recorder>>& recorders() const { return recorders_; }
  // The tag addRecorder gives next: a recorder being built names itself by
  // it when it claims its file (OutputFileClaim).
  int nextRecorderTag() const { return nextRecorderTag_; }
  // OpenSees numbers recorders on across wipe(): the new Domain goes on from the old one's count.
  void setNextRecorderTag(int tag) { nextRecorderTag_ = tag; }
  void record();
  void flushRecorders();

  // --- damping ---------------------------------------------------------------
  // rayleigh(alphaM, betaK, betaKinit, betaKcomm): C = alphaM M + betaK K
  // (current) + betaKinit K(initial) + betaKcomm K(last committed), for every
  // element that does Rayleigh damping and (alphaM only) every nodal mass.
  // As OpenSees, rayleigh() replaces the factors regions gave (region()).
  const RayleighFactors& rayleigh() const { return rayleigh_; }
  void setRayleigh(const RayleighFactors& f);
  // Whether any element or node may be damped by Rayleigh factors, global or
  // of a region (so that the all-zero case costs nothing).
  bool anyRayleigh() const { return rayleigh_.any() || regionRayleigh_; }
  void noteRegionRayleigh();
  // Eigenvalues of the last eigen analysis (the mode shapes are on the nodes).
  const std::vector<double>& eigenvalues() const { return eigenvalues_; }
  void setEigenvalues(std::vector<double> values) { eigenvalues_ = std::move(values); }
  // modalDamping(...): damping by the modes of the last eigen; null when none.
  const ModalDamping* modalDamping() const { return modalDamping_.get(); }
  void setModalDamping(std::unique_ptr<ModalDamping> d) { modalDamping_ = std::move(d); }
  // region(): the nodes and elements a region holds (as OpenSees: a region of
  // elements holds their nodes too, one of nodes the elements all of whose
  // nodes it holds, unless made with an '-...Only' option). False for a tag
  // already used.
  struct Region {
    std::vector<int> nodes, elements;
  };
  bool addRegion(int tag, Region region) { return regions_.emplace(tag, std::move(region)).second; }
  // The region with this tag; an OpenSeesError naming `context` if none.
  const Region& region(int tag, const std::string& context) const;

  // --- state ---------------------------------------------------------------------
  // True while a transient analysis runs (elements that treat impact
  // differently in dynamics ask; StaticAnalysis clears it).
  bool transient() const { return transient_; }
  void setTransient(bool on) { transient_ = on; }
  double currentTime() const { return currentTime_; }
  double committedTime() const { return committedTime_; }
  void setCurrentTime(double t) { currentTime_ = t; }
  void setCommittedTime(double t) { committedTime_ = t; }

  // Nodal loads and element loads of all patterns at time t.
  void applyLoad(double time);
  // Elements read the nodes' trial displacements.
  void update();
  // Nodes, elements and materials commit; recorders record.
  void commit();
  void revertToLastCommit();
  void revertToStart();
  // InitialStateAnalysis('on' | 'off'). 'off' zeroes the displacements,
  // velocities and accelerations of every node but the Lagrange multiplier
  // nodes (their dofs are forces) and commits the elements there: wrapped
  // materials (InitialStateAnalysisWrapper) keep their stress, contact
  // elements re-project onto the reference geometry. Nothing is recorded.
  void initialStateAnalysis(bool on);
  // loadConst: every existing pattern keeps its current factor.
  void setLoadConst();
  // Reactions: element resisting forces minus applied nodal loads; with
  // Dynamic also inertia and Rayleigh damping forces, with Rayleigh the
  // damping forces only (OpenSees' reactions('-dynamic' | '-rayleigh')).
  enum class ReactionKind { Static, Dynamic, Rayleigh };
  void calculateReactions(ReactionKind kind = ReactionKind::Static);

  // Incremented whenever nodes, elements or constraints change, so the
  // analysis knows to renumber and rebuild its sparsity pattern.
  long modelStamp() const { return modelStamp_; }
  void touch() { ++modelStamp_; }
  // After setNodeCoord: the elements on node `tag` re-read their geometry.
  void nodeMoved(int tag, const std::string& context);

  // Whether any element needs a general (non-SPD) solver.
  bool needsGeneralSolver() const;

 private:
  int ndm_ = 0;
  int ndf_ = 0;
  std::map<int, std::unique_ptr<Node>> nodes_;
  std::map<int, std::unique_ptr<Element>> elements_;
  std::vector<SPConstraint> sps_;
  std::vector<MPConstraint> mps_;
  // dofKey()s of sps_ and of the MPs' constrained dofs: duplicate checks in O(1), not a scan per
  // command (quadratic in fix/equalDOF counts).
  std::unordered_set<std::int64_t> fixedDofs_;
  std::unordered_set<std::int64_t> mpConstrainedDofs_;
  std::map<int, std::unique_ptr<LoadPattern>> patterns_;
  std::map<int, std::unique_ptr<Recorder>> recorders_;
  int nextRecorderTag_ = 0;
  int nextMPTag_ = 0;
  RayleighFactors rayleigh_;
  bool regionRayleigh_ = false;
  std::map<int, Region> regions_;
  // Whether any state was committed (the betaKcomm stiffness then is the
  // tangent of that state, not the initial one).
  bool committedOnce_ = false;
  void keepCommittedStiffnesses();
  std::vector<double> eigenvalues_;
  std::unique_ptr<ModalDamping> modalDamping_;
  double currentTime_ = 0.0;
  bool transient_ = false;
  double committedTime_ = 0.0;
  long modelStamp_ = 0;
  // Node-usage cache (nodeUsage()), valid while nodeUsageStamp_ == modelStamp_.
  mutable std::unordered_map<int, NodeUsage> nodeUsage_;
  mutable long nodeUsageStamp_ = -1;
  std::map<std::string, std::weak_ptr<void>> sharedObjects_;
};

}  // namespace beamsolid
