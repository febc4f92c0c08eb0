#pragma once
// Test scaffolding for beam tests: builds a Domain by hand through the
// registered factories, and assembles and solves the free-dof system with
// dense Eigen (no analysis layer involved).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/Registry.h"
#include "elements/Element.h"
#include "elements/transforms/CrdTransf.h"

namespace beamtest {

using beamsolid::CommandArgs;
using beamsolid::Domain;
using beamsolid::Element;
using beamsolid::Matrix;
using beamsolid::Matrix3;
using beamsolid::Node;
using beamsolid::Registry;
using beamsolid::Vector;
using beamsolid::Vector3;
using Args = std::vector<CommandArgs::Value>;

inline Node& addNode(Domain& domain, int tag, const Vector3& x, int ndf = 6) {
  auto node = std::make_unique<Node>(tag, ndf, x);
  Node& ref = *node;
  domain.addNode(std::move(node), "node " + std::to_string(tag));
  return ref;
}

// geomTransf(type, *args) through the registry.
inline beamsolid::CrdTransf& addTransf(Domain& domain, const std::string& type, Args args) {
  CommandArgs a("geomTransf", std::move(args));
  std::shared_ptr<beamsolid::CrdTransf> t = Registry::global().geomTransfs.get(type)(a, domain);
  a.expectEnd();
  domain.geomTransfs.add(t->tag(), t, a.context());
  return *t;
}

// element(type, *args) through the registry, then Domain::addElement.
inline Element& addElement(Domain& domain, const std::string& type, Args args) {
  CommandArgs a("element", std::move(args));
  std::unique_ptr<Element> e = Registry::global().elements.get(type)(a, domain);
  a.expectEnd();
  Element& ref = *e;
  domain.addElement(std::move(e), a.context());
  return ref;
}

// Equation numbers of the free dofs and dense assembly over all elements.
class DenseModel {
 public:
  // fixed: (nodeTag, dof) pairs that are held at zero.
  DenseModel(Domain& domain, const std::set<std::pair<int, int>>& fixed) : domain_(domain) {
    for (const auto& [tag, node] : domain.nodes())
      for (int d = 0; d < node->ndf(); ++d)
        if (!fixed.count({tag, d})) equation_[{tag, d}] = size_++;
  }
  static std::set<std::pair<int, int>> clamp(std::initializer_list<int> nodeTags) {
    std::set<std::pair<int, int>> out;
    for (int t : nodeTags)
      for (int d = 0; d < 6; ++d) out.insert({t, d});
    return out;
  }

  int size() const { return size_; }
  int equation(int nodeTag, int dof) const {
    auto it = equation_.find({nodeTag, dof});
    return it == equation_.end() ? -1 : it->second;
  }

  Matrix stiffness() const {
    Matrix k = Matrix::Zero(size_, size_);
    for (const auto& [etag, e] : domain_.elements()) {
      const std::vector<int> map = scatter(*e);
      const auto ke = e->tangentStiff();
      for (std::size_t a = 0; a < map.size(); ++a)
        for (std::size_t b = 0; b < map.size(); ++b)
          if (map[a] >= 0 && map[b] >= 0) k(map[a], map[b]) += ke(a, b);
    }
    return k;
  }
  Vector internalForce() const {
    Vector f = Vector::Zero(size_);
    for (const auto& [etag, e] : domain_.elements()) {
      const std::vector<int> map = scatter(*e);
      const auto fe = e->resistingForce();
      for (std::size_t a = 0; a < map.size(); ++a)
        if (map[a] >= 0) f(map[a]) += fe(a);
    }
    return f;
  }
  // Sum of element resisting forces at one node (the reaction at a support).
  Vector nodeForce(int nodeTag) const {
    Vector f = Vector::Zero(domain_.node(nodeTag, "test").ndf());
    for (const auto& [etag, e] : domain_.elements()) {
      const auto fe = e->resistingForce();
      int offset = 0;
      for (const Node* n : e->nodes()) {
        if (n->tag() == nodeTag) f += fe.segment(offset, n->ndf());
        offset += n->ndf();
      }
    }
    return f;
  }
  void addLoad(Vector& rhs, int nodeTag, const Vector& load) const {
    for (int d = 0; d < load.size(); ++d)
      if (int eq = equation(nodeTag, d); eq >= 0) rhs(eq) += load(d);
  }
  void setDisplacement(const Vector& u) const {
    for (const auto& [key, eq] : equation_) domain_.node(key.first, "test").setTrialDisp(key.second, u(eq));
    domain_.update();
  }
  Vector displacement() const {
    Vector u(size_);
    for (const auto& [key, eq] : equation_) u(eq) = domain_.node(key.first, "test").trialDisp()(key.second);
    return u;
  }
  // Newton iteration on external load f: K du = f - r(u) until the
  // unbalance is below tol * scale (scale defaults to |f|). Returns the
  // number of iterations, or -1 when it did not converge.
  int solve(const Vector& f, double tol = 1e-12, int maxIterations = 50, double scale = 0.0) const {
    domain_.update();
    if (scale <= 0.0) scale = f.norm();
    for (int it = 0; it <= maxIterations; ++it) {
      const Vector residual = f - internalForce();
      if (std::getenv("BEAMTEST_TRACE")) fprintf(stderr, "it %d residual %g\n", it, residual.norm() / scale);
      if (residual.norm() <= tol * scale) return it;
      const Vector du = stiffness().fullPivLu().solve(residual);
      setDisplacement(displacement() + du);
    }
    return -1;
  }

 private:
  std::vector<int> scatter(const Element& e) const {
    std::vector<int> map;
    for (const Node* n : e.nodes())
      for (int d = 0; d < n->ndf(); ++d) map.push_back(equation(n->tag(), d));
    return map;
  }

  Domain& domain_;
  std::map<std::pair<int, int>, int> equation_;
  int size_ = 0;
};

inline Vector stack(const Vector3& a, const Vector3& b) {
  Vector v(6);
  v << a, b;
  return v;
}

// A unit vector from unnormalized components.
inline Vector3 unit(double x, double y, double z) { return Vector3(x, y, z).normalized(); }

}  // namespace beamtest
