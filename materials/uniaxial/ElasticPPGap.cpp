#include "materials/uniaxial/ElasticPPGap.h"

#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ElasticPPGap::ElasticPPGap(int tag, double E, double Fy, double gap, double eta, bool damage)
    : UniaxialMaterial(tag), E_(E), Fy_(std::fabs(Fy)), eta_(eta), damage_(damage), sign_(Fy < 0.0 ? -1.0 : 1.0) {
  gap_ = sign_ * gap;
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> ElasticPPGap::clone() const { return std::make_unique<ElasticPPGap>(*this); }

void ElasticPPGap::setTrialStrain(double strain, double) {
  trialStrain_ = strain;
  const double e = sign_ * strain;
  if (e > plasticStrain_) {
    trialStress_ = Fy_ + eta_ * E_ * (e - gap_ - Fy_ / E_);
    trialTangent_ = eta_ * E_;
  } else if (e < contactStrain_) {
    trialStress_ = 0.0;
    trialTangent_ = 0.0;
  } else {
    trialStress_ = E_ * (e - contactStrain_);
    trialTangent_ = E_;
  }
}

void ElasticPPGap::commitState() {
  const double e = sign_ * trialStrain_;
  if (e > plasticStrain_) {
    plasticStrain_ = e;
    contactStrain_ = e - trialStress_ / E_;
  } else if (!damage_ && e < contactStrain_ && e > gap_) {
    contactStrain_ = e;
    // The elastic line from the new contact strain meets the plastic line here
    // (never, for a plastic line at least as steep as the elastic one).
    plasticStrain_ = eta_ < 1.0 ? e + (Fy_ + eta_ * E_ * (e - gap_ - Fy_ / E_)) / (E_ * (1.0 - eta_))
                                : std::numeric_limits<double>::infinity();
  }
  committedStrain_ = trialStrain_;
}

void ElasticPPGap::revertToLastCommit() { setTrialStrain(committedStrain_); }

void ElasticPPGap::revertToStart() {
  contactStrain_ = gap_;
  plasticStrain_ = gap_ + Fy_ / E_;
  committedStrain_ = 0.0;
  setTrialStrain(0.0);
}

void ElasticPPGap::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type ElasticPPGap E " << E_ << " Fy " << sign_ * Fy_ << " gap "
     << sign_ * gap_ << " eta " << eta_ << (damage_ ? " damage" : " noDamage") << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildElasticPPGap(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ElasticPPGap " + std::to_string(tag));
  const double E = args.nextDouble("E");
  const double Fy = args.nextDouble("Fy");
  const double gap = args.nextDouble("gap");
  const double eta = args.done() || args.nextIsString() ? 0.0 : args.nextDouble("eta");
  bool damage = false;
  // Any word but 'damage' leaves the default re-centering, as OpenSees.
  if (!args.done()) damage = args.nextString("damage") == "damage";
  args.expectEnd();
  if (!(E > 0.0)) args.fail("E must be positive, got " + std::to_string(E));
  if (Fy == 0.0) args.fail("Fy must be nonzero (its sign picks a tension or a compression gap)");
  return std::make_unique<ElasticPPGap>(tag, E, Fy, gap, eta, damage);
}

void registerElasticPPGap(Registry& r) { r.uniaxialMaterials.add("ElasticPPGap", &buildElasticPPGap); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticPPGap);

}  // namespace beamsolid
