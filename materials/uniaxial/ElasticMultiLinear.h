#pragma once
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('ElasticMultiLinear', tag, <eta>, '-strain', *strains,
//                  '-stress', *stresses):
// nonlinear elastic: stress follows the piecewise linear curve through the
// points (strains increasing) both ways, so no energy is dissipated; the end
// segments extend to infinity. The tangent on a point depends on the segment
// of the previous trial (see evaluate()), as OpenSees' does.
// eta adds a viscous stress eta * strainRate.
class ElasticMultiLinear : public UniaxialMaterial {
 public:
  ElasticMultiLinear(int tag, std::vector<double> strains, std::vector<double> stresses, double eta);

  std::string className() const override { return "ElasticMultiLinear"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override { return trialStress_; }
  double tangent() const override { return trialTangent_; }
  double initialTangent() const override { return initialTangent_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  // Elastic stress and tangent at `strain` on the curve.
  void evaluate(double strain, double& stress, double& tangent);

  std::vector<double> strains_, stresses_;
  double eta_;
  double initialTangent_ = 0.0;
  std::size_t segment_ = 0;  // of the last trial: segment i runs from point i to i+1
  double trialStrain_ = 0.0, trialRate_ = 0.0, trialStress_ = 0.0, trialTangent_ = 0.0;
  double committedStrain_ = 0.0, committedRate_ = 0.0;
};

}  // namespace beamsolid
