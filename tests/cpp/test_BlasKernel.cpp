// The BLAS kernel choice: never a kernel the CPU cannot run, a runnable
// setting kept, OpenBLAS's own pick kept when it is already the widest, a
// generic fallback replaced. The CPU's flags are checked against
// /proc/cpuinfo, an independent reading of the same CPU.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/BlasKernel.h"

using beamsolid::BlasKernel;

namespace {

const std::string kConfig = "OpenBLAS 0.3.21 NO_LAPACKE DYNAMIC_ARCH NO_AFFINITY Prescott MAX_THREADS=64";

BlasKernel::Cpu cpu(const std::string& vendor, std::set<std::string> flags) { return {vendor, std::move(flags)}; }

// An AMD EPYC of the Zen 3 generation: AVX2 and FMA, no AVX-512.
BlasKernel::Cpu epycZen3() {
  return cpu("amd", {"sse2", "pni", "ssse3", "sse4_1", "sse4_2", "sse4a", "avx", "avx2", "fma"});
}

// A Xeon with AVX-512 and bfloat16.
BlasKernel::Cpu xeonAvx512() {
  return cpu("intel", {"sse2", "pni", "ssse3", "sse4_1", "sse4_2", "avx", "avx2", "fma", "avx512f", "avx512bw",
                       "avx512vl", "avx512dq", "avx512cd", "avx512_bf16"});
}

std::set<std::string> procCpuinfoFlags() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("flags", 0) == 0) {
      std::istringstream words(line.substr(line.find(':') + 1));
      std::set<std::string> flags;
      for (std::string w; words >> w;) flags.insert(w);
      return flags;
    }
  }
  return {};
}

void expectRunnable(const BlasKernel::Cpu& c, const std::string& kernel) {
  ASSERT_TRUE(BlasKernel::requiredFlags(kernel)) << kernel;
  EXPECT_TRUE(c.has(*BlasKernel::requiredFlags(kernel))) << kernel;
}

}  // namespace

TEST(BlasKernel, AForcedAvx512KernelOnAnAvx2CpuIsReplacedWithAWarning) {
  // The Makefile once exported SKYLAKEX: every AVX2-only machine died with Illegal instruction.
  const auto c = BlasKernel::choose(epycZen3(), "", "SKYLAKEX", kConfig);
  EXPECT_EQ(c.kernel, "ZEN");
  expectRunnable(epycZen3(), c.kernel);
  EXPECT_NE(c.warning.find("avx512f"), std::string::npos) << c.warning;
  EXPECT_NE(c.warning.find("Illegal instruction"), std::string::npos) << c.warning;
  // Knowing OpenBLAS's own pick, which is already the widest, the variable is dropped instead.
  const auto own = BlasKernel::choose(epycZen3(), "Zen", "SKYLAKEX", kConfig);
  EXPECT_EQ(own.kernel, "");
  EXPECT_FALSE(own.warning.empty());
}

TEST(BlasKernel, ARunnableSettingIsKept) {
  for (const char* setting : {"HASWELL", "Prescott", "SkylakeX", "COOPERLAKE"}) {
    const auto c = BlasKernel::choose(xeonAvx512(), "SkylakeX", setting, kConfig);
    EXPECT_EQ(c.kernel, setting);
    EXPECT_TRUE(c.warning.empty());
    EXPECT_NE(c.reason.find("was set before BeamSolid started"), std::string::npos) << c.reason;
  }
  // A name BeamSolid does not know is OpenBLAS's business: kept, not judged.
  EXPECT_EQ(BlasKernel::choose(xeonAvx512(), "SkylakeX", "LOONGSON3R5", kConfig).kernel, "LOONGSON3R5");
}

TEST(BlasKernel, AGenericFallbackIsReplacedWithTheWidestKernelTheCpuRuns) {
  const auto c = BlasKernel::choose(xeonAvx512(), "Prescott", "", kConfig);
  EXPECT_EQ(c.kernel, "SKYLAKEX");
  EXPECT_NE(c.reason.find("OpenBLAS 0.3.21 picks Prescott"), std::string::npos) << c.reason;
  EXPECT_EQ(BlasKernel::choose(xeonAvx512(), "Haswell", "", kConfig).kernel, "SKYLAKEX");
  EXPECT_EQ(BlasKernel::choose(epycZen3(), "Sandybridge", "", kConfig).kernel, "ZEN");
  // Intel's AVX2 kernel for an Intel CPU without AVX-512.
  auto haswell = epycZen3();
  haswell.vendor = "intel";
  EXPECT_EQ(BlasKernel::choose(haswell, "Prescott", "", kConfig).kernel, "HASWELL");
}

TEST(BlasKernel, OpenBlasOwnWidestPickIsKept) {
  for (const char* own : {"SkylakeX", "Cooperlake", "SapphireRapids"})
    EXPECT_EQ(BlasKernel::choose(xeonAvx512(), own, "", kConfig).kernel, "") << own;
  EXPECT_EQ(BlasKernel::choose(epycZen3(), "Zen", "", kConfig).kernel, "");
  EXPECT_EQ(BlasKernel::choose(epycZen3(), "Haswell", "", kConfig).kernel, "");
}

TEST(BlasKernel, NoOpenBlasNoChoice) {
  const auto c = BlasKernel::choose(xeonAvx512(), "", "", "");
  EXPECT_EQ(c.kernel, "");
  EXPECT_NE(c.reason.find("not OpenBLAS"), std::string::npos);
}

TEST(BlasKernel, EveryChosenKernelRunsOnItsCpu) {
  const std::vector<BlasKernel::Cpu> cpus = {
      epycZen3(), xeonAvx512(), cpu("intel", {"sse2", "pni"}), cpu("intel", {"sse2", "pni", "ssse3"}),
      cpu("intel", {"sse2", "pni", "ssse3", "sse4_1", "sse4_2", "avx"}), cpu("other", {"sse2"})};
  for (const auto& c : cpus) {
    for (const char* detected : {"", "Prescott", "Core2", "Sandybridge", "Haswell", "Zen", "SkylakeX"}) {
      for (const char* setting : {"", "SKYLAKEX", "HASWELL", "PRESCOTT", "BULLDOZER"}) {
        const auto choice = BlasKernel::choose(c, detected, setting, kConfig);
        if (!choice.kernel.empty()) expectRunnable(c, choice.kernel);
      }
    }
  }
}

TEST(BlasKernel, ChoiceTravelsThroughTheEnvironmentUnchanged) {
  const BlasKernel::Choice c{"SKYLAKEX", "OpenBLAS 0.3.21 picks Prescott on this intel CPU, which has avx512f", "w"};
  const auto back = BlasKernel::decode(BlasKernel::encode(c));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->kernel, c.kernel);
  EXPECT_EQ(back->reason, c.reason);
  EXPECT_EQ(back->warning, c.warning);
  EXPECT_FALSE(BlasKernel::decode("no separators"));
}

TEST(BlasKernel, ThisCpusFlagsAreThoseTheKernelReports) {
  const auto cpuinfo = procCpuinfoFlags();
  if (cpuinfo.empty()) GTEST_SKIP() << "no /proc/cpuinfo flags line on this machine";
  const auto mine = BlasKernel::thisCpu();
  ASSERT_TRUE(mine.flags.count("sse2"));  // every x86-64 CPU
  for (const std::string& f : mine.flags) EXPECT_TRUE(cpuinfo.count(f)) << f << " read by CPUID, not in /proc/cpuinfo";
  for (const char* f : {"avx", "avx2", "fma", "avx512f", "avx512bw", "avx512vl", "avx512dq", "avx512cd"})
    EXPECT_EQ(cpuinfo.count(f), mine.flags.count(f)) << f;
}

TEST(BlasKernel, TheKernelThisRunnerUsesRunsOnThisCpu) {
  // main() made the choice and re-executed with it (tests/cpp/support/TestMain.cpp).
  const auto loaded = BlasKernel::loaded();
  if (!loaded) GTEST_SKIP() << "the BLAS is not OpenBLAS";
  const auto required = BlasKernel::requiredFlags(loaded->core);
  ASSERT_TRUE(required) << loaded->core;
  const auto cpuinfo = procCpuinfoFlags();
  for (const std::string& f : *required) EXPECT_TRUE(cpuinfo.count(f)) << loaded->core << " needs " << f;
  const char* made = std::getenv(BlasKernel::kChoiceVariable);
  ASSERT_NE(made, nullptr);
  const auto choice = BlasKernel::decode(made);
  ASSERT_TRUE(choice);
  const char* setting = std::getenv(BlasKernel::kCoreTypeVariable);
  if (choice->kernel.empty()) {
    // OpenBLAS's own pick, kept because it is as wide as the widest this CPU runs.
    EXPECT_EQ(setting, nullptr);
    EXPECT_GE(BlasKernel::tier(loaded->core), BlasKernel::tier(BlasKernel::best(BlasKernel::thisCpu())));
  } else {
    // A named kernel is the one that runs.
    ASSERT_NE(setting, nullptr);
    EXPECT_EQ(choice->kernel, setting);
    if (BlasKernel::requiredFlags(choice->kernel))
      EXPECT_EQ(*BlasKernel::requiredFlags(loaded->core), *BlasKernel::requiredFlags(choice->kernel));
  }
}
