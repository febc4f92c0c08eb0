#pragma once
#include <charconv>
#include <string>
#include <vector>

#include "core/Response.h"
#include "core/Types.h"

namespace beamsolid {

// What the spring elements (zeroLength, twoNodeLink) answer alike: their
// axes, one spring's material, and parameters for every spring's material.
// `Springs` is a container of structs with a `material` pointer.
struct SpringResponses {
  // 'xaxis'/'xlocal' (and y, z): that row of `axes` (kept by the element,
  // which outlives the response); an empty Response for other names.
  static Response axis(const std::string& what, const Matrix3& axes) {
    for (int row = 0; row < 3; ++row) {
      const std::string name(1, "xyz"[row]);
      if (what == name + "axis" || what == name + "local")
        return {{name + "_X", name + "_Y", name + "_Z"}, [&axes, row] { return Vector(axes.row(row).transpose()); }};
    }
    return {};
  }

  // 'material', k, ...: spring k's (1-based) material response.
  template <typename Springs>
  static Response material(const std::vector<std::string>& args, const Springs& springs) {
    if (args.size() < 2 || args[0] != "material") return {};
    int k = 0;
    const std::string& s = args[1];
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), k);
    if (ec != std::errc() || ptr != s.data() + s.size() || k < 1 || k > static_cast<int>(springs.size())) return {};
    return springs[k - 1].material->setResponse(std::vector<std::string>(args.begin() + 2, args.end()));
  }

  template <typename Springs>
  static bool setParameter(Springs& springs, const std::vector<std::string>& args, double value) {
    bool accepted = false;
    for (auto& s : springs) accepted = s.material->setParameter(args, value) || accepted;
    return accepted;
  }
};

}  // namespace beamsolid
