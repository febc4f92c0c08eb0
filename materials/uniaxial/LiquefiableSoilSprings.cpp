// PyLiq1, TzLiq1 and QzLiq1 (the p-y, t-z and q-z springs whose capacity
// follows the pore pressure of neighbouring soil elements or a time series)
// are not built: they answer with an error that says so instead of the
// generic "unknown type".
#include <string>

#include "core/CommandArgs.h"
#include "core/Registry.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

namespace {

template <const char* Name, const char* Simple>
std::unique_ptr<UniaxialMaterial> notAvailable(CommandArgs& args, Domain&) {
  const std::string tag = args.done() ? std::string("?") : CommandArgs::describe(args.at(args.position()));
  args.setContext(std::string("uniaxialMaterial ") + Name + " " + tag);
  args.fail(std::string(Name) +
            " (liquefaction: capacity scaled by the mean effective stress of soil elements or a time series) is "
            "not available in BeamSolid; use " + Simple + " with a reduced capacity instead");
}

constexpr char kPyLiq1[] = "PyLiq1", kTzLiq1[] = "TzLiq1", kQzLiq1[] = "QzLiq1";
constexpr char kPySimple1[] = "PySimple1", kTzSimple1[] = "TzSimple1", kQzSimple1[] = "QzSimple1";

void registerLiquefiableSoilSprings(Registry& r) {
  r.uniaxialMaterials.add("PyLiq1", &notAvailable<kPyLiq1, kPySimple1>);
  r.uniaxialMaterials.add("TzLiq1", &notAvailable<kTzLiq1, kTzSimple1>);
  r.uniaxialMaterials.add("QzLiq1", &notAvailable<kQzLiq1, kQzSimple1>);
}

}  // namespace

BEAMSOLID_REGISTER(registerLiquefiableSoilSprings);

}  // namespace beamsolid
