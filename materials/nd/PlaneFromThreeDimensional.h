#pragma once
#include "materials/nd/NDMaterial.h"
#include "materials/nd/VoigtTensors.h"

namespace beamsolid {

// The plane forms quads ask for ("PlaneStrain", "PlaneStress") of a
// three-dimensional material, with strain [e11, e22, g12] and stress
// [s11, s22, s12]:
// - PlaneStrain: the 3D strain [e11, e22, 0, g12, 0, 0]; the tangent is the
//   in-plane block of the 3D one. sigma_33 stays in the 3D state
//   (response 'stress3D').
// - PlaneStress: the out-of-plane strains z = [e33, g23, g13] are solved so
//   that [s33, s23, s13] = 0 (Newton with the 3D tangent, from the last
//   committed z), and the tangent is the condensed
//   D_pp - D_pz D_zz^-1 D_zp, exact for the converged z.
// State, stages and parameters are the 3D material's.
class PlaneFromThreeDimensional : public NDMaterial {
 public:
  enum class Plane { Strain, Stress };
  using Vector3 = Eigen::Matrix<double, 3, 1>;
  using Matrix3 = Eigen::Matrix<double, 3, 3>;

  PlaneFromThreeDimensional(std::unique_ptr<NDMaterial> threeDimensional, Plane plane);
  PlaneFromThreeDimensional(const PlaneFromThreeDimensional& other);

  std::string className() const override;
  bool isLinear() const override { return inner_->isLinear(); }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(tangent_); }
  MatrixView initialTangent() const override { return viewOf(initialTangent_); }
  double density() const override { return inner_->density(); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void updateStage(int stage) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;
  // 'stress' (sigma11, sigma22, sigma12), 'strain' (eta11, eta22, eta12, as
  // OpenSees names the plane forms), 'stress3D' and 'strain3D' (the 6
  // components of the 3D state); anything else goes to the 3D material.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

  const NDMaterial& threeDimensional() const { return *inner_; }
  Plane plane() const { return plane_; }

 private:
  void evaluate();
  void formInitialTangent();

  std::unique_ptr<NDMaterial> inner_;
  Plane plane_;
  Vector3 strain_ = Vector3::Zero(), stress_ = Vector3::Zero();
  Matrix3 tangent_ = Matrix3::Zero(), initialTangent_ = Matrix3::Zero();
  voigt::Vector6 strain3D_ = voigt::Vector6::Zero();
  // Out-of-plane strains [e33, g23, g13] (plane stress): trial and committed.
  Vector3 outOfPlane_ = Vector3::Zero(), outOfPlaneCommitted_ = Vector3::Zero();
  Vector3 strainCommitted_ = Vector3::Zero();
};

}  // namespace beamsolid
