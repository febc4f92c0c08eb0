#include <amd.h>

#include <memory>

#include "analysis/Numberer.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {
namespace {

// Approximate minimum degree ordering of the node graph, by SuiteSparse AMD.
class AMDNumberer : public Numberer {
 public:
  std::string name() const override { return "AMD"; }
  std::vector<int> order(const std::vector<std::vector<int>>& adj) const override {
    const int n = static_cast<int>(adj.size());
    std::vector<int> colPtr(n + 1, 0), rowIdx;
    for (int v = 0; v < n; ++v) {
      for (int w : adj[v]) rowIdx.push_back(w);
      colPtr[v + 1] = static_cast<int>(rowIdx.size());
    }
    std::vector<int> perm(n);
    if (n == 0) return perm;
    // AMD accepts unsorted columns with duplicates through amd_order's preprocessing.
    const int status = amd_order(n, colPtr.data(), rowIdx.empty() ? nullptr : rowIdx.data(), perm.data(),
                                 nullptr, nullptr);
    if (status < AMD_OK) throw OpenSeesError("numberer AMD: ordering failed (status " + std::to_string(status) + ")");
    return perm;
  }
};

void registerAMDNumberer(Registry& r) {
  r.numberers.add("AMD", [](CommandArgs& args, Domain&) -> std::unique_ptr<Numberer> {
    args.expectEnd();
    return std::make_unique<AMDNumberer>();
  });
}

}  // namespace
BEAMSOLID_REGISTER(registerAMDNumberer);
}  // namespace beamsolid
