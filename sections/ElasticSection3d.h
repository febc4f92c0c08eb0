#pragma once
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

// section('Elastic', tag, E, A, Iz, Iy, G, J, <alphaY, alphaZ>): linear 3D
// section with ks = diag(EA, EIz, EIy, GJ) about its centroid. With alphaY,
// alphaZ it is shear-deformable: Vy = alphaY G A gammaY, Vz = alphaZ G A
// gammaZ, reported (as OpenSees) in the order [P, Mz, Vy, My, Vz, T].
class ElasticSection3d : public SectionForceDeformation {
 public:
  struct Properties {
    double E = 0.0, A = 0.0, Iz = 0.0, Iy = 0.0, G = 0.0, J = 0.0;
    bool shear = false;
    double alphaY = 0.0, alphaZ = 0.0;
  };

  ElasticSection3d(int tag, const Properties& properties);

  std::string className() const override { return "Elastic"; }
  std::unique_ptr<SectionForceDeformation> clone() const override;

  void setTrialDeformation(const Vector4& e) override;
  const Vector4& deformation() const override { return deformation_; }
  const Vector4& force() const override { return force_; }
  const Matrix4& tangent() const override { return stiffness_; }
  const Matrix4& initialTangent() const override { return stiffness_; }

  int numShear() const override { return properties_.shear ? 2 : 0; }
  SectionCode shearCode(int k) const override;
  void setTrialShear(const ShearVector& gamma) override;
  ShearVector shearDeformation() const override { return shearDeformation_.head(numShear()); }
  ShearVector shearForce() const override { return shearStiffness_.cwiseProduct(shearDeformation_).head(numShear()); }
  ShearVector shearTangent() const override { return shearStiffness_.head(numShear()); }
  ShearVector shearInitialTangent() const override { return shearStiffness_.head(numShear()); }
  std::vector<SectionCode> responseCodes() const override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void print(std::ostream& os) const override;
  const Properties& properties() const { return properties_; }

 private:
  Properties properties_;
  Matrix4 stiffness_ = Matrix4::Zero();
  Vector4 deformation_ = Vector4::Zero();
  Vector4 force_ = Vector4::Zero();
  Vector4 committedDeformation_ = Vector4::Zero();
  Eigen::Vector2d shearStiffness_ = Eigen::Vector2d::Zero();  // alphaY G A, alphaZ G A
  Eigen::Vector2d shearDeformation_ = Eigen::Vector2d::Zero(), committedShear_ = Eigen::Vector2d::Zero();
};

}  // namespace beamsolid
