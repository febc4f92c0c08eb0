#include "core/BlasThreads.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <vector>

namespace beamsolid {

namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

// Every OpenBLAS copy the solvers may call: SuiteSparse can resolve BLAS and
// LAPACK to different files of one OpenBLAS build, each with its own pool.
struct Library {
  SetThreads set = nullptr;
  GetThreads get = nullptr;
};

struct State {
  std::vector<Library> libraries;
  int available = 1;
  bool userSet = false;
};

const State& state() {
  static State s;
  static std::once_flag once;
  std::call_once(once, [] {
    const char* names[] = {"libopenblas.so.0", "libblas.so.3", "liblapack.so.3"};
    std::vector<void*> seen;
    auto add = [&](void* set, void* get) {
      if (!set || !get) return;
      for (void* p : seen)
        if (p == set) return;
      seen.push_back(set);
      s.libraries.push_back({reinterpret_cast<SetThreads>(set), reinterpret_cast<GetThreads>(get)});
    };
    add(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"), dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    for (const char* name : names)
      if (void* h = dlopen(name, RTLD_LAZY | RTLD_NOLOAD)) {
        add(dlsym(h, "openblas_set_num_threads"), dlsym(h, "openblas_get_num_threads"));
        dlclose(h);  // NOLOAD: only drops the reference this call took
      }
    for (const auto& l : s.libraries) s.available = std::max(s.available, l.get());
    s.userSet = std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS");
  });
  return s;
}

}  // namespace

int BlasThreads::available() { return state().available; }
bool BlasThreads::userSet() { return state().userSet; }

int BlasThreads::current() {
  int n = 1;
  for (const auto& l : state().libraries) n = std::max(n, l.get());
  return n;
}

void BlasThreads::set(int threads) {
  if (userSet()) return;
  if (threads < 1) threads = 1;
  if (threads > available()) threads = available();
  for (const auto& l : state().libraries)
    if (l.get() != threads) l.set(threads);
}

BlasThreads::Scope::Scope(int threads) : previous_(current()) { set(threads); }
BlasThreads::Scope::~Scope() { set(previous_); }

}  // namespace beamsolid
