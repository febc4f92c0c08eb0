#include "materials/uniaxial/ModIMKPinching.h"

#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

std::unique_ptr<UniaxialMaterial> buildModIMKPinching(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ModIMKPinching " + std::to_string(tag));
  const ImkArguments a = readImkArguments(args, true);
  args.expectEnd();
  checkImkArguments(args, a, true);
  return std::make_unique<ModIMKPinching>(tag, a.K0, a.positive, a.negative, a.deterioration,
                                          ModIMKPeakOriented::Pinching{{a.fprPos, a.fprNeg}, a.aPinch});
}

void registerModIMKPinching(Registry& r) { r.uniaxialMaterials.add("ModIMKPinching", &buildModIMKPinching); }

}  // namespace

BEAMSOLID_REGISTER(registerModIMKPinching);

}  // namespace beamsolid
