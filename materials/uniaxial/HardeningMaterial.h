#pragma once
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Hardening', tag, E, sigmaY, H_iso, H_kin, <eta>):
// rate-independent 1D plasticity with linear isotropic (H_iso) and kinematic
// (H_kin) hardening, integrated by the closed-form return map (Simo & Hughes,
// Computational Inelasticity, box 1.5). The yield function is
//   f = |sigma - q| - (sigmaY + H_iso * alpha)
// with back stress q and accumulated plastic strain alpha; on yielding the
// tangent is E*(H_iso+H_kin)/(E+H_iso+H_kin). OpenSees accepts eta but does
// not use it (it says so); we accept and ignore it the same way.
class HardeningMaterial : public UniaxialMaterial {
 public:
  HardeningMaterial(int tag, double E, double sigmaY, double Hiso, double Hkin);

  std::string className() const override { return "Hardening"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return E_; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  double plasticStrain() const { return trial_.plasticStrain; }
  double backStress() const { return trial_.backStress; }

  // 'E', 'sigmaY' (or 'Fy', 'fy'), 'H_iso' (or 'Hiso'), 'H_kin' (or 'Hkin').
  bool setParameter(const std::vector<std::string>& args, double value) override;
  // Sensitivities by differentiating the return map (the same names, ids 1-4).
  int sensitivityParameter(const std::vector<std::string>& args) override;
  double stressSensitivity(int gradient, int parameterId) override;
  void commitSensitivity(double strainSensitivity, int gradient, int parameterId, int numGradients) override;

  void print(std::ostream& os) const override;

 private:
  // How the trial state was reached from the committed one.
  enum class Branch { Unchanged, Elastic, Plastic };
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double plasticStrain = 0.0, backStress = 0.0, alpha = 0.0;
    Branch branch = Branch::Unchanged;
    double dGamma = 0.0, sign = 1.0;
  };
  // d/d theta of the committed state's stress and history.
  struct Sensitivity {
    double stress = 0.0, plasticStrain = 0.0, backStress = 0.0, alpha = 0.0;
  };
  // The trial state's sensitivity for a strain sensitivity dStrain.
  Sensitivity trialSensitivity(double dStrain, int gradient, int parameterId) const;

  double E_, sigmaY_, Hiso_, Hkin_;
  State trial_, committed_;
  std::vector<Sensitivity> sensitivity_;  // one per gradient
};

}  // namespace beamsolid
