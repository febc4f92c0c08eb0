#include "materials/uniaxial/MultiLinear.h"

#include <cmath>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

MultiLinear::MultiLinear(int tag, const std::vector<double>& strains, const std::vector<double>& stresses)
    : UniaxialMaterial(tag), strains_(strains), stresses_(stresses) {
  const std::size_t n = strains_.size();
  std::vector<double> slope(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double e0 = i == 0 ? 0.0 : strains_[i - 1];
    const double s0 = i == 0 ? 0.0 : stresses_[i - 1];
    slope[i] = (stresses_[i] - s0) / (strains_[i] - e0);
  }
  initialTangent_ = slope[0];
  // The spring of corner i yields at strain e_i and removes slope_i - slope_(i+1).
  for (std::size_t i = 0; i + 1 < n; ++i) stiffness_.push_back(slope[i] - slope[i + 1]);
  elasticStiffness_ = slope[n - 1];
  revertToStart();
}

std::unique_ptr<UniaxialMaterial> MultiLinear::clone() const { return std::make_unique<MultiLinear>(*this); }

void MultiLinear::setTrialStrain(double strain, double) {
  // The committed strain again, to within machine epsilon (as OpenSees, found
  // by running it), keeps the committed state: a spring that stopped on its
  // yield limit would otherwise look elastic (tangent too stiff for the next
  // Newton step; OpenSees keeps the yielding tangent), and round-off in a
  // strain cannot pick a branch.
  if (std::fabs(strain - committedStrain_) < std::numeric_limits<double>::epsilon()) {
    revertToLastCommit();
    return;
  }
  trialStrain_ = strain;
  trialStress_ = elasticStiffness_ * strain;
  trialTangent_ = elasticStiffness_;
  for (std::size_t i = 0; i < stiffness_.size(); ++i) {
    double slip = committedSlip_[i];
    const double elastic = strain - slip;
    if (std::abs(elastic) > strains_[i]) {
      slip = strain - std::copysign(strains_[i], elastic);
    } else {
      trialTangent_ += stiffness_[i];
    }
    trialSlip_[i] = slip;
    trialStress_ += stiffness_[i] * (strain - slip);
  }
}

void MultiLinear::commitState() {
  committedStrain_ = trialStrain_;
  committedStress_ = trialStress_;
  committedTangent_ = trialTangent_;
  committedSlip_ = trialSlip_;
}

void MultiLinear::revertToLastCommit() {
  trialSlip_ = committedSlip_;
  trialStrain_ = committedStrain_;
  trialStress_ = committedStress_;
  trialTangent_ = committedTangent_;
}

void MultiLinear::revertToStart() {
  committedStrain_ = trialStrain_ = 0.0;
  committedSlip_.assign(stiffness_.size(), 0.0);
  trialSlip_ = committedSlip_;
  committedStress_ = trialStress_ = 0.0;
  committedTangent_ = trialTangent_ = initialTangent_;
}

void MultiLinear::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag() << " type MultiLinear points";
  for (std::size_t i = 0; i < strains_.size(); ++i) os << " (" << strains_[i] << ", " << stresses_[i] << ')';
  os << '\n';
}

namespace {

std::unique_ptr<UniaxialMaterial> buildMultiLinear(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("matTag");
  args.setContext("uniaxialMaterial MultiLinear " + std::to_string(tag));
  const std::size_t at = args.position();
  const std::vector<double> values = args.nextDoubles("strain-stress pairs", 2);
  args.expectEnd();
  if (values.size() % 2 != 0)
    args.failAt(at + values.size(), "strain-stress pairs", "a stress after the last strain (pairs e1 s1 e2 s2 ...)");
  std::vector<double> strains, stresses;
  for (std::size_t i = 0; i < values.size(); i += 2) {
    strains.push_back(values[i]);
    stresses.push_back(values[i + 1]);
  }
  for (std::size_t i = 0; i < strains.size(); ++i) {
    const double before = i == 0 ? 0.0 : strains[i - 1];
    if (!(strains[i] > before))
      args.fail("strains must be positive and increasing, but e" + std::to_string(i + 1) + " = " +
                std::to_string(strains[i]) + " is not larger than " + std::to_string(before));
  }
  return std::make_unique<MultiLinear>(tag, strains, stresses);
}

void registerMultiLinear(Registry& r) { r.uniaxialMaterials.add("MultiLinear", &buildMultiLinear); }

}  // namespace

BEAMSOLID_REGISTER(registerMultiLinear);

}  // namespace beamsolid
