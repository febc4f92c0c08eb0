#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('ENT', tag, E): elastic in compression (stress E*strain,
// strain < 0), no stress and no stiffness in tension. History-free; commit
// only remembers the strain for revertToLastCommit.
class ENTMaterial : public UniaxialMaterial {
 public:
  ENTMaterial(int tag, double E) : UniaxialMaterial(tag), E_(E) {}

  std::string className() const override { return "ENT"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override { return trialStrain_ < 0.0 ? E_ * trialStrain_ : 0.0; }
  // At exactly zero strain the compressive modulus, so that an unstrained
  // compression member starts with stiffness.
  double tangent() const override { return trialStrain_ <= 0.0 ? E_ : 0.0; }
  double initialTangent() const override { return E_; }

  void commitState() override { committedStrain_ = trialStrain_; }
  void revertToLastCommit() override { trialStrain_ = committedStrain_; }
  void revertToStart() override { trialStrain_ = committedStrain_ = 0.0; }

  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

 private:
  double E_;
  double trialStrain_ = 0.0, committedStrain_ = 0.0;
};

}  // namespace beamsolid
