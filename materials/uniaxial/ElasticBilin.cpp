#include "materials/uniaxial/ElasticBilin.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ElasticBilin::ElasticBilin(int tag, double EP1, double EP2, double epsP2, double EN1, double EN2, double epsN2)
    : UniaxialMaterial(tag), EP1_(EP1), EP2_(EP2), epsP2_(epsP2), EN1_(EN1), EN2_(EN2), epsN2_(epsN2),
      trialTangent_(EP1) {}

std::unique_ptr<UniaxialMaterial> ElasticBilin::clone() const { return std::make_unique<ElasticBilin>(*this); }

void ElasticBilin::setTrialStrain(double strain, double) {
  trialStrain_ = strain;
  if (strain >= 0.0) {
    if (strain < epsP2_) {
      trialStress_ = EP1_ * strain;
      trialTangent_ = EP1_;
    } else {
      trialStress_ = EP1_ * epsP2_ + EP2_ * (strain - epsP2_);
      trialTangent_ = EP2_;
    }
  } else if (strain > epsN2_) {
    trialStress_ = EN1_ * strain;
    trialTangent_ = EN1_;
  } else {
    trialStress_ = EN1_ * epsN2_ + EN2_ * (strain - epsN2_);
    trialTangent_ = EN2_;
  }
}

void ElasticBilin::revertToStart() {
  committedStrain_ = 0.0;
  setTrialStrain(0.0);
}

void ElasticBilin::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type ElasticBilin EP1 " << EP1_ << " EP2 " << EP2_ << " epsP2 "
     << epsP2_ << " EN1 " << EN1_ << " EN2 " << EN2_ << " epsN2 " << epsN2_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildElasticBilin(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ElasticBilin " + std::to_string(tag));
  const double EP1 = args.nextDouble("EP1");
  const double EP2 = args.nextDouble("EP2");
  const double epsP2 = args.nextDouble("epsP2");
  double EN1 = EP1, EN2 = EP2, epsN2 = -epsP2;
  // OpenSees takes the compression side whole or not at all.
  if (!args.done()) {
    EN1 = args.nextDouble("EN1");
    EN2 = args.nextDouble("EN2");
    epsN2 = args.nextDouble("epsN2");
  }
  args.expectEnd();
  if (!(epsP2 > 0.0)) args.fail("epsP2 must be positive (tension break strain), got " + std::to_string(epsP2));
  if (!(epsN2 < 0.0)) args.fail("epsN2 must be negative (compression break strain), got " + std::to_string(epsN2));
  return std::make_unique<ElasticBilin>(tag, EP1, EP2, epsP2, EN1, EN2, epsN2);
}

void registerElasticBilin(Registry& r) { r.uniaxialMaterials.add("ElasticBilin", &buildElasticBilin); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticBilin);

}  // namespace beamsolid
