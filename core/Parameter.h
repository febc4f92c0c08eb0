#pragma once
#include <map>
#include <string>
#include <vector>

namespace beamsolid {

// parameter(tag, ...) and addToParameter: one named value mapped onto
// objects' arguments (an element's, as setParameter reaches them, or a
// node's coordinate). updateParameter sets it; sensitivityAlgorithm
// differentiates the response with respect to it.
struct Parameter {
  struct Target {
    std::string kind;  // "element" or "node"
    int tag = 0;
    std::vector<std::string> args;  // the element's parameter name, or the node's dim (1-based)
  };
  std::vector<Target> targets;
  double value = 0.0;
};

// The parameters of a model by tag; their order is the gradients' order.
using ParameterMap = std::map<int, Parameter>;

}  // namespace beamsolid
