#pragma once
#include "sections/SectionForceDeformation.h"

namespace beamsolid {

// section('Elastic', tag, E, A, Iz, Iy, G, J): linear 3D section with
// ks = diag(EA, EIz, EIy, GJ) about its centroid.
class ElasticSection3d : public SectionForceDeformation {
 public:
  struct Properties {
    double E = 0.0, A = 0.0, Iz = 0.0, Iy = 0.0, G = 0.0, J = 0.0;
  };

  ElasticSection3d(int tag, const Properties& properties);

  std::string className() const override { return "Elastic"; }
  std::unique_ptr<SectionForceDeformation> clone() const override;

  void setTrialDeformation(const Vector4& e) override;
  const Vector4& deformation() const override { return deformation_; }
  const Vector4& force() const override { return force_; }
  const Matrix4& tangent() const override { return stiffness_; }
  const Matrix4& initialTangent() const override { return stiffness_; }

  void commitState() override { committedDeformation_ = deformation_; }
  void revertToLastCommit() override { setTrialDeformation(committedDeformation_); }
  void revertToStart() override;

  void print(std::ostream& os) const override;
  const Properties& properties() const { return properties_; }

 private:
  Properties properties_;
  Matrix4 stiffness_ = Matrix4::Zero();
  Vector4 deformation_ = Vector4::Zero();
  Vector4 force_ = Vector4::Zero();
  Vector4 committedDeformation_ = Vector4::Zero();
};

}  // namespace beamsolid
