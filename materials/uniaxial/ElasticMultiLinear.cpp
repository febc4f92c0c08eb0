#include "materials/uniaxial/ElasticMultiLinear.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

ElasticMultiLinear::ElasticMultiLinear(int tag, std::vector<double> strains, std::vector<double> stresses,
                                       double eta)
    : UniaxialMaterial(tag), strains_(std::move(strains)), stresses_(std::move(stresses)), eta_(eta) {
  double stress0 = 0.0;
  evaluate(0.0, stress0, initialTangent_);
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> ElasticMultiLinear::clone() const {
  return std::make_unique<ElasticMultiLinear>(*this);
}

void ElasticMultiLinear::evaluate(double strain, double& stress, double& tangent) {
  const std::size_t last = strains_.size() - 1;
  // From the last trial's segment; on a point this picks the segment the way
  // OpenSees' tangents show: upwards the segment above, downwards the one
  // above when the point is the segment's own start, else the one below.
  std::size_t& i = segment_;
  while (i + 1 < last && strain >= strains_[i + 1]) ++i;
  if (strain < strains_[i])
    while (i > 0 && strain <= strains_[i]) --i;
  tangent = (stresses_[i + 1] - stresses_[i]) / (strains_[i + 1] - strains_[i]);
  stress = stresses_[i] + tangent * (strain - strains_[i]);
}

void ElasticMultiLinear::setTrialStrain(double strain, double strainRate) {
  trialStrain_ = strain;
  trialRate_ = strainRate;
  evaluate(strain, trialStress_, trialTangent_);
  trialStress_ += eta_ * strainRate;
}

void ElasticMultiLinear::commitState() {
  committedStrain_ = trialStrain_;
  committedRate_ = trialRate_;
}

void ElasticMultiLinear::revertToLastCommit() { setTrialStrain(committedStrain_, committedRate_); }

void ElasticMultiLinear::revertToStart() {
  committedStrain_ = committedRate_ = 0.0;
  setTrialStrain(0.0, 0.0);
}

void ElasticMultiLinear::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type ElasticMultiLinear eta " << eta_ << " points";
  for (std::size_t i = 0; i < strains_.size(); ++i) os << " (" << strains_[i] << ", " << stresses_[i] << ')';
  os << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildElasticMultiLinear(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial ElasticMultiLinear " + std::to_string(tag));
  double eta = 0.0;
  if (args.nextIsNumber()) eta = args.nextDouble("eta");
  std::vector<double> strains, stresses;
  while (!args.done()) {
    if (args.nextFlag("-strain"))
      strains = args.nextDoubles("strainPoints", 2);
    else if (args.nextFlag("-stress"))
      stresses = args.nextDoubles("stressPoints", 2);
    else
      args.failAt(args.position(), "option", "'-strain' or '-stress'");
  }
  if (strains.empty()) args.fail("missing '-strain' followed by the strain points");
  if (stresses.empty()) args.fail("missing '-stress' followed by the stress points");
  if (strains.size() != stresses.size())
    args.fail("expected as many stress points as strain points, got " + std::to_string(strains.size()) +
              " strains and " + std::to_string(stresses.size()) + " stresses");
  for (std::size_t i = 1; i < strains.size(); ++i)
    if (!(strains[i] > strains[i - 1]))
      args.fail("strain points must increase, but point " + std::to_string(i + 1) + " (" +
                std::to_string(strains[i]) + ") does not exceed the one before");
  return std::make_unique<ElasticMultiLinear>(tag, std::move(strains), std::move(stresses), eta);
}

void registerElasticMultiLinear(Registry& r) {
  r.uniaxialMaterials.add("ElasticMultiLinear", &buildElasticMultiLinear);
}

}  // namespace

BEAMSOLID_REGISTER(registerElasticMultiLinear);

}  // namespace beamsolid
