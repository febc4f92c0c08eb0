#include "materials/uniaxial/ENTMaterial.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

std::unique_ptr<UniaxialMaterial> ENTMaterial::clone() const { return std::make_unique<ENTMaterial>(*this); }

void ENTMaterial::setTrialStrain(double strain, double) { trialStrain_ = strain; }

bool ENTMaterial::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty() || args[0] != "E") return false;
  E_ = value;
  return true;
}

void ENTMaterial::print(std::ostream& os) const { os << "UniaxialMaterial " << tag() << " type ENT E " << E_ << '\n'; }

namespace {

std::unique_ptr<UniaxialMaterial> buildENTMaterial(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ENT " + std::to_string(tag));
  const double E = args.nextDouble("E");
  args.expectEnd();
  if (!(E > 0.0)) args.fail("E must be positive, got " + std::to_string(E));
  return std::make_unique<ENTMaterial>(tag, E);
}

void registerENTMaterial(Registry& r) { r.uniaxialMaterials.add("ENT", &buildENTMaterial); }

}  // namespace

BEAMSOLID_REGISTER(registerENTMaterial);

}  // namespace beamsolid
