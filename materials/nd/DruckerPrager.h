#pragma once
#include "materials/nd/NDMaterial.h"
#include "materials/nd/VoigtTensors.h"

namespace beamsolid {

// nDMaterial('DruckerPrager', tag, K, G, sigmaY, rho, rhoBar, Kinf, Ko,
// delta1, delta2, H, theta, density, <atmPressure=101e3>) in its
// three-dimensional form (plane strain: PlaneFromThreeDimensional), as the
// OpenSees manual writes it (docs/soil_materials.md, section Drucker-Prager):
//   cone:      f1 = ||s - beta|| + rho I1 - sqrt(2/3) Y(alpha)
//              Y(alpha) = sigmaY + theta H alpha + (Kinf - Ko)(1 - exp(-delta1 alpha))
//   cutoff:    f2 = I1 - T(alphaT),  T = T0 exp(-delta2 alphaT),  T0 = sqrt(2/3) sigmaY / rho
//              (rho = 0: von Mises, no cutoff)
//   flow:      d eps_p = dgamma1 (n + rhoBar 1) + dgamma2 1,
//              d alpha = sqrt(2/3) dgamma1, d beta = (2/3)(1 - theta) H dgamma1 n,
//              d alphaT = dgamma2
// Backward Euler with an active set (cone, apex, cutoff, cone and cutoff)
// and the consistent (algorithmic) tangent, unsymmetric when rhoBar != rho.
// The apex is the cone's subdifferential: there s = beta and the deviatoric
// plastic strain takes what the trial deviator leaves.
//
// Stages: 1 plastic (the default, as OpenSeesPy 3.7.1's), 0 elastic with the
// plastic state frozen (updateMaterialStage 0/1). setParameter
// 'materialState' takes OpenSees' numbers: 0 elastic, 2 plastic; OpenSees'
// 1 (elastic with moduli updated from the pressure through atmPressure) is
// not implemented and raises.
class DruckerPrager : public NDMaterial {
 public:
  using Vector6 = voigt::Vector6;
  using Matrix6 = voigt::Matrix6;

  struct Parameters {
    double K = 0, G = 0, sigmaY = 0, rho = 0, rhoBar = 0, Kinf = 0, Ko = 0, delta1 = 0, delta2 = 0, H = 0,
           theta = 0, density = 0, atmPressure = 101e3;
  };

  DruckerPrager(int tag, const Parameters& p);

  std::string className() const override { return "DruckerPrager"; }
  bool isLinear() const override { return stage_ == 0; }
  // "ThreeDimensional" (a copy), "PlaneStrain" (wrapped); nullptr otherwise
  // (OpenSees offers no plane-stress Drucker-Prager).
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(tangent_); }
  MatrixView initialTangent() const override { return viewOf(elastic_); }
  double density() const override { return p_.density; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void updateStage(int stage) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;
  // Beyond 'stress', 'strain', 'tangent': 'state' (as OpenSeesPy 3.7.1:
  // I1, ||s - beta||, tr(eps_p), ||dev(eps_p)||, ||eps_p||; the manual
  // lists the first four), 'plasticStrain' (6,
  // engineering shears), 'equivalentPlasticStrain' (alpha).
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

  int stage() const { return stage_; }
  // Which return the last trial took: 0 elastic, 1 cone, 2 apex, 3 cutoff,
  // 4 cone and cutoff, 5 apex and cutoff.
  int lastReturn() const { return lastReturn_; }
  Vector6 plasticStrain() const { return voigt::tensorToStrain(plasticStrainTrial_); }

 private:
  struct Trial;
  double Y(double alpha) const;
  double dY(double alpha) const;
  double T(double alphaT) const;
  double dT(double alphaT) const;
  void integrate();
  // Solves the active residuals for (dgamma1, dgamma2); false when no root.
  bool solve(const Trial& t, bool cone, bool cutoff, double& dg1, double& dg2) const;
  void residuals(const Trial& t, bool cone, bool cutoff, double dg1, double dg2, Eigen::Vector2d& F,
                 Eigen::Matrix2d& J) const;

  Parameters p_;
  double T0_ = 0.0;
  int stage_ = 1;
  int lastReturn_ = 0;
  Matrix6 elastic_;

  Vector6 strain_ = Vector6::Zero(), stress_ = Vector6::Zero();
  Matrix6 tangent_;
  Vector6 plasticStrainTrial_ = Vector6::Zero(), plasticStrainCommitted_ = Vector6::Zero();
  Vector6 backStressTrial_ = Vector6::Zero(), backStressCommitted_ = Vector6::Zero();
  double alphaTrial_ = 0.0, alphaCommitted_ = 0.0;
  double alphaTensionTrial_ = 0.0, alphaTensionCommitted_ = 0.0;
  Vector6 strainCommitted_ = Vector6::Zero();
  // The committed answer, restored as it was by revertToLastCommit.
  Vector6 stressCommitted_ = Vector6::Zero();
  Matrix6 tangentCommitted_;
  // False once a stage or parameter change makes the stored answer stale.
  bool committedAnswerValid_ = true;
};

}  // namespace beamsolid
