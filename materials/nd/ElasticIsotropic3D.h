#pragma once
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// nDMaterial('ElasticIsotropic', tag, E, nu, <rho=0>) in its three-dimensional
// form: stress = D * strain with Voigt order [xx, yy, zz, xy, yz, zx] and
// engineering shear strains (so the shear diagonal of D is G, not 2G).
class ElasticIsotropic3D : public NDMaterial {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  ElasticIsotropic3D(int tag, double E, double nu, double rho);

  std::string className() const override { return "ElasticIsotropic3D"; }
  bool isLinear() const override { return true; }
  // "ThreeDimensional" (a copy), "PlaneStrain" or "PlaneStress" (an
  // ElasticIsotropic2D); nullptr for any other kind.
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

  // 'E', 'nu', 'rho' (same validity checks as the command).
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

  double E() const { return E_; }
  double nu() const { return nu_; }

 private:
  void formTangent();

  double E_, nu_, rho_;
  Matrix6 D_;
  Vector6 trialStrain_ = Vector6::Zero(), trialStress_ = Vector6::Zero();
  Vector6 committedStrain_ = Vector6::Zero();
};

}  // namespace beamsolid
