#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Viscous', tag, C, alpha): a dashpot, stress =
// C |rate|^alpha sgn(rate) of the strain rate (the element's deformation
// velocity); no stiffness. Its damping tangent alpha C |rate|^(alpha - 1)
// is evaluated at |rate| >= minRate (1e-11) so that alpha < 1 stays finite
// at rest.
class ViscousMaterial : public UniaxialMaterial {
 public:
  ViscousMaterial(int tag, double C, double alpha);

  std::string className() const override { return "Viscous"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override;
  double tangent() const override { return 0.0; }
  double initialTangent() const override { return 0.0; }
  double dampingTangent() const override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  void print(std::ostream& os) const override;

 private:
  double C_, alpha_;
  double trialStrain_ = 0.0, trialRate_ = 0.0;
  double committedStrain_ = 0.0, committedRate_ = 0.0;
};

}  // namespace beamsolid
