#pragma once
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// The two-dimensional forms of nDMaterial('ElasticIsotropic', tag, E, nu,
// <rho>) that quad elements ask for: strain [e11, e22, g12] (engineering
// shear), stress [s11, s22, s12].
// - PlaneStrain: e33 = 0, D = E/((1+nu)(1-2nu)) [1-nu nu 0; nu 1-nu 0; 0 0 (1-2nu)/2]
// - PlaneStress: s33 = 0, D = E/(1-nu^2) [1 nu 0; nu 1 0; 0 0 (1-nu)/2]
// (the 3D law with e33 = 0, or condensed for s33 = 0).
class ElasticIsotropic2D : public NDMaterial {
 public:
  enum class Plane { Strain, Stress };
  using Vector3 = Eigen::Matrix<double, 3, 1>;
  using Matrix3 = Eigen::Matrix<double, 3, 3>;

  ElasticIsotropic2D(int tag, Plane plane, double E, double nu, double rho);

  // OpenSees' class names: ElasticIsotropicPlaneStrain2D, ElasticIsotropicPlaneStress2D.
  std::string className() const override;
  bool isLinear() const override { return true; }
  // A copy for the same kind ("PlaneStrain" or "PlaneStress"); nullptr otherwise.
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(trialStrain_); }
  VectorView stress() const override { return viewOf(trialStress_); }
  MatrixView tangent() const override { return viewOf(D_); }
  MatrixView initialTangent() const override { return viewOf(D_); }
  double density() const override { return rho_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 'stress' (sigma11, sigma22, sigma12), 'strain' (eta11, eta22, eta12:
  // OpenSees' names), 'tangent' (9).
  Response setResponse(const std::vector<std::string>& args) override;
  // 'E', 'nu', 'rho' as the 3D form.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

  Plane plane() const { return plane_; }

 private:
  void formTangent();

  Plane plane_;
  double E_, nu_, rho_;
  Matrix3 D_;
  Vector3 trialStrain_ = Vector3::Zero(), trialStress_ = Vector3::Zero();
  Vector3 committedStrain_ = Vector3::Zero();
};

}  // namespace beamsolid
