#include "materials/uniaxial/ElasticPPMaterial.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ElasticPPMaterial::ElasticPPMaterial(int tag, double E, double epsyP, double epsyN, double eps0)
    : UniaxialMaterial(tag), E_(E), epsyP_(epsyP), epsyN_(epsyN), eps0_(eps0), trialTangent_(E), committedTangent_(E) {
  // With an initial strain the unstrained state is already stressed.
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> ElasticPPMaterial::clone() const {
  return std::make_unique<ElasticPPMaterial>(*this);
}

void ElasticPPMaterial::setTrialStrain(double strain, double) {
  // A change below machine epsilon keeps the committed stress and tangent (as OpenSees, found
  // by running it; unlike Steel01 the new strain is kept, so the next change counts from it).
  if (std::fabs(strain - committedStrain_) < std::numeric_limits<double>::epsilon()) {
    revertToLastCommit();
    trialStrain_ = strain;
    return;
  }
  trialFrom(strain);
}

void ElasticPPMaterial::trialFrom(double strain) {
  trialStrain_ = strain;
  const double fyP = E_ * epsyP_;
  const double fyN = E_ * epsyN_;
  // Elastic predictor from the committed plastic strain, then return to the
  // yield stress if it is reached (the plastic strain absorbs the excess).
  const double elasticStress = E_ * (strain - eps0_ - committedPlasticStrain_);
  // A predictor on the yield surface, to round-off, is plastic (tangent 0),
  // as in OpenSees: a bar that yielded in the last step starts the next one
  // with zero stiffness, which is what keeps Newton's iteration counts and
  // ModifiedNewton's convergence the same as OpenSees'.
  const double roundOff = 8.0 * std::numeric_limits<double>::epsilon() * E_ *
                          std::max({std::fabs(strain - eps0_), epsyP_, -epsyN_});
  if (elasticStress >= fyP - roundOff) {
    trialStress_ = fyP;
    trialPlasticStrain_ = strain - eps0_ - fyP / E_;
    trialTangent_ = 0.0;
  } else if (elasticStress <= fyN + roundOff) {
    trialStress_ = fyN;
    trialPlasticStrain_ = strain - eps0_ - fyN / E_;
    trialTangent_ = 0.0;
  } else {
    trialStress_ = elasticStress;
    trialPlasticStrain_ = committedPlasticStrain_;
    trialTangent_ = E_;
  }
}

void ElasticPPMaterial::commitState() {
  committedStrain_ = trialStrain_;
  committedStress_ = trialStress_;
  committedTangent_ = trialTangent_;
  committedPlasticStrain_ = trialPlasticStrain_;
}

void ElasticPPMaterial::revertToLastCommit() {
  trialStrain_ = committedStrain_;
  trialStress_ = committedStress_;
  trialTangent_ = committedTangent_;
  trialPlasticStrain_ = committedPlasticStrain_;
}

void ElasticPPMaterial::revertToStart() {
  committedPlasticStrain_ = 0.0;
  trialFrom(0.0);
  commitState();
}

void ElasticPPMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type ElasticPP E " << E_ << " epsyP " << epsyP_ << " epsyN "
     << epsyN_ << " eps0 " << eps0_ << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildElasticPPMaterial(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ElasticPP " + std::to_string(tag));
  const double E = args.nextDouble("E");
  const double epsyP = args.nextDouble("epsyP");
  const double epsyN = args.done() ? -epsyP : args.nextDouble("epsyN");
  const double eps0 = args.done() ? 0.0 : args.nextDouble("eps0");
  args.expectEnd();
  if (!(E > 0.0)) args.fail("E must be positive, got " + std::to_string(E));
  if (!(epsyP > 0.0)) args.fail("epsyP must be positive (yield strain in tension), got " + std::to_string(epsyP));
  if (!(epsyN < 0.0))
    args.fail("epsyN must be negative (yield strain in compression), got " + std::to_string(epsyN));
  return std::make_unique<ElasticPPMaterial>(tag, E, epsyP, epsyN, eps0);
}

void registerElasticPPMaterial(Registry& r) { r.uniaxialMaterials.add("ElasticPP", &buildElasticPPMaterial); }

}  // namespace

BEAMSOLID_REGISTER(registerElasticPPMaterial);

}  // namespace beamsolid
