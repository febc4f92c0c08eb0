#pragma once
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// nDMaterial('InitialStateAnalysisWrapper', tag, innerTag, nDim): any nDMaterial
// that keeps its state when InitialStateAnalysis('off') zeroes the nodal
// displacements. At 'off' the wrapper records the inner material's strain as
// an initial strain eps0 and from then on passes eps + eps0 to it, so the
// stress of a gravity stage stays while the geometry returns to the
// reference (as in OpenSees: a plain material is re-evaluated at zero
// strain instead). strain() is the inner material's, eps0 included.
// Only nDim 3 (ThreeDimensional) here.
class InitialStateAnalysisWrapper : public NDMaterial {
 public:
  InitialStateAnalysisWrapper(int tag, std::unique_ptr<NDMaterial> inner);

  std::string className() const override { return "InitialStateAnalysisWrapper"; }
  bool isLinear() const override { return inner_->isLinear(); }
  std::unique_ptr<NDMaterial> clone(const std::string& kind) const override;

  void setTrialStrain(const Eigen::Ref<const Vector>& strain) override;
  VectorView strain() const override { return inner_->strain(); }
  VectorView stress() const override { return inner_->stress(); }
  MatrixView tangent() const override { return inner_->tangent(); }
  MatrixView initialTangent() const override { return inner_->initialTangent(); }
  double density() const override { return inner_->density(); }

  void commitState() override { inner_->commitState(); }
  void revertToLastCommit() override { inner_->revertToLastCommit(); }
  // Back to the virgin state: the initial strain goes too.
  void revertToStart() override;

  void initialStateAnalysis(bool on) override;
  void updateStage(int stage) override { inner_->updateStage(stage); }
  bool setParameter(const std::vector<std::string>& args, double value) override {
    return inner_->setParameter(args, value);
  }
  // The inner material's responses (its stress and strain are the wrapper's), so that a
  // wrapped plastic soil still reports 'plasticStrain' and 'equivalentPlasticStrain' to its
  // elements and the PVD recorder.
  Response setResponse(const std::vector<std::string>& args) override { return inner_->setResponse(args); }
  void print(std::ostream& os) const override;

  const Vector& initialStrain() const { return initialStrain_; }

 private:
  std::unique_ptr<NDMaterial> inner_;
  Vector initialStrain_;
  Vector totalStrain_;  // eps + eps0, kept so that a Gauss-point update does not allocate
};

}  // namespace beamsolid
