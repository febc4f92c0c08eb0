#include "elements/CorotTruss.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

std::unique_ptr<Element> buildCorotTruss(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element corotTruss " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const Truss::Options o = Truss::readOptions(args);
  const UniaxialMaterial& material = domain.uniaxialMaterials.get(o.matTag, args.context());
  return std::make_unique<CorotTruss>(tag, iNode, jNode, o.area, material, o.rho, o.consistentMass, o.doRayleigh);
}

void registerCorotTruss(Registry& r) {
  r.elements.add("corotTruss", &buildCorotTruss);
  r.elements.add("CorotTruss", &buildCorotTruss);
}

}  // namespace

BEAMSOLID_REGISTER(registerCorotTruss);

}  // namespace beamsolid
