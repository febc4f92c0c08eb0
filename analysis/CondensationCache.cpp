#include "analysis/CondensationCache.h"

#include <cholmod.h>

#include <cstdlib>
#include <cstring>
#include <deque>
#include <mutex>

namespace beamsolid {

namespace {

struct Entry {
  CondensationCache::Key key;
  cholmod_factor* factor = nullptr;
  std::vector<double> coupling;
};

// The entries with a CHOLMOD common of their own for the copies; freed at exit.
struct Store {
  std::mutex mutex;
  cholmod_common common;
  std::deque<Entry> entries;
  long hits = 0;
  Store() {
    cholmod_start(&common);
    common.print = 0;
    common.error_handler = nullptr;
  }
  ~Store() {
    for (Entry& e : entries)
      if (e.factor) cholmod_free_factor(&e.factor, &common);
    cholmod_finish(&common);
  }
  void drop() {
    if (entries.back().factor) cholmod_free_factor(&entries.back().factor, &common);
    entries.pop_back();
  }
};

Store& theStore() {
  static Store s;
  return s;
}

std::size_t bytesOf(const CondensationCache::Key& k, const cholmod_factor* f, const std::vector<double>& coupling) {
  std::size_t n = coupling.size() * sizeof(double);
  n += (k.iiValues.size() + k.ibValues.size() + k.biValues.size()) * (sizeof(double) + 2 * sizeof(int));
  if (f) n += (f->is_super ? f->xsize : f->nzmax) * sizeof(double);
  return n;
}

}  // namespace

bool CondensationCache::Key::operator==(const Key& o) const {
  return interior == o.interior && iiStart == o.iiStart && iiRow == o.iiRow && ibStart == o.ibStart &&
         ibRow == o.ibRow && biRow == o.biRow && biCol == o.biCol && iiValues == o.iiValues &&
         ibValues == o.ibValues && biValues == o.biValues;
}

bool CondensationCache::enabled() {
  const char* env = std::getenv("BEAMSOLID_CONDENSE_CACHE");
  return !(env && (!std::strcmp(env, "off") || !std::strcmp(env, "0")));
}

bool CondensationCache::find(const Key& key, void* common, cholmod_factor** factor, std::vector<double>& coupling) {
  Store& s = theStore();
  std::lock_guard<std::mutex> lock(s.mutex);
  for (auto it = s.entries.begin(); it != s.entries.end(); ++it) {
    if (!(it->key == key)) continue;
    cholmod_factor* copy = nullptr;
    if (it->factor) {
      copy = cholmod_copy_factor(it->factor, static_cast<cholmod_common*>(common));
      if (!copy) return false;
    }
    *factor = copy;
    coupling = it->coupling;
    ++s.hits;
    if (it != s.entries.begin()) {  // most recent first
      Entry e = std::move(*it);
      s.entries.erase(it);
      s.entries.push_front(std::move(e));
    }
    return true;
  }
  return false;
}

void CondensationCache::store(const Key& key, const cholmod_factor* factor, const std::vector<double>& coupling) {
  if (bytesOf(key, factor, coupling) > kMaxBytes) return;
  Store& s = theStore();
  std::lock_guard<std::mutex> lock(s.mutex);
  Entry e;
  e.key = key;
  if (factor) {
    e.factor = cholmod_copy_factor(const_cast<cholmod_factor*>(factor), &s.common);
    if (!e.factor) return;
  }
  e.coupling = coupling;
  s.entries.push_front(std::move(e));
  while (s.entries.size() > 2) s.drop();
}

long CondensationCache::hits() {
  Store& s = theStore();
  std::lock_guard<std::mutex> lock(s.mutex);
  return s.hits;
}

}  // namespace beamsolid
