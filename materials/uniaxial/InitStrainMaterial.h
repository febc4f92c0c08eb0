#pragma once
#include "materials/uniaxial/OwnedMaterial.h"

namespace beamsolid {

// uniaxialMaterial('InitStrainMaterial', tag, otherTag, eps0): the other
// material driven at strain + eps0 (its path starts by a step to eps0), so
// the stress at zero strain is the other material's stress at eps0. The
// strain reported is the one applied (without eps0).
class InitStrainMaterial : public UniaxialMaterial {
 public:
  InitStrainMaterial(int tag, const UniaxialMaterial& other, double initialStrain);

  std::string className() const override { return "InitStrainMaterial"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return strain_; }
  double stress() const override { return other_->stress(); }
  double tangent() const override { return other_->tangent(); }
  double initialTangent() const override { return other_->initialTangent(); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

 private:
  OwnedMaterial other_;
  double initialStrain_;
  double strain_ = 0.0, committedStrain_ = 0.0;
};

}  // namespace beamsolid
