#pragma once
#include "elements/SmallStrain.h"
#include "elements/SolidElement.h"

namespace beamsolid {

// A stabilized single-point solid (SSPquad, SSPbrick): one material point
// at the centre, strain = B0 u with B0 of the mean shape function
// gradients, and a stabilization stiffness K_stab that acts on the
// hourglass modes only (zero on every linear displacement field, so the
// patch test holds) and is built from the material's initial tangent:
//   K = V B0^T D B0 + K_stab,   f = V B0^T sigma + K_stab u
// (V the volume, times thick in 2D). K_stab from the initial tangent keeps f
// and K consistent and is what OpenSees does (checked with OpenSeesPy 3.7.1:
// the hourglass forces of an element yielded in J2 are the elastic ones).
template <int Dim, int Strains>
class SinglePointSolid : public SolidElement<Dim> {
 public:
  using Base = SolidElement<Dim>;
  using typename Base::NodalMatrix;
  using typename Base::NodalVector;
  using StrainVector = Eigen::Matrix<double, Strains, 1>;
  using StrainMatrix = Eigen::Matrix<double, Strains, Strains>;
  using StrainDisplacement = Eigen::Matrix<double, Strains, Base::kDofs>;

  SinglePointSolid(int tag, const std::array<int, Base::kNodes>& nodeTags, const NDMaterial& material,
                   const std::string& kind, double thickness, const typename Base::BodyForce& bodyForce)
      : Base(tag, nodeTags, material, kind, 1, thickness, bodyForce) {}

  // The stabilization stiffness in use (nodal dofs).
  const NodalMatrix& stabilization() const { return stabilization_; }

 protected:
  // K_stab for the material's initial tangent D0 (geometry from cell()).
  virtual void formStabilization(const StrainMatrix& D0, NodalMatrix& K) const = 0;

  // The centre strain uses the mean gradients (1/V) integral(grad N dV):
  // equal to the centre gradients for a quadrilateral, and the uniform
  // gradient of Flanagan and Belytschko for a hexahedron.
  void prepare() override {
    smallstrain::strainDisplacement(this->cell().meanGradients(), centreB_);
    prepared_ = true;
    rebuildStabilization();
  }

  void materialsChanged() override {
    Base::materialsChanged();
    if (prepared_) rebuildStabilization();
  }

  double weight() const { return this->thickness() * this->cell().volume(); }

  void setMaterialStrains(const NodalVector& u) override {
    const StrainVector strain = centreB_ * u;
    this->materials_[0]->setTrialStrain(strain);
  }

  void formStiffness(bool initial, NodalMatrix& K) const override {
    const StrainMatrix D = initial ? this->materials_[0]->initialTangent() : this->materials_[0]->tangent();
    K.noalias() = weight() * (centreB_.transpose() * (D * centreB_));
    K += stabilization_;
  }

  void formInternalForce(NodalVector& f) const override {
    const StrainVector stress = this->materials_[0]->stress();
    f.noalias() = weight() * (centreB_.transpose() * stress);
    f.noalias() += stabilization_ * this->displacement_;
  }

  const StrainDisplacement& centreB() const { return centreB_; }

 private:
  void rebuildStabilization() {
    const StrainMatrix D0 = this->materials_[0]->initialTangent();
    formStabilization(D0, stabilization_);
  }

  bool prepared_ = false;  // the geometry is known (setDomain ran)
  StrainDisplacement centreB_ = StrainDisplacement::Zero();
  NodalMatrix stabilization_ = NodalMatrix::Zero();
};

}  // namespace beamsolid
