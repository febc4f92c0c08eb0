// A test plugin stamped by another BeamSolid: loadPlugin must refuse it,
// naming both stamps, before it calls the registration function.
#include <cstdlib>

#include "core/PluginAbi.h"
#include "core/Registry.h"

extern "C" __attribute__((visibility("default"))) const char* beamsolid_plugin_abi() {
  return "BeamSolid 0.0.1; gcc 9; libstdc++ cxx11 ABI 1; Eigen 3.3.7 aligned to 16 bytes";
}

BEAMSOLID_PLUGIN_REGISTER(r) {
  (void)r;
  std::abort();  // never reached: a mismatched plugin is not registered
}
