#include "elements/Element.h"

#include <algorithm>

#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

Element::Element(int tag, std::vector<int> nodeTags) : tag_(tag), nodeTags_(std::move(nodeTags)) {}

std::string Element::context() const {
  return "element " + className() + " " + std::to_string(tag_);
}

void Element::connect(Domain& domain) {
  domain_ = &domain;
  nodes_.clear();
  numDOF_ = 0;
  for (int t : nodeTags_) {
    Node* n = domain.findNode(t);
    if (!n) throw OpenSeesError(context() + ": node " + std::to_string(t) + " does not exist");
    nodes_.push_back(n);
    numDOF_ += n->ndf();
  }
  setDomain(domain);
}

void Element::reconnect(std::vector<int> nodeTags) {
  if (!domain_) throw OpenSeesError(context() + ": cannot change the nodes of an element that is not in a domain");
  std::vector<Node*> nodes;
  int numDOF = 0;
  for (int t : nodeTags) {
    Node* n = domain_->findNode(t);
    if (!n) throw OpenSeesError(context() + ": node " + std::to_string(t) + " does not exist");
    nodes.push_back(n);
    numDOF += n->ndf();
  }
  std::vector<int> oldTags = std::move(nodeTags_);
  nodeTags_ = std::move(nodeTags);
  nodes_ = std::move(nodes);
  numDOF_ = numDOF;
  domain_->elementReconnected(*this, oldTags);
}

void Element::rereadGeometry() {
  if (!domain_) throw OpenSeesError(context() + ": not in a domain");
  connect(*domain_);
}

void Element::noSensitivity(const std::string& why) const {
  throw OpenSeesError(context() + " does not compute sensitivities (sensitivityAlgorithm): " + why);
}

int Element::sensitivityParameter(const std::vector<std::string>&) { return 0; }

Vector Element::resistingForceSensitivity(int, const SensitivityParameter& p) {
  if (hasHistory() || p.id != 0)
    noSensitivity(p.id != 0 ? "its response depends on the parameter" : "it has a history (path-dependent state)");
  // Without history, an element theta does not reach answers zero, and one
  // whose node moves is differentiated by central differences in the
  // coordinate (step 1e-6 of the element's size).
  if (p.node < 0) return Vector::Zero(numDOF());
  double size = 0.0;
  for (const Node* a : nodes())
    for (const Node* b : nodes()) size = std::max(size, (a->crd() - b->crd()).norm());
  Node& node = *nodes()[p.node];
  const double x = node.crd()[p.dim], h = 1e-6 * (size > 0.0 ? size : 1.0);
  auto forceAt = [&](double value) {
    node.setCoordinate(p.dim, value);
    rereadGeometry();
    update();
    return Vector(resistingForce());
  };
  const Vector plus = forceAt(x + h), minus = forceAt(x - h);
  forceAt(x);
  return (plus - minus) / (2.0 * h);
}

void Element::commitSensitivity(int, const SensitivityParameter& p, const Vector&, int) {
  // No history, nothing to keep (resistingForceSensitivity refused the others).
  if (!hasHistory() && p.id == 0) return;
  noSensitivity("it keeps no sensitivity of its history");
}

MatrixView Element::massMatrix() {
  if (zeroMass_.rows() != numDOF_) zeroMass_ = Matrix::Zero(numDOF_, numDOF_);
  return viewOf(zeroMass_);
}

namespace {
// The element's nodes' trial velocities (or accelerations), in element dof order.
Vector gatherNodal(const std::vector<Node*>& nodes, int size, const Vector& (Node::*what)() const) {
  Vector out(size);
  int offset = 0;
  for (const Node* n : nodes) {
    out.segment(offset, n->ndf()) = (n->*what)();
    offset += n->ndf();
  }
  return out;
}
}  // namespace

Vector Element::inertiaForce() {
  MatrixView m = massMatrix();
  return m * gatherNodal(nodes_, numDOF_, &Node::trialAccel);
}

Matrix Element::rayleighMatrix(const RayleighFactors& f, const Matrix& current) {
  Matrix c = Matrix::Zero(numDOF_, numDOF_);
  if (!doesRayleighDamping()) return c;
  if (f.alphaM != 0.0) c += f.alphaM * Matrix(massMatrix());
  if (f.betaK != 0.0) c += f.betaK * current;
  if (f.betaKinit != 0.0) c += f.betaKinit * Matrix(initialStiff());
  // Before the first commit OpenSees damps with the initial stiffness.
  if (f.betaKcomm != 0.0)
    c += f.betaKcomm * (committedStiff_.rows() == numDOF_ ? committedStiff_ : Matrix(initialStiff()));
  return c;
}

Vector Element::rayleighForce(const RayleighFactors& f) {
  if (!doesRayleighDamping() || !f.any()) return Vector::Zero(numDOF_);
  const Matrix current = f.betaK != 0.0 ? Matrix(tangentStiff()) : Matrix();
  return rayleighMatrix(f, current) * gatherNodal(nodes_, numDOF_, &Node::trialVel);
}

void Element::addLoad(const ElementLoad& load, double) {
  throw OpenSeesError(context() + ": does not accept element load " +
                      ElementLoad::typeName(load.type));
}

Response Element::setResponse(const std::vector<std::string>&) { return {}; }

bool Element::setParameter(const std::vector<std::string>&, double) { return false; }

void Element::updateMaterialStage(int, int) {}

void Element::print(std::ostream& os) const {
  os << "Element " << tag_ << " type " << className() << " nodes";
  for (int t : nodeTags_) os << ' ' << t;
  os << '\n';
}

void Element::printJSON(std::ostream& os) const {
  os << "{\"name\": " << tag_ << ", \"type\": \"" << className() << "\", \"nodes\": [";
  for (std::size_t i = 0; i < nodeTags_.size(); ++i) os << (i ? ", " : "") << nodeTags_[i];
  os << "]}";
}

}  // namespace beamsolid
