#pragma once
#include "materials/uniaxial/OwnedMaterial.h"

namespace beamsolid {

// uniaxialMaterial('MinMax', tag, otherTag, <'-min', minStrain>, <'-max', maxStrain>):
// behaves as the other material until a trial strain reaches minStrain or
// maxStrain (defaults -1e16 and 1e16); from then on the material
// has failed: stress 0 and, as OpenSees, a tangent of 1e-8 times the other
// material's initial tangent, so a failed bar does not make the stiffness
// singular. Failure is part of the state: it is committed and reverted.
class MinMaxMaterial : public UniaxialMaterial {
 public:
  MinMaxMaterial(int tag, const UniaxialMaterial& other, double minStrain, double maxStrain);

  std::string className() const override { return "MinMax"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  // After failure, the other material's last strain (as OpenSees reports).
  double strain() const override { return trialFailed_ ? other_->strain() : strain_; }
  double stress() const override;
  double tangent() const override;
  double initialTangent() const override { return other_->initialTangent(); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  bool failed() const { return trialFailed_; }
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

 private:
  OwnedMaterial other_;
  double minStrain_, maxStrain_;
  double strain_ = 0.0, committedStrain_ = 0.0;
  bool trialFailed_ = false, committedFailed_ = false;
};

}  // namespace beamsolid
