#pragma once
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace beamsolid {

// Which OpenBLAS kernel the sparse factorizations run on, and why.
//
// OpenBLAS picks its kernel from CPUID when it is loaded, unless
// OPENBLAS_CORETYPE names one. Some releases pick a slow generic kernel on CPUs
// newer than they are; a hard-coded OPENBLAS_CORETYPE is no cure, since a
// kernel the CPU cannot run dies with "Illegal instruction". So the choice is
// made here, from the CPU's own flags, once per process tree: a setting the
// user or the machine made is kept when the CPU runs it, OpenBLAS's own pick
// is kept when it already uses the CPU's widest vector instructions, and
// otherwise the best kernel the CPU runs is named. The variable must be set
// before OpenBLAS loads, so entry points (the Python package's import, the
// C++ test runner) ask before they load the solvers or re-execute themselves.
class BlasKernel {
 public:
  // CPU flags in /proc/cpuinfo's spelling (avx2, avx512f, pni for SSE3, ...).
  struct Cpu {
    std::string vendor;  // "intel", "amd" or "other"
    std::set<std::string> flags;
    bool has(const std::vector<std::string>& required) const;
    std::vector<std::string> missing(const std::vector<std::string>& required) const;
  };

  // The OpenBLAS loaded in this process.
  struct Loaded {
    std::string library;  // path of the file holding openblas_get_corename
    std::string config;   // openblas_get_config(): version and build options
    std::string core;     // openblas_get_corename(), e.g. "SkylakeX"
    int threads = 1;
  };

  // What OPENBLAS_CORETYPE should hold (empty: leave it unset) and why.
  struct Choice {
    std::string kernel;
    std::string reason;
    std::string warning;  // a setting that was not kept, and why
  };

  // The environment variables that carry a choice to this process's children,
  // so that it is made once per process tree.
  static constexpr const char* kCoreTypeVariable = "OPENBLAS_CORETYPE";
  static constexpr const char* kChoiceVariable = "BEAMSOLID_BLAS_CHOICE";

  static Cpu thisCpu();
  static std::optional<Loaded> loaded();

  // Upper-case kernel name -> the CPU flags its code needs; nullopt for a
  // name BeamSolid does not know.
  static std::optional<std::vector<std::string>> requiredFlags(const std::string& kernel);
  // 0 (SSE2/SSE3) .. 4 (AVX-512): how wide the kernel's double-precision code is.
  static int tier(const std::string& kernel);
  // The widest kernel the CPU runs.
  static std::string best(const Cpu& cpu);

  // The decision. `detected` is OpenBLAS's own pick with OPENBLAS_CORETYPE
  // unset (empty when unknown); `setting` is OPENBLAS_CORETYPE as the user or
  // the machine left it (empty when unset); `config` is openblas_get_config()
  // (empty when the BLAS is not OpenBLAS).
  static Choice choose(const Cpu& cpu, const std::string& detected, const std::string& setting,
                       const std::string& config);

  // For a process that has already loaded OpenBLAS (the C++ test runner, the
  // probe the Python package runs): the choice for this process, taking a
  // choice already made by a parent from kChoiceVariable.
  static Choice chooseForThisProcess();
  // Encodes a choice for kChoiceVariable, and back.
  static std::string encode(const Choice& c);
  static std::optional<Choice> decode(const std::string& text);

  // Called first in a main(): makes the choice and, when it names a kernel
  // other than the one loaded, sets OPENBLAS_CORETYPE and re-executes the
  // program (OpenBLAS reads the variable only when it loads).
  static void applyOrReexec(char** argv);
};

}  // namespace beamsolid
