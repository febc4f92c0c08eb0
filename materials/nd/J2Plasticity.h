#pragma once
#include "materials/nd/NDMaterial.h"
#include "materials/nd/VoigtTensors.h"

namespace beamsolid {

// nDMaterial('J2Plasticity', tag, K, G, sig0, sigInf, delta, H, <eta=0>,
//            <'-kinematic', Hkin>) in its three-dimensional form: von Mises
// plasticity, associative flow, backward Euler (radial return), with the
// consistent tangent (docs/soil_materials.md, section J2).
//   yield:      f = ||dev(sigma) - beta|| - sqrt(2/3) q(xi)
//   hardening:  q(xi) = sig0 + (sigInf - sig0)(1 - exp(-delta xi)) + H xi
//   flow:       d eps_p = dgamma n,  d xi = sqrt(2/3) dgamma,
//               d beta = (2/3) Hkin dgamma n  (n = unit normal)
// so a uniaxial test yields at sig0 (checked against OpenSeesPy 3.7.1) and
// xi is the equivalent plastic strain sqrt(2/3)||eps_p|| under proportional
// loading. Hkin (linear kinematic hardening, 0 by default) is BeamSolid's
// addition; OpenSees' J2Plasticity has none. eta != 0 (OpenSees' rate
// dependence, which needs the analysis time step) is refused by the command.
//
// Stages (updateMaterialStage): 1 plastic (the default, as in OpenSees), 0
// elastic: sigma = K tr(eps) 1 + 2G (dev(eps) - eps_p) with the plastic
// state frozen, and the tangent constant (isLinear()).
// Plane strain and plane stress forms: PlaneFromThreeDimensional.
class J2Plasticity : public NDMaterial {
 public:
  using Vector6 = voigt::Vector6;
  using Matrix6 = voigt::Matrix6;

  struct Parameters {
    double K = 0, G = 0, sig0 = 0, sigInf = 0, delta = 0, H = 0;
    double kinematicH = 0;  // BeamSolid's option '-kinematic'
  };

  J2Plasticity(int tag, const Parameters& p);

  std::string className() const override { return "J2Plasticity"; }
  bool isLinear() const override { return stage_ == 0; }
  // "ThreeDimensional" (a copy); "PlaneStrain" and "PlaneStress" (the copy
  // wrapped in PlaneFromThreeDimensional); nullptr otherwise.
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(tangent_); }
  MatrixView initialTangent() const override { return viewOf(elastic_); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 0 elastic, 1 plastic; anything else is an OpenSeesError.
  void updateStage(int stage) override;
  // 'materialState' (as the stage), 'K', 'G', 'sig0', 'sigInf', 'delta', 'H'.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  // Beyond 'stress', 'strain', 'tangent': 'plasticStrain' (6, engineering
  // shears), 'equivalentPlasticStrain' (xi), 'backStress' (6).
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

  int stage() const { return stage_; }
  const Parameters& parameters() const { return p_; }
  // Plastic strain as a strain-like vector (engineering shears).
  Vector6 plasticStrain() const { return voigt::tensorToStrain(plasticStrainTrial_); }
  double equivalentPlasticStrain() const { return xiTrial_; }

 private:
  double yieldStress(double xi) const;
  double hardeningModulus(double xi) const;  // dq/dxi
  void integrate();

  Parameters p_;
  int stage_ = 1;
  Matrix6 elastic_;

  Vector6 strain_ = Vector6::Zero(), stress_ = Vector6::Zero();
  Matrix6 tangent_;
  // Internal variables: plastic strain and back stress as tensors
  // (stress-like layout), xi scalar; trial and committed.
  Vector6 plasticStrainTrial_ = Vector6::Zero(), plasticStrainCommitted_ = Vector6::Zero();
  Vector6 backStressTrial_ = Vector6::Zero(), backStressCommitted_ = Vector6::Zero();
  double xiTrial_ = 0.0, xiCommitted_ = 0.0;
  Vector6 strainCommitted_ = Vector6::Zero();
  // The committed answer, restored as it was by revertToLastCommit.
  Vector6 stressCommitted_ = Vector6::Zero();
  Matrix6 tangentCommitted_;
  // False once a stage or parameter change makes the stored answer stale.
  bool committedAnswerValid_ = true;
};

}  // namespace beamsolid
