#pragma once
#include "sections/PlateSection.h"

namespace beamsolid {

// section('ElasticMembranePlateSection', tag, E, nu, h, <rho>): a linear
// isotropic plate of thickness h. Membrane Eh/(1-nu^2) [1 nu 0; nu 1 0;
// 0 0 (1-nu)/2], bending D = E h^3 / (12 (1 - nu^2)) times the same matrix,
// transverse shear 5/6 G h; mass rho h per unit area.
class ElasticMembranePlateSection : public PlateSection {
 public:
  struct Properties {
    double E = 0.0, nu = 0.0, h = 0.0, rho = 0.0;
  };

  ElasticMembranePlateSection(int tag, const Properties& properties);

  std::string className() const override { return "ElasticMembranePlateSection"; }
  std::unique_ptr<PlateSection> clone() const override;

  void setTrialDeformation(const Vector8& e) override;
  const Vector8& deformation() const override { return deformation_; }
  const Vector8& force() const override { return force_; }
  const Matrix8& tangent() const override { return stiffness_; }
  const Matrix8& initialTangent() const override { return stiffness_; }
  double areaDensity() const override { return properties_.rho * properties_.h; }

  void commitState() override { committedDeformation_ = deformation_; }
  void revertToLastCommit() override { setTrialDeformation(committedDeformation_); }
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  Properties properties_;
  Matrix8 stiffness_ = Matrix8::Zero();
  Vector8 deformation_ = Vector8::Zero();
  Vector8 force_ = Vector8::Zero();
  Vector8 committedDeformation_ = Vector8::Zero();
};

}  // namespace beamsolid
