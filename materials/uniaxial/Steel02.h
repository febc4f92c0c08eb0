#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Steel02', tag, Fy, E0, b, <R0=15, cR1=0.925, cR2=0.15>,
//                  <a1=0, a2=1, a3=0, a4=1>, <sigInit=0>):
// Giuffre-Menegotto-Pinto steel with Filippou's isotropic hardening.
// Each branch starts at a reversal point (strainR, stressR) and follows
//   s* = b*e* + (1-b)*e* / (1 + |e*|^R)^(1/R),
//   e* = (e - eR)/(e0 - eR),  s* = (s - sR)/(s0 - sR),
// a smooth transition from the elastic line of slope E0 through the
// reversal point to the yield asymptote of slope b*E0; (e0, s0) is where
// the two lines meet. The asymptotes are the lines
//   b*E0*e +- (1-b)*Fy*(1 + growth),
// the growth of each side set at a reversal towards it by
//   a1 * ((maxStrain - minStrain) / (2*a2*Fy/E0))^0.8   (compression; a3, a4 tension).
// The curvature parameter R = R0*(1 - cR1*xi/(cR2 + xi)) falls with the
// plastic excursion xi = |extreme strain towards the branch - e0| / (Fy/E0)
// (Bauschinger effect). sigInit is an initial stress: the material starts
// at strain sigInit/E0 on the internal curve and reports stress sigInit at
// zero strain.
class Steel02 : public UniaxialMaterial {
 public:
  struct Parameters {
    double fy, E0, b;
    double R0 = 15.0, cR1 = 0.925, cR2 = 0.15;
    double a1 = 0.0, a2 = 1.0, a3 = 0.0, a4 = 1.0;
    double sigInit = 0.0;
  };
  Steel02(int tag, const Parameters& p);

  std::string className() const override { return "Steel02"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain - initialStrain_; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return p_.E0; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  // The current branch, for tests: its curvature parameter R and the
  // intersection (e0, s0) of its two asymptotes (in internal strain).
  double curvature() const;
  double asymptoteStrain() const { return trial_.asymptoteStrain - initialStrain_; }
  double asymptoteStress() const { return trial_.asymptoteStress; }

  void print(std::ostream& os) const override;

 private:
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;  // strain includes initialStrain_
    int direction = 0;  // +1 towards tension, -1 towards compression, 0 before any step
    double reversalStrain = 0.0, reversalStress = 0.0;
    double asymptoteStrain = 0.0, asymptoteStress = 0.0;
    double excursion = 0.0;  // xi
    double maxStrain = 0.0, minStrain = 0.0;
  };
  void startBranch(State& s, int direction) const;

  Parameters p_;
  double yieldStrain_, initialStrain_;
  State trial_, committed_;
};

}  // namespace beamsolid
