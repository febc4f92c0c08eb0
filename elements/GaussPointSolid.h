#pragma once
#include "elements/SolidElement.h"

namespace beamsolid {

// A solid integrated on its cell's full Gauss rule (2^Dim points of a
// MultilinearCell, the centroid of a SimplexCell) with one material point
// per Gauss point: strain = B_g u, K = sum_g w_g B_g^T D_g B_g,
// f = sum_g w_g B_g^T sigma_g, w_g = thick det J_g. The formulations differ
// only in B_g (StdBrick, BbarBrick, FourNodeQuad, BbarQuad, Tri31,
// FourNodeTetrahedron); `Strains` is the size of the material's strain vector.
template <int Dim, int Strains, class CellType = MultilinearCell<Dim>>
class GaussPointSolid : public SolidElement<Dim, CellType> {
 public:
  using Base = SolidElement<Dim, CellType>;
  using typename Base::NodalMatrix;
  using typename Base::NodalVector;
  static constexpr int kGaussPoints = Base::Cell::kGaussPoints;
  using StrainVector = Eigen::Matrix<double, Strains, 1>;
  using StrainMatrix = Eigen::Matrix<double, Strains, Strains>;
  using StrainDisplacement = Eigen::Matrix<double, Strains, Base::kDofs>;

  GaussPointSolid(int tag, const std::array<int, Base::kNodes>& nodeTags, const NDMaterial& material,
                  const std::string& kind, double thickness, const typename Base::BodyForce& bodyForce)
      : Base(tag, nodeTags, material, kind, kGaussPoints, thickness, bodyForce) {}

  // Gauss point coordinates in the reference configuration.
  typename Base::Cell::Point gaussPointCoordinates(int g) const {
    return this->cell().coordinatesAt(Base::Cell::gaussPoint(g));
  }

 protected:
  // The strain-displacement matrix at Gauss point g.
  virtual void formStrainDisplacement(int g, StrainDisplacement& B) const = 0;

  double weight(int g) const { return this->thickness() * this->cell().weightedDetJ(g); }

  void setMaterialStrains(const NodalVector& u) override {
    StrainDisplacement B;
    StrainVector strain;
    for (int g = 0; g < kGaussPoints; ++g) {
      formStrainDisplacement(g, B);
      strain.noalias() = B * u;
      this->materials_[g]->setTrialStrain(strain);
    }
  }

  void formStiffness(bool initial, NodalMatrix& K) const override {
    K.setZero();
    StrainDisplacement B, DB;
    StrainMatrix D;
    for (int g = 0; g < kGaussPoints; ++g) {
      formStrainDisplacement(g, B);
      D = initial ? this->materials_[g]->initialTangent() : this->materials_[g]->tangent();
      DB.noalias() = D * B;
      K.noalias() += weight(g) * (B.transpose() * DB);
    }
  }

  void formInternalForce(NodalVector& f) const override {
    f.setZero();
    StrainDisplacement B;
    StrainVector stress;
    for (int g = 0; g < kGaussPoints; ++g) {
      formStrainDisplacement(g, B);
      stress = this->materials_[g]->stress();
      f.noalias() += weight(g) * (B.transpose() * stress);
    }
  }
};

}  // namespace beamsolid
