#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('BoucWen', tag, alpha, ko, n, gamma, beta, Ao, deltaA,
// deltaNu, deltaEta, <tol, maxIter>): the smooth hysteretic Bouc-Wen model
// with the strength and stiffness degradation of Baber and Noori (1985):
//   sigma = alpha ko eps + (1 - alpha) ko z,
//   dz = deps (A - |z|^n nu (gamma + beta sgn(deps z))) / eta,
//   A = Ao - deltaA e, nu = 1 + deltaNu e, eta = 1 + deltaEta e,
// with e the hysteretic energy, de = (1 - alpha) ko z deps. Each step is
// backward Euler (z and e at the end of the step) solved by Newton; the
// tangent is its consistent linearization. A step without a strain change
// keeps the committed state (the tangent before any step is ko). Equal to
// OpenSeesPy 3.7.1 point by point (tests/python/test_bouc_wen.py).
class BoucWenMaterial : public UniaxialMaterial {
 public:
  struct Parameters {
    double alpha = 0.0, ko = 0.0, n = 1.0, gamma = 0.0, beta = 0.0, Ao = 1.0;
    double deltaA = 0.0, deltaNu = 0.0, deltaEta = 0.0;
    double tolerance = 1e-8;
    int maxIterations = 20;
  };

  BoucWenMaterial(int tag, const Parameters& p);

  std::string className() const override { return "BoucWen"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.strain; }
  double stress() const override { return trial_.stress; }
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return p_.ko; }

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override;

  // 'stress', 'strain', 'tangent', 'stressStrain', and 'z' (the hysteretic
  // variable) and 'energy'.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

 private:
  struct State {
    double strain = 0.0, stress = 0.0, tangent = 0.0, z = 0.0, energy = 0.0;
  };
  Parameters p_;
  State trial_, committed_;
};

}  // namespace beamsolid
