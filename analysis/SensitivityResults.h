#pragma once
#include <unordered_map>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

// What the last sensitivity computation found: d u / d theta of every node
// dof, one column per parameter (in the order of parameterTags).
struct SensitivityResults {
  std::vector<int> parameterTags;
  std::unordered_map<int, Matrix> nodeDisp;  // node tag -> ndf x parameters
  std::vector<double> lambda;                 // d lambda / d theta (the Domain's time), per parameter

  void clear() {
    parameterTags.clear();
    nodeDisp.clear();
    lambda.clear();
  }
  // Column of parameter `tag`, -1 if it has none.
  int gradientOf(int tag) const {
    for (std::size_t k = 0; k < parameterTags.size(); ++k)
      if (parameterTags[k] == tag) return static_cast<int>(k);
    return -1;
  }
};

}  // namespace beamsolid
