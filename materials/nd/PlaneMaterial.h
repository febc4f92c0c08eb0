#pragma once
#include <memory>

#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// nDMaterial('PlaneStress' | 'PlaneStrain', tag, mat3DTag): a
// three-dimensional material used in one plane form whatever the element
// asks for, as OpenSees' wrappers are (a quad declared 'PlaneStrain' on a
// 'PlaneStress' wrapper is in plane stress). The plane form is the 3D
// material's own (exact for ElasticIsotropic, PlaneFromThreeDimensional
// for the plastic ones).
class PlaneMaterial : public NDMaterial {
 public:
  PlaneMaterial(int tag, const NDMaterial& threeDimensional, const std::string& plane);
  PlaneMaterial(const PlaneMaterial& other);

  std::string className() const override { return plane_; }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override { form_->setTrialStrain(strain); }
  VectorView strain() const override { return form_->strain(); }
  VectorView stress() const override { return form_->stress(); }
  MatrixView tangent() const override { return form_->tangent(); }
  MatrixView initialTangent() const override { return form_->initialTangent(); }
  double density() const override { return form_->density(); }
  bool isLinear() const override { return form_->isLinear(); }

  void commitState() override { form_->commitState(); }
  void revertToLastCommit() override { form_->revertToLastCommit(); }
  void revertToStart() override { form_->revertToStart(); }

 private:
  std::unique_ptr<NDMaterial> threeDimensional_;
  std::string plane_;  // "PlaneStress" or "PlaneStrain"
  std::unique_ptr<NDMaterial> form_;  // the plane form, for the state queries
};

}  // namespace beamsolid
