#include "elements/FourNodeTetrahedron.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/SmallStrain.h"

namespace beamsolid {

FourNodeTetrahedron::FourNodeTetrahedron(int tag, const std::array<int, kNodes>& nodeTags,
                                         const NDMaterial& material, const Vector3& bodyForce)
    : GaussPointSolid(tag, nodeTags, material, "ThreeDimensional", 1.0, bodyForce) {}

void FourNodeTetrahedron::formStrainDisplacement(int g, StrainDisplacement& B) const {
  smallstrain::strainDisplacement(cell().gradients(g), B);
}

namespace {

void registerFourNodeTetrahedron(Registry& r) {
  r.elements.add("FourNodeTetrahedron", [](CommandArgs& a, Domain& d) {
    return solidargs::solid<FourNodeTetrahedron, 4>(a, d, "FourNodeTetrahedron");
  });
}

}  // namespace

BEAMSOLID_REGISTER(registerFourNodeTetrahedron);

}  // namespace beamsolid
