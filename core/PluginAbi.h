#pragma once
// The plugin ABI stamp. A plugin shares C++ classes (Element, CommandArgs,
// Registry, Eigen matrices, std::string, std::function) with libbeamsolid, so
// both must come from the same BeamSolid headers, the same compiler family
// and major version, the same standard library ABI and the same Eigen with
// the same alignment. The stamp spells these out at compile time; loadPlugin
// compares the plugin's with the library's and refuses a mismatch.
#include <Eigen/Core>
#include <string>

#include "core/Version.h"

#define BEAMSOLID_STR_(x) #x
#define BEAMSOLID_STR(x) BEAMSOLID_STR_(x)

#if defined(__clang__)
#define BEAMSOLID_COMPILER "clang " BEAMSOLID_STR(__clang_major__)
#elif defined(__GNUC__)
#define BEAMSOLID_COMPILER "gcc " BEAMSOLID_STR(__GNUC__)
#else
#define BEAMSOLID_COMPILER "unknown compiler"
#endif

#if defined(_GLIBCXX_USE_CXX11_ABI)
#define BEAMSOLID_STDLIB "libstdc++ cxx11 ABI " BEAMSOLID_STR(_GLIBCXX_USE_CXX11_ABI)
#elif defined(_LIBCPP_VERSION)
#define BEAMSOLID_STDLIB "libc++ ABI " BEAMSOLID_STR(_LIBCPP_ABI_VERSION)
#else
#define BEAMSOLID_STDLIB "unknown standard library"
#endif

#define BEAMSOLID_PLUGIN_ABI                                                                               \
  "BeamSolid " BEAMSOLID_VERSION "; " BEAMSOLID_COMPILER "; " BEAMSOLID_STDLIB "; Eigen " BEAMSOLID_STR( \
      EIGEN_WORLD_VERSION) "." BEAMSOLID_STR(EIGEN_MAJOR_VERSION) "." BEAMSOLID_STR(EIGEN_MINOR_VERSION) \
      " aligned to " BEAMSOLID_STR(EIGEN_MAX_STATIC_ALIGN_BYTES) " bytes"

// One line in one source file of a plugin (beamsolid_add_plugin() adds it for
// you): exports the stamp the plugin was compiled with.
#define BEAMSOLID_PLUGIN_ABI_STAMP() \
  extern "C" __attribute__((visibility("default"))) const char* beamsolid_plugin_abi() { return BEAMSOLID_PLUGIN_ABI; }

// A plugin's registration function, exported whatever the visibility default:
//   BEAMSOLID_PLUGIN_REGISTER(registry) { registry.elements.add("MySpring", &build); }
#define BEAMSOLID_PLUGIN_REGISTER(registry) \
  extern "C" __attribute__((visibility("default"))) void beamsolid_register(::beamsolid::Registry& registry)

namespace beamsolid {

// The stamp libbeamsolid itself was compiled with.
const char* pluginAbi();

}  // namespace beamsolid
