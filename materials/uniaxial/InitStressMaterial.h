#pragma once
#include "materials/uniaxial/OwnedMaterial.h"

namespace beamsolid {

// uniaxialMaterial('InitStressMaterial', tag, otherTag, sigma0): the other
// material shifted by the strain eps0 at which it carries sigma0 (found by
// Newton's method on its loading curve from zero), so the stress at zero
// strain is sigma0. The strain reported is the one applied (without eps0).
class InitStressMaterial : public UniaxialMaterial {
 public:
  // Throws OpenSeesError (naming `context`) when no strain gives sigma0.
  InitStressMaterial(int tag, const UniaxialMaterial& other, double initialStress, const std::string& context);

  std::string className() const override { return "InitStressMaterial"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return strain_; }
  double stress() const override { return other_->stress(); }
  double tangent() const override { return other_->tangent(); }
  double initialTangent() const override { return other_->initialTangent(); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  double initialStrain() const { return initialStrain_; }
  void print(std::ostream& os) const override;

 private:
  OwnedMaterial other_;
  double initialStress_, initialStrain_ = 0.0;
  double strain_ = 0.0, committedStrain_ = 0.0;
};

}  // namespace beamsolid
