#include <algorithm>
#include <memory>
#include <queue>

#include "analysis/Numberer.h"
#include "core/Registry.h"

namespace beamsolid {
namespace {

// Reverse Cuthill-McKee: breadth-first levels from a pseudo-peripheral
// vertex, neighbours by increasing degree, then reversed. Neither Eigen nor
// SuiteSparse ships RCM, so it is written here.
class RCMNumberer : public Numberer {
 public:
  std::string name() const override { return "RCM"; }

  std::vector<int> order(const std::vector<std::vector<int>>& adj) const override {
    const int n = static_cast<int>(adj.size());
    std::vector<int> result;
    result.reserve(n);
    std::vector<char> visited(n, 0);
    for (int seed = 0; seed < n; ++seed) {
      if (visited[seed]) continue;
      const int start = pseudoPeripheral(adj, seed);
      std::queue<int> q;
      q.push(start);
      visited[start] = 1;
      std::vector<int> nbrs;
      while (!q.empty()) {
        int v = q.front();
        q.pop();
        result.push_back(v);
        nbrs.clear();
        for (int w : adj[v])
          if (!visited[w]) { visited[w] = 1; nbrs.push_back(w); }
        std::sort(nbrs.begin(), nbrs.end(), [&](int a, int b) { return adj[a].size() < adj[b].size(); });
        for (int w : nbrs) q.push(w);
      }
    }
    std::reverse(result.begin(), result.end());
    return result;
  }

 private:
  // Repeated BFS: the last vertex of the deepest level, until eccentricity stops growing.
  static int pseudoPeripheral(const std::vector<std::vector<int>>& adj, int v) {
    int depth = -1;
    for (int pass = 0; pass < 8; ++pass) {
      std::vector<int> level(adj.size(), -1);
      std::queue<int> q;
      q.push(v);
      level[v] = 0;
      int last = v;
      while (!q.empty()) {
        int u = q.front();
        q.pop();
        if (level[u] > level[last] || (level[u] == level[last] && adj[u].size() < adj[last].size())) last = u;
        for (int w : adj[u])
          if (level[w] < 0) { level[w] = level[u] + 1; q.push(w); }
      }
      if (level[last] <= depth) break;
      depth = level[last];
      v = last;
    }
    return v;
  }
};

void registerRCMNumberer(Registry& r) {
  // 'ParallelRCM' (OpenSeesSP/MP's name) numbers the same way in one process.
  for (const char* name : {"RCM", "ParallelRCM"})
    r.numberers.add(name, [](CommandArgs& args, Domain&) -> std::unique_ptr<Numberer> {
      args.expectEnd();
      return std::make_unique<RCMNumberer>();
    });
}

}  // namespace
BEAMSOLID_REGISTER(registerRCMNumberer);
}  // namespace beamsolid
