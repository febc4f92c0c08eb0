#pragma once
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// An nDMaterial in OpenSees' "AxiSymmetric" form, strain [e11, e22, e33,
// g12] and stress [s11, s22, s33, s12], made from any material's
// ThreeDimensional form with g23 = g13 = 0. The B-bar quad asks for this
// form: its mean dilatation puts a strain e33 into a plane strain element.
// For materials that have no AxiSymmetric form of their own (copyOf); it
// changes nothing for an isotropic material, whose 23 and 13 shear stresses
// vanish with those strains.
class AxiSymmetricFrom3D : public NDMaterial {
 public:
  using Vector4 = Eigen::Matrix<double, 4, 1>;
  using Matrix4 = Eigen::Matrix<double, 4, 4>;

  explicit AxiSymmetricFrom3D(std::unique_ptr<NDMaterial> threeDimensional);
  // The material's own AxiSymmetric form, else this adapter around its
  // ThreeDimensional form; nullptr when it has neither.
  static std::unique_ptr<NDMaterial> copyOf(const NDMaterial& material);
  AxiSymmetricFrom3D(const AxiSymmetricFrom3D& other);

  std::string className() const override { return solid_->className(); }
  bool isLinear() const override { return solid_->isLinear(); }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return viewOf(strain_); }
  VectorView stress() const override { return viewOf(stress_); }
  MatrixView tangent() const override { return viewOf(tangent_); }
  MatrixView initialTangent() const override { return viewOf(initialTangent_); }
  double density() const override { return solid_->density(); }

  void commitState() override { solid_->commitState(); }
  void revertToLastCommit() override;
  void revertToStart() override;

  void updateStage(int stage) override;
  void initialStateAnalysis(bool on) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;

  // 'stress' (sigma11 sigma22 sigma33 sigma12), 'strain' (eta11 ... eta12,
  // OpenSees' names for the 2D forms), 'tangent' (16); other names go to
  // the three-dimensional material.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override { solid_->print(os); }

  const NDMaterial& threeDimensional() const { return *solid_; }

 private:
  // Reads stress and tangents back from the three-dimensional material.
  void readBack();

  std::unique_ptr<NDMaterial> solid_;
  Vector4 strain_ = Vector4::Zero(), stress_ = Vector4::Zero();
  Matrix4 tangent_ = Matrix4::Zero(), initialTangent_ = Matrix4::Zero();
};

}  // namespace beamsolid
