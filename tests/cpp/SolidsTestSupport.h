#pragma once
// Helpers for the solids/truss/zeroLength tests: build a Domain by hand
// through the Registry, finite-difference tangent checks, and a small dense
// static solver (Newton on the free dofs) written independently of the
// analysis layer.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/Registry.h"

namespace beamsolid::solidstest {

inline void pushValue(std::vector<CommandArgs::Value>& out, const char* s) { out.emplace_back(std::string(s)); }
inline void pushValue(std::vector<CommandArgs::Value>& out, const std::string& s) { out.emplace_back(s); }
inline void pushValue(std::vector<CommandArgs::Value>& out, double d) { out.emplace_back(d); }
template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0>
inline void pushValue(std::vector<CommandArgs::Value>& out, T i) {
  out.emplace_back(static_cast<long long>(i));
}
inline void pushValue(std::vector<CommandArgs::Value>& out, const std::vector<int>& v) {
  for (int i : v) pushValue(out, i);
}
inline void pushValue(std::vector<CommandArgs::Value>& out, const std::vector<double>& v) {
  for (double d : v) pushValue(out, d);
}

// Command arguments after the type name, e.g. args("element", 1, 2, 3, 2.5, "-rho", 1.0).
template <class... T>
CommandArgs args(const std::string& command, const T&... values) {
  std::vector<CommandArgs::Value> out;
  (pushValue(out, values), ...);
  return CommandArgs(command, std::move(out));
}

inline void addNode(Domain& d, int tag, int ndf, double x, double y, double z) {
  d.addNode(std::make_unique<Node>(tag, ndf, Vector3(x, y, z)), "test");
}

template <class... T>
void addNDMaterial(Domain& d, const std::string& type, int tag, const T&... rest) {
  CommandArgs a = args("nDMaterial", tag, rest...);
  d.ndMaterials.add(tag, std::shared_ptr<NDMaterial>(Registry::global().ndMaterials.get(type)(a, d)), "test");
}

template <class... T>
void addUniaxialMaterial(Domain& d, const std::string& type, int tag, const T&... rest) {
  CommandArgs a = args("uniaxialMaterial", tag, rest...);
  d.uniaxialMaterials.add(tag, std::shared_ptr<UniaxialMaterial>(Registry::global().uniaxialMaterials.get(type)(a, d)),
                          "test");
}

template <class... T>
Element& addElement(Domain& d, const std::string& type, int tag, const T&... rest) {
  CommandArgs a = args("element", tag, rest...);
  d.addElement(Registry::global().elements.get(type)(a, d), "test");
  return *d.findElement(tag);
}

// Largest |K - K_fd| over all entries and the largest |K|, where K_fd is the
// central difference of resistingForce with respect to the element's node
// trial displacements (step h). The element state is restored afterwards.
struct TangentCheck {
  double maxError = 0.0;
  double maxEntry = 0.0;
  double relativeError() const { return maxEntry > 0.0 ? maxError / maxEntry : maxError; }
};

inline TangentCheck checkTangent(Element& e, double h) {
  e.update();
  const Matrix K = e.tangentStiff();
  const int n = e.numDOF();
  Matrix Kfd(n, n);
  int col = 0;
  for (Node* node : e.nodes()) {
    for (int dof = 0; dof < node->ndf(); ++dof, ++col) {
      const double u0 = node->trialDisp()(dof);
      node->setTrialDisp(dof, u0 + h);
      e.update();
      const Vector plus = e.resistingForce();
      node->setTrialDisp(dof, u0 - h);
      e.update();
      const Vector minus = e.resistingForce();
      node->setTrialDisp(dof, u0);
      Kfd.col(col) = (plus - minus) / (2.0 * h);
    }
  }
  e.update();
  return {(K - Kfd).cwiseAbs().maxCoeff(), K.cwiseAbs().maxCoeff()};
}

// Dense static solver over the whole domain. Fixed dofs keep their trial
// displacement (set them before solving to impose values).
class DenseStatics {
 public:
  explicit DenseStatics(Domain& d) : domain_(d) {
    for (const auto& [tag, node] : d.nodes()) {
      offsets_[tag] = size_;
      size_ += node->ndf();
    }
  }
  int size() const { return size_; }
  int index(int nodeTag, int dof) const { return offsets_.at(nodeTag) + dof; }
  void fix(int nodeTag, int dof) { fixed_.insert(index(nodeTag, dof)); }
  void fixAll(int nodeTag) {
    for (int k = 0; k < domain_.node(nodeTag, "test").ndf(); ++k) fix(nodeTag, k);
  }
  bool isFixed(int i) const { return fixed_.count(i) > 0; }
  // External nodal load (global dof vector).
  Vector& load() {
    if (load_.size() != size_) load_ = Vector::Zero(size_);
    return load_;
  }

  void assemble(Matrix& K, Vector& R) const {
    K = Matrix::Zero(size_, size_);
    R = Vector::Zero(size_);
    for (const auto& [tag, e] : domain_.elements()) {
      std::vector<int> map;
      for (Node* n : e->nodes())
        for (int k = 0; k < n->ndf(); ++k) map.push_back(index(n->tag(), k));
      const Matrix ke = e->tangentStiff();
      const Vector re = e->resistingForce();
      for (std::size_t a = 0; a < map.size(); ++a) {
        R(map[a]) += re(a);
        for (std::size_t b = 0; b < map.size(); ++b) K(map[a], map[b]) += ke(a, b);
      }
    }
  }

  // Unbalance P - R on the free dofs (zero on the fixed ones).
  Vector unbalance() const {
    Matrix K;
    Vector R;
    domain_.update();
    assemble(K, R);
    Vector r = (load_.size() == size_ ? load_ : Vector::Zero(size_)) - R;
    for (int i : fixed_) r(i) = 0.0;
    return r;
  }

  // Newton iterations until the free-dof unbalance is below tol (absolute);
  // returns the number of iterations, or -1.
  int solve(double tol, int maxIterations = 30) {
    if (load_.size() != size_) load_ = Vector::Zero(size_);
    std::vector<int> freeDofs;
    for (int i = 0; i < size_; ++i)
      if (!isFixed(i)) freeDofs.push_back(i);
    const int nf = static_cast<int>(freeDofs.size());
    for (int it = 0; it <= maxIterations; ++it) {
      domain_.update();
      Matrix K;
      Vector R;
      assemble(K, R);
      Vector r(nf);
      Matrix Kff(nf, nf);
      for (int a = 0; a < nf; ++a) {
        r(a) = load_(freeDofs[a]) - R(freeDofs[a]);
        for (int b = 0; b < nf; ++b) Kff(a, b) = K(freeDofs[a], freeDofs[b]);
      }
      if (r.lpNorm<Eigen::Infinity>() <= tol) return it;
      const Vector du = Kff.fullPivLu().solve(r);
      for (int a = 0; a < nf; ++a) {
        auto [node, dof] = locate(freeDofs[a]);
        node->incrTrialDisp(dof, du(a));
      }
    }
    return -1;
  }

  std::pair<Node*, int> locate(int i) const {
    for (const auto& [tag, off] : offsets_) {
      Node* n = domain_.findNode(tag);
      if (i >= off && i < off + n->ndf()) return {n, i - off};
    }
    return {nullptr, -1};
  }

 private:
  Domain& domain_;
  std::map<int, int> offsets_;
  std::set<int> fixed_;
  int size_ = 0;
  Vector load_;
};

}  // namespace beamsolid::solidstest
