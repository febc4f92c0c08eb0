#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Elastic', tag, E, <eta=0>, <Eneg=E>):
// stress = E*strain in tension (strain > 0), Eneg*strain otherwise, plus a
// viscous term eta*strainRate. History-free; commit only remembers the state
// so that revertToLastCommit can restore it.
class ElasticMaterial : public UniaxialMaterial {
 public:
  ElasticMaterial(int tag, double E, double eta, double Eneg);

  std::string className() const override { return "Elastic"; }
  bool isLinear() const override { return E_ == Eneg_; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override;
  double tangent() const override;
  double initialTangent() const override { return E_; }
  double strainRate() const { return trialStrainRate_; }
  double dampingTangent() const override { return eta_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 'E', 'Epos', 'Eneg', 'eta'.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  // Sensitivity to 'E' (1), 'Epos' (2), 'Eneg' (3), 'eta' (4); no history.
  int sensitivityParameter(const std::vector<std::string>& args) override;
  double stressSensitivity(int gradient, int parameterId) override;
  void commitSensitivity(double, int, int, int) override {}
  void print(std::ostream& os) const override;

 private:
  double E_, eta_, Eneg_;
  double trialStrain_ = 0.0, trialStrainRate_ = 0.0;
  double committedStrain_ = 0.0, committedStrainRate_ = 0.0;
};

}  // namespace beamsolid
