#pragma once
#include <string>

#include "elements/GaussPointSolid.h"
#include "elements/PlaneSolid.h"
#include "elements/SmallStrain.h"

namespace beamsolid {

// A plane solid with a thickness integrated on its cell's Gauss rule, one
// copy of the ND material in its PlaneStrain or PlaneStress form per point
// (strain [e11, e22, g12], stress [s11, s22, s12]), with the loads and mass
// of PlaneSolidProperties: quad (the bilinear quadrilateral, 2x2 points)
// and tri31 (the linear triangle, one point).
template <class CellType>
class PlaneGaussSolid : public GaussPointSolid<2, 3, CellType> {
 public:
  using Base = GaussPointSolid<2, 3, CellType>;
  using typename Base::NodalVector;
  using typename Base::StrainDisplacement;
  using Properties = PlaneSolidProperties;

  // `command` names the element in messages ("quad", "tri31").
  PlaneGaussSolid(int tag, const std::array<int, CellType::kNodes>& nodeTags, const NDMaterial& material,
                  const Properties& properties, const std::string& command)
      : Base(tag, nodeTags, material, planesolid::checkedType(command, tag, properties.type), properties.thickness,
             properties.bodyForce),
        properties_(properties) {}

  const Properties& properties() const { return properties_; }
  double area() const { return this->volume(); }
  // Mass density in use: the element's rho, else the material's.
  double density() const override { return properties_.density(*this->materials_[0]); }
  // Body force and pressure: the nodal forces resistingForce() subtracts.
  NodalVector appliedLoad() const override { return Base::appliedLoad() + pressureLoad_; }

 protected:
  void prepare() override {
    pressureLoad_ = planesolid::pressureLoad<CellType::kNodes>(this->cell().nodeCoordinates(), properties_.pressure);
  }
  void formStrainDisplacement(int g, StrainDisplacement& B) const override {
    smallstrain::strainDisplacement(this->cell().gradients(g), B);
  }
  typename Base::MassKind massKind() const override { return Base::MassKind::RowSum; }

 private:
  Properties properties_;
  NodalVector pressureLoad_ = NodalVector::Zero();
};

}  // namespace beamsolid
