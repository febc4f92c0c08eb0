#pragma once
#include <unordered_map>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

class ConstraintHandler;
class Domain;
class Element;
class Node;
class Numberer;

// Equation numbers for every node dof after constraints (OpenSees'
// AnalysisModel + DOF_Groups). Each node dof is a combination of equations,
// u_f = sum coef * U[eq] (+ a prescribed value): one term for a free dof,
// none for a fixed one, several for an MP-constrained one. The compressed-
// column pattern of the global matrix and each element's scatter positions
// into it are built here once per model change.
class DofMap {
 public:
  // Warnings are said once per model (a dof map is rebuilt by every
  // analysis); a new model or wipe() lets them be said again.
  static void resetWarnings();

  struct Term {
    int equation;
    double coefficient;
  };

  void build(const Domain& domain, const ConstraintHandler& handler, const Numberer& numberer);

  int numEquations() const { return numEquations_; }
  long builtForStamp() const { return stamp_; }

  // --- nodes ---------------------------------------------------------------
  const std::vector<Node*>& nodes() const { return nodes_; }
  // Owner of full dof f: (node, dof).
  Node* nodeOfFull(int f) const { return fullOwner_[f].first; }
  int dofOfFull(int f) const { return fullOwner_[f].second; }
  // First full dof of the node with this tag, -1 if unknown.
  int fullStartOfNode(int nodeTag) const;
  int numFullDofs() const { return static_cast<int>(fullTermStart_.size()) - 1; }
  const Term* fullTermsBegin(int full) const { return fullTerms_.data() + fullTermStart_[full]; }
  const Term* fullTermsEnd(int full) const { return fullTerms_.data() + fullTermStart_[full + 1]; }
  // (node, dof) of equation eq, for messages.
  std::pair<int, int> nodeDofOfEquation(int eq) const { return equationOwner_[eq]; }

  // --- elements (in Domain order) ------------------------------------------
  struct ElementMap {
    int termStart;   // into elementTerms_, one range per local dof
    int scatterStart;  // into scatterPositions_ (simple) or generalScatter_ (general)
    int numDOF;
    bool simple;     // every local dof is free with coefficient 1, or fixed
  };
  const std::vector<ElementMap>& elementMaps() const { return elementMaps_; }
  const std::vector<Element*>& elements() const { return elements_; }
  // Terms of local dof i of element e: [begin, end).
  const Term* elementTermsBegin(int e, int i) const { return elementTerms_.data() + elementTermStart_[elementMaps_[e].termStart + i]; }
  const Term* elementTermsEnd(int e, int i) const { return elementTerms_.data() + elementTermStart_[elementMaps_[e].termStart + i + 1]; }
  // Simple elements: position of local (i, j) in the values array, -1 if fixed.
  const int* scatterPositions(int e) const { return scatterPositions_.data() + elementMaps_[e].scatterStart; }
  struct GeneralScatter {
    int local;     // i + j * numDOF
    int position;  // into the values array
    double coefficient;
  };
  const GeneralScatter* generalScatterBegin(int e) const;
  const GeneralScatter* generalScatterEnd(int e) const;

  // --- the sparsity pattern (compressed column, full storage) --------------
  const std::vector<int>& columnStart() const { return colStart_; }
  const std::vector<int>& rowIndex() const { return rowIndex_; }
  int position(int row, int col) const;  // -1 if not in the pattern
  const std::vector<int>& diagonalPosition() const { return diagPos_; }

  // --- prescribed values (elimination handlers) -----------------------------
  // Full dofs set from the Domain's imposed values, in Domain::imposedValues order; -1 where a multi-point
  // constraint overrides the value (Transformation).
  const std::vector<int>& imposedFullDofs() const { return imposedFull_; }
  // MP-constrained full dofs in dependency order, with their expression in
  // terms of other full dofs: u_c = sum coef * u[full].
  struct Dependent {
    int full;
    std::vector<std::pair<int, double>> sources;
  };
  const std::vector<Dependent>& dependents() const { return dependents_; }

  // --- penalty handler: extra terms ------------------------------------------
  struct PenaltySP {
    int full;
    int equation;
    int diagPosition;
  };
  const std::vector<PenaltySP>& penaltySPs() const { return penaltySPs_; }
  struct PenaltyMP {
    // constraint row: g = sum coef * u[full] (= u_c - C u_r)
    struct Entry {
      int full;
      int equation;
      double coefficient;
    };
    std::vector<Entry> row;
    std::vector<int> positions;  // row.size()^2 positions into values, column by column
  };
  const std::vector<PenaltyMP>& penaltyMPs() const { return penaltyMPs_; }

 private:
  int numEquations_ = 0;
  long stamp_ = -1;
  std::vector<Node*> nodes_;
  std::vector<int> nodeStart_;
  std::unordered_map<int, int> nodeIndex_;
  std::vector<Term> fullTerms_;
  std::vector<int> fullTermStart_;
  std::vector<std::pair<int, int>> equationOwner_;
  std::vector<std::pair<Node*, int>> fullOwner_;
  std::vector<Element*> elements_;

  std::vector<ElementMap> elementMaps_;
  std::vector<Term> elementTerms_;
  std::vector<int> elementTermStart_;
  std::vector<int> scatterPositions_;
  std::vector<GeneralScatter> generalScatter_;
  std::vector<int> generalScatterEnd_;

  std::vector<int> colStart_, rowIndex_, diagPos_;

  std::vector<int> imposedFull_;
  std::vector<Dependent> dependents_;
  std::vector<PenaltySP> penaltySPs_;
  std::vector<PenaltyMP> penaltyMPs_;
};

}  // namespace beamsolid
