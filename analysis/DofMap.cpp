#include "analysis/DofMap.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "analysis/ConstraintHandler.h"
#include "analysis/Numberer.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

namespace {
// The last warning said (the dof map is rebuilt by every analysis of a model).
std::string& lastWarning() {
  static std::string text;
  return text;
}
}  // namespace

void DofMap::resetWarnings() { lastWarning().clear(); }

namespace {
std::string dofName(const Node& n, int dof) {
  return "node " + std::to_string(n.tag()) + " dof " + std::to_string(dof + 1);
}
}  // namespace

const DofMap::GeneralScatter* DofMap::generalScatterBegin(int e) const {
  return generalScatter_.data() + elementMaps_[e].scatterStart;
}
const DofMap::GeneralScatter* DofMap::generalScatterEnd(int e) const {
  return generalScatter_.data() + generalScatterEnd_[e];
}

int DofMap::fullStartOfNode(int nodeTag) const {
  auto it = nodeIndex_.find(nodeTag);
  return it == nodeIndex_.end() ? -1 : nodeStart_[it->second];
}

int DofMap::position(int row, int col) const {
  auto b = rowIndex_.begin() + colStart_[col];
  auto e = rowIndex_.begin() + colStart_[col + 1];
  auto it = std::lower_bound(b, e, row);
  return (it != e && *it == row) ? static_cast<int>(it - rowIndex_.begin()) : -1;
}

void DofMap::build(const Domain& domain, const ConstraintHandler& handler, const Numberer& numberer) {
  // --- full dofs: every dof of every node, nodes in tag order ---------------
  nodes_.clear();
  nodeStart_.clear();
  std::unordered_map<int, int>& nodeIndex = nodeIndex_;
  nodeIndex.clear();
  int nFull = 0;
  for (const auto& [tag, n] : domain.nodes()) {
    nodeIndex[tag] = static_cast<int>(nodes_.size());
    nodes_.push_back(n.get());
    nodeStart_.push_back(nFull);
    nFull += n->ndf();
  }
  nodeStart_.push_back(nFull);
  std::vector<int> ownerNode(nFull);
  fullOwner_.resize(nFull);
  for (int v = 0; v < static_cast<int>(nodes_.size()); ++v)
    for (int f = nodeStart_[v]; f < nodeStart_[v + 1]; ++f) {
      ownerNode[f] = v;
      fullOwner_[f] = {nodes_[v], f - nodeStart_[v]};
    }
  auto fullOf = [&](int nodeTag, int dof) { return nodeStart_[nodeIndex.at(nodeTag)] + dof; };
  auto nameOf = [&](int f) { return dofName(*nodes_[ownerNode[f]], f - nodeStart_[ownerNode[f]]); };

  // --- classify: free, imposed (SP) or dependent (MP) -------------------------
  enum Kind : char { Free, Imposed, Dependent };
  std::vector<char> kind(nFull, Free);
  imposedFull_.clear();
  const bool eliminate = handler.eliminates();
  // imposedValues lists the fixes first, then the patterns' sp/imposedMotion.
  const std::size_t numFixes = domain.sps().size();
  for (const auto& iv : domain.imposedValues(domain.currentTime())) {
    const int f = fullOf(iv.nodeTag, iv.dof);
    auto earlier = std::find(imposedFull_.begin(), imposedFull_.end(), f);
    if (earlier != imposedFull_.end()) {
      // A pattern's sp or imposedMotion on a fixed dof (multiple-support
      // excitation scripts fix the supports, then impose their motion): as
      // OpenSees, with Transformation/Plain the imposed value governs, with
      // Penalty both constraints act (two springs: the mean of 0 and the value).
      const bool fixThenPattern = static_cast<std::size_t>(earlier - imposedFull_.begin()) < numFixes &&
                                  imposedFull_.size() >= numFixes;
      if (!fixThenPattern)
        throw OpenSeesError("analysis: " + nameOf(f) + " has more than one single-point constraint (fix/sp)");
      if (eliminate) *earlier = -1;
    }
    imposedFull_.push_back(f);
  }
  std::unordered_map<int, std::vector<std::pair<int, double>>> sources;
  if (eliminate) {
    std::vector<std::string> overridden;
    for (int f : imposedFull_)
      if (f >= 0) kind[f] = Imposed;
    for (const auto& mp : domain.mps()) {
      for (std::size_t i = 0; i < mp.constrainedDofs.size(); ++i) {
        const int f = fullOf(mp.constrainedNode, mp.constrainedDofs[i]);
        if (kind[f] == Dependent)
          throw OpenSeesError("analysis: " + nameOf(f) + " is constrained by more than one multi-point constraint");
        if (kind[f] == Imposed && handler.method() == ConstraintHandler::Method::Lagrange)
          throw OpenSeesError("constraints Lagrange: " + nameOf(f) +
                              " is both fixed and constrained by a multi-point constraint; BeamSolid enforces "
                              "Lagrange constraints by elimination and cannot hold both: remove the fix or use "
                              "constraints('Transformation'), which ignores the fix");
        if (kind[f] == Imposed) {
          // OpenSees' Transformation handler lets the equalDOF/rigidLink win over a fix on its constrained dof
          // (public scripts, e.g. the p-y pile example, rely on it): the fix is dropped, with a warning.
          overridden.push_back(nameOf(f));
          std::replace(imposedFull_.begin(), imposedFull_.end(), f, -1);
        }
        kind[f] = Dependent;
        auto& src = sources[f];
        for (std::size_t k = 0; k < mp.retainedDofs.size(); ++k)
          if (mp.C(i, k) != 0.0) src.push_back({fullOf(mp.retainedNode, mp.retainedDofs[k]), mp.C(i, k)});
      }
    }
    if (!overridden.empty()) {
      std::ostringstream warning;
      warning << "WARNING constraints Transformation: " << overridden.size()
              << " fixed dof(s) also constrained by a multi-point constraint (" << overridden.front()
              << (overridden.size() > 1 ? ", ..." : "") << "); their fixes are ignored\n";
      if (warning.str() != lastWarning()) std::cerr << (lastWarning() = warning.str());
    }
  }

  // --- resolve every full dof into free full dofs (chains of MPs allowed) ----
  std::vector<std::vector<std::pair<int, double>>> resolved(nFull);
  std::vector<char> state(nFull, 0);  // 0 new, 1 visiting, 2 done
  dependents_.clear();
  auto resolve = [&](auto&& self, int f) -> const std::vector<std::pair<int, double>>& {
    if (state[f] == 2) return resolved[f];
    if (state[f] == 1) throw OpenSeesError("analysis: multi-point constraints form a cycle at " + nameOf(f));
    state[f] = 1;
    std::vector<std::pair<int, double>> terms;
    if (kind[f] == Free) {
      terms.push_back({f, 1.0});
    } else if (kind[f] == Dependent) {
      std::map<int, double> sum;
      for (const auto& [src, c] : sources[f])
        for (const auto& [g, cg] : self(self, src)) sum[g] += c * cg;
      for (const auto& [g, c] : sum)
        if (c != 0.0) terms.push_back({g, c});
      dependents_.push_back({f, sources[f]});
    }
    resolved[f] = std::move(terms);
    state[f] = 2;
    return resolved[f];
  };
  for (int f = 0; f < nFull; ++f) resolve(resolve, f);

  // --- node graph and numbering ----------------------------------------------
  const int nNodes = static_cast<int>(nodes_.size());
  std::vector<std::vector<int>> adjacency(nNodes);
  auto connect = [&](std::vector<int>& group) {
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
    for (int a : group)
      for (int b : group)
        if (a != b) adjacency[a].push_back(b);
  };
  std::vector<int> group;
  for (const auto& [tag, e] : domain.elements()) {
    group.clear();
    for (const Node* n : e->nodes()) {
      const int v = nodeIndex.at(n->tag());
      for (int f = nodeStart_[v]; f < nodeStart_[v + 1]; ++f)
        for (const auto& [g, c] : resolved[f]) group.push_back(ownerNode[g]);
    }
    connect(group);
  }
  if (!eliminate)
    for (const auto& mp : domain.mps()) {
      group = {nodeIndex.at(mp.retainedNode), nodeIndex.at(mp.constrainedNode)};
      connect(group);
    }
  for (auto& a : adjacency) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  const std::vector<int> order = numberer.order(adjacency);
  std::vector<int> equationOf(nFull, -1);
  equationOwner_.clear();
  int neq = 0;
  for (int v : order)
    for (int f = nodeStart_[v]; f < nodeStart_[v + 1]; ++f)
      if (kind[f] == Free) {
        equationOf[f] = neq++;
        equationOwner_.push_back({nodes_[v]->tag(), f - nodeStart_[v]});
      }
  numEquations_ = neq;

  fullTerms_.clear();
  fullTermStart_.assign(1, 0);
  for (int f = 0; f < nFull; ++f) {
    for (const auto& [g, c] : resolved[f]) fullTerms_.push_back({equationOf[g], c});
    fullTermStart_.push_back(static_cast<int>(fullTerms_.size()));
  }

  // --- element terms ------------------------------------------------------------
  elementMaps_.clear();
  elements_.clear();
  elementTerms_.clear();
  elementTermStart_.assign(1, 0);
  std::vector<std::vector<int>> columns(neq);
  std::vector<int> eqs;
  for (const auto& [tag, e] : domain.elements()) {
    ElementMap m{static_cast<int>(elementTermStart_.size()) - 1, 0, e->numDOF(), true};
    eqs.clear();
    for (const Node* n : e->nodes()) {
      const int v = nodeIndex.at(n->tag());
      for (int f = nodeStart_[v]; f < nodeStart_[v + 1]; ++f) {
        const int count = fullTermStart_[f + 1] - fullTermStart_[f];
        if (count > 1 || (count == 1 && fullTerms_[fullTermStart_[f]].coefficient != 1.0)) m.simple = false;
        for (int k = fullTermStart_[f]; k < fullTermStart_[f + 1]; ++k) {
          elementTerms_.push_back(fullTerms_[k]);
          eqs.push_back(fullTerms_[k].equation);
        }
        elementTermStart_.push_back(static_cast<int>(elementTerms_.size()));
      }
    }
    std::sort(eqs.begin(), eqs.end());
    eqs.erase(std::unique(eqs.begin(), eqs.end()), eqs.end());
    for (int c : eqs) columns[c].insert(columns[c].end(), eqs.begin(), eqs.end());
    elementMaps_.push_back(m);
    elements_.push_back(e.get());
  }

  // --- nodal terms -----------------------------------------------------------------
  // A nodal mass on a dof tied to several equations (a node constrained by a
  // rigidLink) couples them all (T^T m T in AnalysisModel::assembleMass), even
  // where no element does. The pattern holds these couplings for every such
  // dof: a mass may be set after the pattern is built.
  for (std::size_t f = 0; f + 1 < fullTermStart_.size(); ++f) {
    const int first = fullTermStart_[f], last = fullTermStart_[f + 1];
    if (last - first < 2) continue;
    for (int b = first; b < last; ++b)
      for (int a = first; a < last; ++a) columns[fullTerms_[b].equation].push_back(fullTerms_[a].equation);
  }

  // --- penalty terms -------------------------------------------------------------
  penaltySPs_.clear();
  penaltyMPs_.clear();
  if (!eliminate) {
    for (const auto& mp : domain.mps())
      for (std::size_t i = 0; i < mp.constrainedDofs.size(); ++i) {
        PenaltyMP p;
        const int fc = fullOf(mp.constrainedNode, mp.constrainedDofs[i]);
        p.row.push_back({fc, equationOf[fc], 1.0});
        for (std::size_t k = 0; k < mp.retainedDofs.size(); ++k)
          if (mp.C(i, k) != 0.0) {
            const int fr = fullOf(mp.retainedNode, mp.retainedDofs[k]);
            p.row.push_back({fr, equationOf[fr], -mp.C(i, k)});
          }
        for (const auto& a : p.row)
          for (const auto& b : p.row) columns[b.equation].push_back(a.equation);
        penaltyMPs_.push_back(std::move(p));
      }
  }

  // --- compressed-column pattern, always with the diagonal ----------------------
  colStart_.assign(1, 0);
  rowIndex_.clear();
  for (int c = 0; c < neq; ++c) {
    auto& col = columns[c];
    col.push_back(c);
    std::sort(col.begin(), col.end());
    col.erase(std::unique(col.begin(), col.end()), col.end());
    rowIndex_.insert(rowIndex_.end(), col.begin(), col.end());
    colStart_.push_back(static_cast<int>(rowIndex_.size()));
    std::vector<int>().swap(col);
  }
  diagPos_.resize(neq);
  for (int c = 0; c < neq; ++c) diagPos_[c] = position(c, c);

  if (!eliminate)
    for (int f : imposedFull_) penaltySPs_.push_back({f, equationOf[f], diagPos_[equationOf[f]]});
  for (auto& p : penaltyMPs_)
    for (const auto& b : p.row)
      for (const auto& a : p.row) p.positions.push_back(position(a.equation, b.equation));

  // --- scatter positions -----------------------------------------------------------
  scatterPositions_.clear();
  generalScatter_.clear();
  generalScatterEnd_.clear();
  for (std::size_t e = 0; e < elementMaps_.size(); ++e) {
    ElementMap& m = elementMaps_[e];
    const int n = m.numDOF;
    const int* ts = elementTermStart_.data() + m.termStart;
    if (m.simple) {
      m.scatterStart = static_cast<int>(scatterPositions_.size());
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const bool fi = ts[i + 1] > ts[i], fj = ts[j + 1] > ts[j];
          scatterPositions_.push_back(fi && fj ? position(elementTerms_[ts[i]].equation, elementTerms_[ts[j]].equation)
                                               : -1);
        }
    } else {
      m.scatterStart = static_cast<int>(generalScatter_.size());
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          for (int a = ts[i]; a < ts[i + 1]; ++a)
            for (int b = ts[j]; b < ts[j + 1]; ++b)
              generalScatter_.push_back({i + j * n, position(elementTerms_[a].equation, elementTerms_[b].equation),
                                         elementTerms_[a].coefficient * elementTerms_[b].coefficient});
    }
    generalScatterEnd_.push_back(static_cast<int>(generalScatter_.size()));
  }
  stamp_ = domain.modelStamp();
}

}  // namespace beamsolid
