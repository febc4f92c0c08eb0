#include "elements/Element.h"

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

MatrixView Element::massMatrix() {
  if (zeroMass_.rows() != numDOF_) zeroMass_ = Matrix::Zero(numDOF_, numDOF_);
  return viewOf(zeroMass_);
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
