#include "materials/uniaxial/ElasticMaterial.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ElasticMaterial::ElasticMaterial(int tag, double E, double eta, double Eneg)
    : UniaxialMaterial(tag), E_(E), eta_(eta), Eneg_(Eneg) {}

std::unique_ptr<UniaxialMaterial> ElasticMaterial::clone() const {
  return std::make_unique<ElasticMaterial>(*this);
}

void ElasticMaterial::setTrialStrain(double strain, double strainRate) {
  trialStrain_ = strain;
  trialStrainRate_ = strainRate;
}

double ElasticMaterial::stress() const {
  const double modulus = trialStrain_ > 0.0 ? E_ : Eneg_;
  return modulus * trialStrain_ + eta_ * trialStrainRate_;
}

double ElasticMaterial::tangent() const { return trialStrain_ > 0.0 ? E_ : Eneg_; }

void ElasticMaterial::commitState() {
  committedStrain_ = trialStrain_;
  committedStrainRate_ = trialStrainRate_;
}

void ElasticMaterial::revertToLastCommit() {
  trialStrain_ = committedStrain_;
  trialStrainRate_ = committedStrainRate_;
}

void ElasticMaterial::revertToStart() {
  trialStrain_ = trialStrainRate_ = committedStrain_ = committedStrainRate_ = 0.0;
}

bool ElasticMaterial::setParameter(const std::vector<std::string>& args, double value) {
  if (args.empty()) return false;
  if (args[0] == "E") {
    // Changing E alone keeps a symmetric material symmetric.
    if (Eneg_ == E_) Eneg_ = value;
    E_ = value;
    return true;
  }
  if (args[0] == "Epos") { E_ = value; return true; }
  if (args[0] == "Eneg") { Eneg_ = value; return true; }
  if (args[0] == "eta") { eta_ = value; return true; }
  return false;
}

int ElasticMaterial::sensitivityParameter(const std::vector<std::string>& args) {
  if (args.empty()) return 0;
  if (args[0] == "E") return 1;
  if (args[0] == "Epos") return 2;
  if (args[0] == "Eneg") return 3;
  if (args[0] == "eta") return 4;
  return 0;
}

double ElasticMaterial::stressSensitivity(int, int parameterId) {
  const bool tension = trialStrain_ > 0.0;
  switch (parameterId) {
    // 'E' moves Eneg with it while the two are equal (setParameter).
    case 1: return tension || Eneg_ == E_ ? trialStrain_ : 0.0;
    case 2: return tension ? trialStrain_ : 0.0;
    case 3: return tension ? 0.0 : trialStrain_;
    case 4: return trialStrainRate_;
    default: return 0.0;
  }
}

void ElasticMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type Elastic E " << E_ << " eta " << eta_ << " Eneg " << Eneg_
     << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildElasticMaterial(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial Elastic " + std::to_string(tag));
  const double E = args.nextDouble("E");
  const double eta = args.done() ? 0.0 : args.nextDouble("eta");
  const double Eneg = args.done() ? E : args.nextDouble("Eneg");
  args.expectEnd();
  return std::make_unique<ElasticMaterial>(tag, E, eta, Eneg);
}

void registerElasticMaterial(Registry& r) { r.uniaxialMaterials.add("Elastic", &buildElasticMaterial); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticMaterial);

}  // namespace beamsolid
