// A test plugin whose registration fails half-way: one type is added, then it
// throws. loadPlugin must leave the registry as it was.
#include <stdexcept>

#include "core/PluginAbi.h"
#include "core/Registry.h"
#include "materials/uniaxial/ElasticMaterial.h"

BEAMSOLID_PLUGIN_REGISTER(r) {
  r.uniaxialMaterials.add("HalfRegistered", [](beamsolid::CommandArgs& a, beamsolid::Domain&)
                                                -> std::unique_ptr<beamsolid::UniaxialMaterial> {
    return std::make_unique<beamsolid::ElasticMaterial>(a.nextInt("matTag"), 1.0, 0.0, 1.0);
  });
  throw std::runtime_error("the plugin's licence file is missing");
}
