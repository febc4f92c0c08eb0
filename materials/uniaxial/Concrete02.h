#pragma once
#include "materials/uniaxial/KentParkEnvelope.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('Concrete02', tag, fpc, epsc0, fpcu, epsU,
//                  <lambda=0.1, ft=0.1*|fpc|, Ets=0.1*|fpc/epsc0|>):
// concrete with linear tension softening after Mohd Yassin (1994)
// (compression negative; positive compressive input is taken as negative).
// Compression: Kent-Scott-Park envelope (KentParkEnvelope.h). Unloading and
// reloading lines from the envelope point (epsMin, sigMin) aim at a focal
// point R on the initial tangent line, where that line meets the unloading
// line from the crushing point (epsU, fpcu) of slope lambda*Ec:
//   epsR = (fpcu - lambda*Ec*epsU) / (Ec*(1 - lambda)),  sigR = Ec*epsR,
//   Er = (sigMin - sigR)/(epsMin - epsR),  epsT = epsMin - sigMin/Er.
// Below epsT the stress moves with Ec from the committed state, bounded
// below by the reloading line sigMin + Er*(e - epsMin) and above by the
// unloading line 0.5*Er*(e - epsT): this gives the hysteresis loops.
// Above epsT (the crack opening) the tension envelope rises with Ec to ft
// and softens with -Ets to zero; unloading from it and reloading follow the
// secant to (epsT, 0).
class Concrete02 : public UniaxialMaterial {
 public:
  Concrete02(int tag, double fpc, double epsc0, double fpcu, double epsU, double lambda, double ft, double Ets);

  std::string className() const override { return "Concrete02"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return envelope_.initialTangent(); }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  // The reloading line from the envelope point at `minStrain`: its slope Er
  // and the strain epsT where it reaches zero stress (for tests).
  void reloadingLine(double minStrain, double& slope, double& zeroStressStrain) const;

  void print(std::ostream& os) const override;

 private:
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0;
    double minStrain = 0.0;       // most compressive strain reached
    double maxCrackOpening = 0.0;  // largest strain beyond epsT reached in tension
  };
  // Tension envelope as a function of the strain beyond epsT.
  void tensionEnvelope(double opening, double& stress, double& tangent) const;

  KentParkEnvelope envelope_;
  double lambda_, ft_, Ets_;
  State trial_, committed_;
};

}  // namespace beamsolid
