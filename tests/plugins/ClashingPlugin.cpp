// A test plugin that registers a new type and one that is built in already.
#include "core/PluginAbi.h"
#include "core/Registry.h"
#include "materials/uniaxial/ElasticMaterial.h"

namespace {
std::unique_ptr<beamsolid::UniaxialMaterial> build(beamsolid::CommandArgs& a, beamsolid::Domain&) {
  return std::make_unique<beamsolid::ElasticMaterial>(a.nextInt("matTag"), 1.0, 0.0, 1.0);
}
}  // namespace

BEAMSOLID_PLUGIN_REGISTER(r) {
  r.uniaxialMaterials.add("BrandNew", &build);
  r.uniaxialMaterials.add("Elastic", &build);
}
