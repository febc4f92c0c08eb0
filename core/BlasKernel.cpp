#include "core/BlasKernel.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace beamsolid {

namespace {

struct KernelSpec {
  std::vector<std::string> flags;
  int tier;
};

// The x86-64 kernels of OpenBLAS's DYNAMIC_ARCH builds, with the instructions
// their code needs (from the processors they were written for) and how wide
// their double-precision code is. Only these are compared or chosen.
const std::map<std::string, KernelSpec>& kernels() {
  static const std::vector<std::string> avx512 = {"avx512f", "avx512bw", "avx512vl", "avx512dq", "avx512cd"};
  static const std::map<std::string, KernelSpec> table = [] {
    std::map<std::string, KernelSpec> t = {
        {"OPTERON", {{"sse2"}, 0}},
        {"OPTERON_SSE3", {{"sse2", "pni"}, 0}},
        {"PRESCOTT", {{"sse2", "pni"}, 0}},
        {"CORE2", {{"sse2", "pni", "ssse3"}, 1}},
        {"NANO", {{"sse2", "pni", "ssse3"}, 1}},
        {"PENRYN", {{"sse2", "pni", "ssse3", "sse4_1"}, 1}},
        {"DUNNINGTON", {{"sse2", "pni", "ssse3", "sse4_1"}, 1}},
        {"NEHALEM", {{"sse2", "pni", "ssse3", "sse4_1", "sse4_2"}, 1}},
        {"BARCELONA", {{"sse2", "pni", "sse4a"}, 1}},
        {"BOBCAT", {{"sse2", "pni", "ssse3", "sse4a"}, 1}},
        {"SANDYBRIDGE", {{"sse4_2", "avx"}, 2}},
        {"BULLDOZER", {{"sse4_2", "avx", "fma4"}, 2}},
        {"PILEDRIVER", {{"sse4_2", "avx", "fma"}, 2}},
        {"STEAMROLLER", {{"sse4_2", "avx", "fma"}, 2}},
        {"EXCAVATOR", {{"sse4_2", "avx", "avx2", "fma"}, 3}},
        {"HASWELL", {{"sse4_2", "avx", "avx2", "fma"}, 3}},
        {"ZEN", {{"sse4_2", "avx", "avx2", "fma"}, 3}},
    };
    std::vector<std::string> skx = {"avx", "avx2", "fma"};
    skx.insert(skx.end(), avx512.begin(), avx512.end());
    t["SKYLAKEX"] = {skx, 4};
    auto cpx = skx;
    cpx.push_back("avx512_bf16");
    t["COOPERLAKE"] = {cpx, 4};
    auto spr = cpx;
    spr.insert(spr.end(), {"avx512_fp16", "amx_tile", "amx_bf16"});
    t["SAPPHIRERAPIDS"] = {spr, 4};
    return t;
  }();
  return table;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

// "OpenBLAS 0.3.21 NO_LAPACKE DYNAMIC_ARCH ..." -> "OpenBLAS 0.3.21".
std::string versionOf(const std::string& config) {
  const auto second = config.find(' ', config.find(' ') + 1);
  return config.substr(0, second);
}

// The flags that set a kernel's tier apart from the one below: what a reader
// needs to see in a reason.
std::vector<std::string> telling(const std::string& kernel) {
  switch (BlasKernel::tier(kernel)) {
    case 4: return {"avx512f", "avx512bw", "avx512vl", "avx512dq", "avx512cd"};
    case 3: return {"avx2", "fma"};
    case 2: return {"avx"};
    case 1: return {"ssse3"};
    default: return {"sse2"};
  }
}

}  // namespace

bool BlasKernel::Cpu::has(const std::vector<std::string>& required) const { return missing(required).empty(); }

std::vector<std::string> BlasKernel::Cpu::missing(const std::vector<std::string>& required) const {
  std::vector<std::string> out;
  for (const std::string& f : required)
    if (!flags.count(f)) out.push_back(f);
  return out;
}

BlasKernel::Cpu BlasKernel::thisCpu() {
  Cpu cpu;
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  cpu.vendor = __builtin_cpu_is("intel") ? "intel" : __builtin_cpu_is("amd") ? "amd" : "other";
  // __builtin_cpu_supports also asks the operating system whether it saves
  // the wide registers (XGETBV), as /proc/cpuinfo does.
#define BEAMSOLID_FLAG(gcc, cpuinfo) \
  if (__builtin_cpu_supports(gcc)) cpu.flags.insert(cpuinfo);
  BEAMSOLID_FLAG("sse2", "sse2")
  BEAMSOLID_FLAG("sse3", "pni")
  BEAMSOLID_FLAG("ssse3", "ssse3")
  BEAMSOLID_FLAG("sse4.1", "sse4_1")
  BEAMSOLID_FLAG("sse4.2", "sse4_2")
  BEAMSOLID_FLAG("sse4a", "sse4a")
  BEAMSOLID_FLAG("fma4", "fma4")
  BEAMSOLID_FLAG("avx", "avx")
  BEAMSOLID_FLAG("avx2", "avx2")
  BEAMSOLID_FLAG("fma", "fma")
  BEAMSOLID_FLAG("avx512f", "avx512f")
  BEAMSOLID_FLAG("avx512bw", "avx512bw")
  BEAMSOLID_FLAG("avx512vl", "avx512vl")
  BEAMSOLID_FLAG("avx512dq", "avx512dq")
  BEAMSOLID_FLAG("avx512cd", "avx512cd")
  BEAMSOLID_FLAG("avx512bf16", "avx512_bf16")
  BEAMSOLID_FLAG("avx512fp16", "avx512_fp16")
  BEAMSOLID_FLAG("amx-tile", "amx_tile")
  BEAMSOLID_FLAG("amx-bf16", "amx_bf16")
#undef BEAMSOLID_FLAG
#else
  cpu.vendor = "other";
#endif
  return cpu;
}

std::optional<BlasKernel::Loaded> BlasKernel::loaded() {
  // The OpenBLAS that SuiteSparse resolved to: from this library's own scope
  // (RTLD_DEFAULT searches the caller's dependencies), or by its usual name.
  void* corename = dlsym(RTLD_DEFAULT, "openblas_get_corename");
  if (!corename) {
    if (void* handle = dlopen("libopenblas.so.0", RTLD_LAZY | RTLD_NOLOAD)) {
      corename = dlsym(handle, "openblas_get_corename");
      dlclose(handle);
    }
  }
  if (!corename) return std::nullopt;
  Dl_info where{};
  Loaded l;
  if (dladdr(corename, &where) && where.dli_fname) l.library = where.dli_fname;
  void* handle = dlopen(l.library.c_str(), RTLD_LAZY | RTLD_NOLOAD);
  auto symbol = [&](const char* name) { return handle ? dlsym(handle, name) : dlsym(RTLD_DEFAULT, name); };
  l.core = reinterpret_cast<char* (*)()>(corename)();
  if (auto f = reinterpret_cast<char* (*)()>(symbol("openblas_get_config"))) l.config = f();
  if (auto f = reinterpret_cast<int (*)()>(symbol("openblas_get_num_threads"))) l.threads = f();
  if (handle) dlclose(handle);
  return l;
}

std::optional<std::vector<std::string>> BlasKernel::requiredFlags(const std::string& kernel) {
  auto it = kernels().find(upper(kernel));
  if (it == kernels().end()) return std::nullopt;
  return it->second.flags;
}

int BlasKernel::tier(const std::string& kernel) {
  auto it = kernels().find(upper(kernel));
  return it == kernels().end() ? -1 : it->second.tier;
}

std::string BlasKernel::best(const Cpu& cpu) {
  // Among kernels of one tier, the plainest: one every OpenBLAS release since
  // 0.3.0 has (COOPERLAKE and SAPPHIRERAPIDS differ from SKYLAKEX only in
  // bfloat16 code), tuned for the CPU's maker where that differs.
  for (const char* k : {"SKYLAKEX", cpu.vendor == "amd" ? "ZEN" : "HASWELL", "SANDYBRIDGE", "NEHALEM", "CORE2",
                        "PRESCOTT"})
    if (cpu.has(kernels().at(k).flags)) return k;
  return "OPTERON";
}

BlasKernel::Choice BlasKernel::choose(const Cpu& cpu, const std::string& detected, const std::string& setting,
                                      const std::string& config) {
  if (config.empty()) return {"", "the BLAS in use is not OpenBLAS: there is no kernel to choose", ""};
  const std::string version = versionOf(config);
  std::string warning;
  if (!setting.empty()) {
    const auto required = requiredFlags(setting);
    if (!required)
      return {setting,
              "OPENBLAS_CORETYPE=" + setting + " was set before BeamSolid started; BeamSolid does not know that " +
                  "kernel name and leaves it to " + version,
              ""};
    const auto missing = cpu.missing(*required);
    if (missing.empty())
      return {setting,
              "OPENBLAS_CORETYPE=" + setting + " was set before BeamSolid started (by the user or the machine) " +
                  "and this CPU runs it",
              ""};
    warning = "OPENBLAS_CORETYPE=" + setting + " needs " + joined(missing) +
              ", which this CPU lacks (it would stop with 'Illegal instruction'); BeamSolid chose again";
  }
  const std::string want = best(cpu);
  const std::string flags = joined(telling(want));
  if (detected.empty())
    return {want, version + "'s own pick is not known here; " + want + " is the widest kernel this CPU runs (" +
                      flags + ")",
            warning};
  if (tier(detected) >= tier(want))
    return {"", version + " picks " + detected + " itself, which uses this CPU's widest vector instructions (" +
                    flags + ")",
            warning};
  return {want,
          version + " picks " + detected + " on this " + cpu.vendor + " CPU, which has " + flags + "; " + want +
              " uses them",
          warning};
}

BlasKernel::Choice BlasKernel::chooseForThisProcess() {
  const char* settingEnv = std::getenv(kCoreTypeVariable);
  const std::string setting = settingEnv ? settingEnv : "";
  if (const char* made = std::getenv(kChoiceVariable)) {
    if (auto c = decode(made); c && c->kernel == setting) return *c;
  }
  const auto l = loaded();
  // With a setting in force the loaded kernel is the setting, not OpenBLAS's own pick.
  return choose(thisCpu(), l && setting.empty() ? l->core : "", setting, l ? l->config : "");
}

std::string BlasKernel::encode(const Choice& c) { return c.kernel + "|" + c.reason + "|" + c.warning; }

std::optional<BlasKernel::Choice> BlasKernel::decode(const std::string& text) {
  const auto a = text.find('|');
  if (a == std::string::npos) return std::nullopt;
  const auto b = text.find('|', a + 1);
  if (b == std::string::npos) return std::nullopt;
  return Choice{text.substr(0, a), text.substr(a + 1, b - a - 1), text.substr(b + 1)};
}

void BlasKernel::applyOrReexec(char** argv) {
  const char* settingEnv = std::getenv(kCoreTypeVariable);
  const std::string setting = settingEnv ? settingEnv : "";
  const bool madeByParent = std::getenv(kChoiceVariable) != nullptr;
  const Choice c = chooseForThisProcess();
  setenv(kChoiceVariable, encode(c).c_str(), 1);
  if (c.kernel == setting) return;
  if (!madeByParent && !c.warning.empty()) std::fprintf(stderr, "beamsolid: %s\n", c.warning.c_str());
  if (c.kernel.empty()) unsetenv(kCoreTypeVariable);
  else setenv(kCoreTypeVariable, c.kernel.c_str(), 1);
  execv("/proc/self/exe", argv);
  // Could not re-execute: carry on with the kernel OpenBLAS loaded.
  std::fprintf(stderr, "beamsolid: could not re-execute to set OPENBLAS_CORETYPE=%s\n", c.kernel.c_str());
}

}  // namespace beamsolid
