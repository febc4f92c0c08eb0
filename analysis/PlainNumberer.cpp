#include <memory>
#include <numeric>

#include "analysis/Numberer.h"
#include "core/Registry.h"

namespace beamsolid {
namespace {

// Nodes in tag order.
class PlainNumberer : public Numberer {
 public:
  std::string name() const override { return "Plain"; }
  std::vector<int> order(const std::vector<std::vector<int>>& adjacency) const override {
    std::vector<int> p(adjacency.size());
    std::iota(p.begin(), p.end(), 0);
    return p;
  }
};

void registerPlainNumberer(Registry& r) {
  // 'ParallelPlain' (OpenSeesSP/MP's name) numbers the same way in one process.
  for (const char* name : {"Plain", "ParallelPlain"})
    r.numberers.add(name, [](CommandArgs& args, Domain&) -> std::unique_ptr<Numberer> {
      args.expectEnd();
      return std::make_unique<PlainNumberer>();
    });
}

}  // namespace
BEAMSOLID_REGISTER(registerPlainNumberer);
}  // namespace beamsolid
