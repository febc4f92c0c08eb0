#include "elements/Tri31.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

std::unique_ptr<Element> buildTri31(CommandArgs& args, Domain& domain) {
  const auto c = planesolid::parse<Tri31::kNodes>(args, domain, "tri31", true);
  return std::make_unique<Tri31>(c.tag, c.nodes, *c.material, c.properties);
}

void registerTri31(Registry& r) { r.elements.add("tri31", &buildTri31); }

}  // namespace

BEAMSOLID_REGISTER(registerTri31);

}  // namespace beamsolid
