#pragma once
#include <memory>

#include "materials/nd/NDMaterial.h"
#include "materials/nd/VoigtTensors.h"

namespace beamsolid {

// nDMaterial('PlateFiber', tag, mat3DTag): a three-dimensional material in
// a plate fiber, strain [e11, e22, g12, g23, g31] and stress [s11, s22, s12,
// s23, s31], with the normal strain e33 solved so that s33 = 0 (Newton with
// the 3D tangent from the last committed e33) and the tangent condensed,
// D_ff - D_f3 D_33^-1 D_3f. What plate sections ('PlateFiber',
// 'LayeredShell') integrate through the thickness.
class PlateFiberMaterial : public NDMaterial {
 public:
  using Vector5 = Eigen::Matrix<double, 5, 1>;
  using Matrix5 = Eigen::Matrix<double, 5, 5>;

  PlateFiberMaterial(int tag, std::unique_ptr<NDMaterial> threeDimensional);
  PlateFiberMaterial(const PlateFiberMaterial& other);

  std::string className() const override { return "PlateFiber"; }
  bool isLinear() const override { return inner_->isLinear(); }
  // "PlateFiber": a copy; "ThreeDimensional": the 3D material's.
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

  // 'stress', 'strain' (5 each); anything else goes to the 3D material.
  Response setResponse(const std::vector<std::string>& args) override;

 private:
  void evaluate();

  std::unique_ptr<NDMaterial> inner_;
  Vector5 strain_ = Vector5::Zero(), stress_ = Vector5::Zero(), strainCommitted_ = Vector5::Zero();
  Matrix5 tangent_ = Matrix5::Zero(), initialTangent_ = Matrix5::Zero();
  double e33_ = 0.0, e33Committed_ = 0.0;
  voigt::Vector6 strain3D_ = voigt::Vector6::Zero();
};

}  // namespace beamsolid
