#include "elements/FourNodeQuad.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

std::unique_ptr<Element> buildFourNodeQuad(CommandArgs& args, Domain& domain) {
  const auto c = planesolid::parse<FourNodeQuad::kNodes>(args, domain, "quad");
  return std::make_unique<FourNodeQuad>(c.tag, c.nodes, *c.material, c.properties);
}

void registerFourNodeQuad(Registry& r) { r.elements.add("quad", &buildFourNodeQuad); }

}  // namespace

BEAMSOLID_REGISTER(registerFourNodeQuad);

}  // namespace beamsolid
