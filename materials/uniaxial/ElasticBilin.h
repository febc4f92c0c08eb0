#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('ElasticBilin', tag, EP1, EP2, epsP2, <EN1, EN2, epsN2>):
// nonlinear elastic, bilinear on each side of zero strain. In tension the
// slope is EP1 up to epsP2 and EP2 beyond; in compression EN1 down to epsN2
// and EN2 beyond (defaults EP1, EP2, -epsP2). Loading and unloading follow the
// same curve: there is no history. A strain exactly at a break point takes the
// outer slope and zero strain the tension slope, as OpenSees (found by running it).
class ElasticBilin : public UniaxialMaterial {
 public:
  ElasticBilin(int tag, double EP1, double EP2, double epsP2, double EN1, double EN2, double epsN2);

  std::string className() const override { return "ElasticBilin"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override { return trialStress_; }
  double tangent() const override { return trialTangent_; }
  double initialTangent() const override { return EP1_; }

  void commitState() override { committedStrain_ = trialStrain_; }
  void revertToLastCommit() override { setTrialStrain(committedStrain_); }
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  double EP1_, EP2_, epsP2_, EN1_, EN2_, epsN2_;
  double trialStrain_ = 0.0, trialStress_ = 0.0, trialTangent_;
  double committedStrain_ = 0.0;
};

}  // namespace beamsolid
