#pragma once
#include "materials/uniaxial/KentParkEnvelope.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Concrete01', tag, fpc, epsc0, fpcu, epsU):
// Kent-Scott-Park concrete without tensile strength (compression negative;
// positive input is taken as its negative). Loading beyond the most
// compressive strain reached follows the envelope (KentParkEnvelope.h).
// Unloading and reloading follow one straight line from that envelope point
// (epsMin, sigMin) to the plastic strain epsP of Karsan and Jirsa,
//   r = epsMin/epsc0:  epsP/epsc0 = 0.145 r^2 + 0.13 r      (r < 2)
//                      epsP/epsc0 = 0.707 (r - 2) + 0.834   (r >= 2),
// with r held at epsU/epsc0 beyond epsU and the slope of the line at most
// the initial tangent Ec = 2 fpc/epsc0. Strains above the line's zero give
// zero stress.
class Concrete01 : public UniaxialMaterial {
 public:
  Concrete01(int tag, double fpc, double epsc0, double fpcu, double epsU);

  std::string className() const override { return "Concrete01"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return envelope_.initialTangent(); }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  // The unloading line from the envelope point at `minStrain` (for tests).
  void unloadingLine(double minStrain, double& slope, double& zeroStressStrain) const;

  void print(std::ostream& os) const override;

 private:
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double minStrain = 0.0;  // most compressive strain reached
  };

  KentParkEnvelope envelope_;
  State trial_, committed_;
};

}  // namespace beamsolid
