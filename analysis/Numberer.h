#pragma once
#include <string>
#include <vector>

namespace beamsolid {

// Orders the nodes (vertices of the node adjacency graph) before their free
// dofs get consecutive equation numbers. Sparse direct solvers reorder again
// for fill, so the numberer changes equation numbers, not answers.
class Numberer {
 public:
  virtual ~Numberer() = default;
  virtual std::string name() const = 0;
  // adjacency[v] lists the neighbours of vertex v; returns the vertices in
  // their new order (a permutation of 0..n-1).
  virtual std::vector<int> order(const std::vector<std::vector<int>>& adjacency) const = 0;
};

}  // namespace beamsolid
