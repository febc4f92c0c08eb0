// A test plugin built without beamsolid_add_plugin: it registers, but has no
// ABI stamp, so loadPlugin cannot know what it was built against.
#include <cstdlib>

#include "core/PluginAbi.h"
#include "core/Registry.h"

BEAMSOLID_PLUGIN_REGISTER(r) {
  (void)r;
  std::abort();  // never reached
}
