// Compiled into every plugin by beamsolid_add_plugin(): the ABI stamp that
// loadPlugin compares with libbeamsolid's own (core/PluginAbi.h).
#include "core/PluginAbi.h"

BEAMSOLID_PLUGIN_ABI_STAMP()
