#pragma once
#include <cstdint>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

// A single-point constraint: dof `dof` (0-based) of node `nodeTag` is held
// at `value` (times the pattern factor when it belongs to a load pattern).
struct SPConstraint {
  int nodeTag = 0;
  int dof = 0;
  double value = 0.0;
  // Belongs to a load pattern (sp command): value scales with its factor.
  int patternTag = -1;
  bool homogeneous() const { return value == 0.0; }
};

// A (node, dof) pair as one number, for sets of constrained dofs.
inline std::int64_t dofKey(int nodeTag, int dof) {
  return static_cast<std::int64_t>(static_cast<std::uint32_t>(nodeTag)) << 16 | dof;
}

// A multi-point constraint: u_c[constrainedDofs] = C * u_r[retainedDofs].
struct MPConstraint {
  int tag = 0;
  int retainedNode = 0;
  int constrainedNode = 0;
  std::vector<int> constrainedDofs;  // 0-based
  std::vector<int> retainedDofs;     // 0-based
  Matrix C;                          // constrainedDofs.size() x retainedDofs.size()
  std::string kind = "equalDOF";
};

}  // namespace beamsolid
