#pragma once
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// nDMaterial('ElasticOrthotropic', tag, Ex, Ey, Ez, nu_xy, nu_yz, nu_zx,
// Gxy, Gyz, Gzx, <rho=0>): linear elastic with orthotropic axes along x, y,
// z. The compliance of the normal stresses is symmetric with
//   S_xy = -nu_xy / Ex, S_yz = -nu_yz / Ey, S_zx = -nu_zx / Ez
// (nu_ij: the contraction along j under stress along i, measured against
// OpenSeesPy 3.7.1), the shears are G gamma; Voigt order [xx, yy, zz, xy, yz,
// zx] with engineering shears. Quads get its plane forms
// (PlaneFromThreeDimensional: plane stress condenses the 3D law).
class ElasticOrthotropic : public NDMaterial {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  struct Constants {
    double Ex = 0.0, Ey = 0.0, Ez = 0.0, nuXY = 0.0, nuYZ = 0.0, nuZX = 0.0, Gxy = 0.0, Gyz = 0.0, Gzx = 0.0;
    double rho = 0.0;
  };

  // Throws OpenSeesError when the constants do not make a positive definite D.
  ElasticOrthotropic(int tag, const Constants& c);

  std::string className() const override { return "ElasticOrthotropic"; }
  bool isLinear() const override { return true; }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(trialStrain_); }
  VectorView stress() const override { return viewOf(trialStress_); }
  MatrixView tangent() const override { return viewOf(D_); }
  MatrixView initialTangent() const override { return viewOf(D_); }
  double density() const override { return c_.rho; }

  void commitState() override { committedStrain_ = trialStrain_; }
  void revertToLastCommit() override;
  void revertToStart() override;
  void print(std::ostream& os) const override;

 private:
  Constants c_;
  Matrix6 D_ = Matrix6::Zero();
  Vector6 trialStrain_ = Vector6::Zero(), committedStrain_ = Vector6::Zero(), trialStress_ = Vector6::Zero();
};

}  // namespace beamsolid
