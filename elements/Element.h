#pragma once
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/ElementLoad.h"
#include "core/RayleighFactors.h"
#include "core/Response.h"
#include "core/Types.h"

namespace beamsolid {

class Domain;
class Node;

// An element knows its nodes, reads their trial displacements in update(),
// and answers stiffness, resisting force and mass in its own dof order
// (node by node, all dofs of each node). It never touches the global system.
class Element {
 public:
  Element(int tag, std::vector<int> nodeTags);
  virtual ~Element() = default;
  Element(const Element&) = delete;
  Element& operator=(const Element&) = delete;

  int tag() const { return tag_; }
  virtual std::string className() const = 0;

  const std::vector<int>& nodeTags() const { return nodeTags_; }
  const std::vector<Node*>& nodes() const { return nodes_; }
  // Sum of the ndf of the element's nodes: the size of its matrices.
  int numDOF() const { return numDOF_; }
  // Whether the element works in a model of ndm dimensions. Most elements
  // are 3D only; those that work in 1D/2D say so.
  virtual bool supportsSpace(int ndm) const { return ndm == 3; }

  // Resolves node tags against the domain (clear error for a missing node)
  // and then calls setDomain() for element-specific checks and set-up.
  void connect(Domain& domain);

  // Reads trial displacements of the nodes and updates element state.
  virtual void update() = 0;
  virtual MatrixView tangentStiff() = 0;
  virtual MatrixView initialStiff() = 0;
  // Internal force minus element loads, in element dof order.
  virtual VectorView resistingForce() = 0;
  // Consistent or lumped mass; zero by default.
  virtual MatrixView massMatrix();
  // Whether the global rayleigh() factors damp this element (OpenSees'
  // -doRayleigh flags of truss and zeroLength; other elements always).
  virtual bool doesRayleighDamping() const { return true; }
  // Factors of a region(..., '-rayleigh', ...) that holds this element; they
  // replace the global ones until the next rayleigh() clears them.
  void setRegionRayleigh(const RayleighFactors& f) { regionRayleigh_ = f; hasRegionRayleigh_ = true; }
  void clearRegionRayleigh() { hasRegionRayleigh_ = false; }
  const RayleighFactors& rayleighFactors(const RayleighFactors& global) const {
    return hasRegionRayleigh_ ? regionRayleigh_ : global;
  }
  // d force / d nodal velocity of the element's own dashpots (Viscous
  // materials, Elastic eta), added to the damping matrix; none by default.
  virtual bool hasDampingTangent() const { return false; }
  virtual Matrix dampingTangent() { return Matrix::Zero(numDOF_, numDOF_); }
  // Transient analysis, from the nodes' trial velocities and accelerations:
  // M a, and C v with C the Rayleigh damping of factors f (zero when the
  // element does no Rayleigh damping).
  Vector inertiaForce();
  Vector rayleighForce(const RayleighFactors& f);
  // Element matrix of Rayleigh damping with factors f (betaK on `current`,
  // the tangent already formed, to spare a second evaluation).
  Matrix rayleighMatrix(const RayleighFactors& f, const Matrix& current);
  // The tangent at the last commit (betaKcomm); empty (zero) until kept.
  void keepCommittedStiffness() { committedStiff_ = tangentStiff(); }
  const Matrix& committedStiffness() const { return committedStiff_; }

  virtual void commitState() {}
  virtual void revertToLastCommit() {}
  virtual void revertToStart() {}

  // Element loads of load patterns (eleLoad); zeroLoad() is called before
  // each applyLoad. Elements that take no load throw a clear error.
  virtual void zeroLoad() {}
  virtual void addLoad(const ElementLoad& load, double factor);
  // Whether this element accepts this kind of load (checked at eleLoad time).
  virtual bool acceptsLoad(ElementLoad::Type) const { return false; }

  // Response for eleResponse and Element recorders; an empty Response when
  // the arguments name nothing this element has.
  virtual Response setResponse(const std::vector<std::string>& args);

  // setParameter('-val', v, '-ele', tag, *args): true when recognized.
  virtual bool setParameter(const std::vector<std::string>& args, double value);
  // updateMaterialStage('-material', matTag, '-stage', s): forwarded to
  // every element, which passes it to its copies of material matTag.
  virtual void updateMaterialStage(int materialTag, int stage);
  // InitialStateAnalysis('on' | 'off'): passed to the element's materials.
  virtual void initialStateAnalysis(bool) {}
  // Tags of the element's Lagrange multiplier nodes: forces, not
  // displacements, so InitialStateAnalysis('off') keeps their values.
  virtual std::vector<int> multiplierNodes() const { return {}; }

  // --- Sensitivity (direct differentiation, sensitivityAlgorithm) ------------
  // A parameter theta as this element sees it: `id` > 0 when theta is one of
  // the element's own arguments (the value sensitivityParameter() gave for
  // its name), `node` >= 0 and `dim` when theta is a coordinate of
  // nodes()[node]; neither when theta belongs to other objects only (the
  // element's history still depends on it through its displacements).
  struct SensitivityParameter {
    int id = 0;
    int node = -1, dim = -1;
  };
  // Whether the element's response depends on its path (committed state);
  // one without history takes part in sensitivities without keeping any.
  virtual bool hasHistory() const { return !hasConstantTangent(); }
  // The id (> 0) of the element argument named by `args` (as setParameter
  // reads them), 0 if the element has none of that name.
  virtual int sensitivityParameter(const std::vector<std::string>& args);
  // d R / d theta at the nodes' trial displacements: the element's own
  // dependence on theta and that of its history (committed sensitivities of
  // gradient `gradient`). The default serves elements without history:
  // zero when theta does not reach them, central differences in a node's
  // coordinate; others throw.
  virtual Vector resistingForceSensitivity(int gradient, const SensitivityParameter& p);
  // After the nodes' displacement sensitivities of `gradient` are known
  // (dU, in element dof order): keeps the history's sensitivities of the
  // trial state; numGradients sizes the storage.
  virtual void commitSensitivity(int gradient, const SensitivityParameter& p, const Vector& dU, int numGradients);

  // Solver needs: a tangent that is unsymmetric, or has zero diagonal
  // entries (Lagrange multipliers), cannot go to an SPD-only solver.
  virtual bool needsGeneralSolver() const { return false; }
  // True when the tangent never changes (linear material and geometry): the
  // solver may condense the dofs only such elements touch, once per model.
  virtual bool hasConstantTangent() const { return false; }
  // True when the tangent's row and column of local dof i never change and
  // couple it to no other dof (the inert dofs of a Lagrange multiplier node):
  // the solver may condense that dof with the constant part of the model.
  virtual bool hasConstantUncoupledDof(int /*i*/) const { return false; }

  // The node (index into nodes()) at which the element is drawn as a point
  // (VTK_VERTEX) by the PVD recorder, e.g. a node-to-node contact; -1, the
  // default, for an element that is not a point.
  virtual int vertexNode() const { return -1; }

  // Readable one-element description for printModel, and a JSON object.
  virtual void print(std::ostream& os) const;
  virtual void printJSON(std::ostream& os) const;

 protected:
  // Element-specific set-up once the nodes are known; throw OpenSeesError
  // naming the element (e.g. wrong ndf, zero length).
  virtual void setDomain(Domain&) {}
  // Changes the element's nodes after creation (e.g. a contact element that
  // hands its secondary node over to the next pile segment). The tags are
  // resolved against the Domain the element was connected to (clear error
  // for a missing node; the old nodes stay on error), numDOF() follows, and
  // the Domain's model stamp is touched so that the analysis renumbers and
  // rebuilds its scatter maps before the next step. setDomain() is not
  // called again: the element keeps its state and updates what depends on
  // the nodes itself. Only between steps (e.g. in commitState()), never
  // inside a Newton iteration, and only after connect().
  void reconnect(std::vector<int> nodeTags);
  // "element <className> <tag>", the prefix of this element's messages.
  std::string context() const;
  // Re-reads the nodes' coordinates (connect() again): sensitivities to a
  // node coordinate evaluate the element at nearby positions.
  void rereadGeometry();
  // Throws: this element cannot compute sensitivities (`why`).
  [[noreturn]] void noSensitivity(const std::string& why) const;

 private:
  int tag_;
  Domain* domain_ = nullptr;  // not owned: the Domain of the last connect()
  std::vector<int> nodeTags_;
  std::vector<Node*> nodes_;
  int numDOF_ = 0;
  Matrix zeroMass_;
  Matrix committedStiff_;
  RayleighFactors regionRayleigh_;
  bool hasRegionRayleigh_ = false;
};

}  // namespace beamsolid
