#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('ElasticPP', tag, E, epsyP, <epsyN=-epsyP>, <eps0=0>):
// elastic-perfectly plastic with yield stresses E*epsyP (tension) and
// E*epsyN (compression); eps0 is an initial strain. The plastic strain is a
// committed state variable: every trial starts from the committed one, so
// repeated trials within a step never accumulate plastic flow.
class ElasticPPMaterial : public UniaxialMaterial {
 public:
  ElasticPPMaterial(int tag, double E, double epsyP, double epsyN, double eps0);

  std::string className() const override { return "ElasticPP"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override { return trialStress_; }
  double tangent() const override { return trialTangent_; }
  double initialTangent() const override { return E_; }
  double plasticStrain() const { return trialPlasticStrain_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  // The trial state at `strain` from the committed plastic strain.
  void trialFrom(double strain);

  double E_, epsyP_, epsyN_, eps0_;
  double trialStrain_ = 0.0, trialStress_ = 0.0, trialTangent_;
  double trialPlasticStrain_ = 0.0;
  // The committed stress and tangent are stored, not recomputed: at the yield
  // point the predictor alone cannot tell loading (tangent 0) from elastic.
  double committedStrain_ = 0.0, committedStress_ = 0.0, committedTangent_;
  double committedPlasticStrain_ = 0.0;
};

}  // namespace beamsolid
