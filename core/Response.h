#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

// A response an element or material offers to eleResponse and recorders:
// built once from the argument list, read at every record.
struct Response {
  // One name per component, e.g. {"Px_1", "Py_1", ...}; used for recorder sidecars.
  std::vector<std::string> componentNames;
  std::function<Vector()> value;

  explicit operator bool() const { return static_cast<bool>(value); }
  std::size_t size() const { return componentNames.size(); }

  // Helper: a response whose components are named prefix1, prefix2, ...
  static Response named(std::vector<std::string> names, std::function<Vector()> f) {
    return Response{std::move(names), std::move(f)};
  }
  static std::vector<std::string> numberedNames(const std::string& prefix, int count) {
    std::vector<std::string> names;
    for (int i = 1; i <= count; ++i) names.push_back(prefix + std::to_string(i));
    return names;
  }
};

}  // namespace beamsolid
