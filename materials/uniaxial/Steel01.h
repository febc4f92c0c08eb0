#pragma once
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Steel01', tag, Fy, E0, b, <a1, a2, a3, a4>):
// bilinear steel with kinematic hardening (post-yield tangent b*E0) and
// optional isotropic hardening. The stress is bounded by two yield lines of
// slope b*E0,
//   upper: b*E0*strain + (1-b)*Fy*(1 + tensionGrowth)
//   lower: b*E0*strain - (1-b)*Fy*(1 + compressionGrowth)
// and moves with E0 between them. At a reversal from tension the
// compression line grows by
//   compressionGrowth = a1 * ((maxStrain - minStrain) / (2*a2*Fy/E0))^0.8
// (a3, a4 likewise for the tension line at a reversal from compression),
// where max/minStrain are the extreme strains reached. The growth takes
// effect from the step after the reversal, so every trial uses committed
// yield lines and the tangent (E0 or b*E0) is the consistent one.
class Steel01 : public UniaxialMaterial {
 public:
  Steel01(int tag, double fy, double E0, double b, double a1 = 0.0, double a2 = 1.0, double a3 = 0.0,
          double a4 = 1.0);

  std::string className() const override { return "Steel01"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return E0_; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  // Isotropic growth of the yield lines as a fraction of Fy (for tests).
  double tensionGrowth() const { return trial_.tensionGrowth; }
  double compressionGrowth() const { return trial_.compressionGrowth; }

  // Sensitivities (sensitivityAlgorithm) to 'Fy' (or 'fy'), 'E0' (or 'E'),
  // 'b', 'a1'...'a4': the branch the trial took held, the rest differentiated.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  int sensitivityParameter(const std::vector<std::string>& args) override;
  double stressSensitivity(int gradient, int parameterId) override;
  void commitSensitivity(double strainSensitivity, int gradient, int parameterId, int numGradients) override;

  void print(std::ostream& os) const override;

 private:
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double maxStrain = 0.0, minStrain = 0.0;
    double tensionGrowth = 0.0, compressionGrowth = 0.0;
    int direction = 0;  // sign of the last strain increment, 0 before any
    int branch = 0;     // the trial's stress: 0 elastic, +1 upper line, -1 lower line
    bool unchanged = true;  // the trial kept the committed state (step below epsilon)
  };
  double growth(double a, double aStrain, double strainRange) const;
  // d/d theta of the committed stress, strain, extreme strains and growths.
  struct Sensitivity {
    double stress = 0.0, strain = 0.0, maxStrain = 0.0, minStrain = 0.0;
    double tensionGrowth = 0.0, compressionGrowth = 0.0;
  };
  Sensitivity trialSensitivity(double dStrain, int gradient, int parameterId) const;
  // d growth(a, aStrain, range) for the parameters' and range's changes.
  double growthSensitivity(int aId, int aStrainId, double a, double aStrain, double range, double dRange,
                           int parameterId) const;
  std::vector<Sensitivity> sensitivity_;  // one per gradient

  double fy_, E0_, b_, a1_, a2_, a3_, a4_;
  State trial_, committed_;
};

}  // namespace beamsolid
