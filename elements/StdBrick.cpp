#include "elements/StdBrick.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/SmallStrain.h"

namespace beamsolid {

StdBrick::StdBrick(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                   const Vector3& bodyForce)
    : GaussPointSolid(tag, nodeTags, material, "ThreeDimensional", 1.0, bodyForce) {}

void StdBrick::formStrainDisplacement(int g, StrainDisplacement& B) const {
  smallstrain::strainDisplacement(cell().gradients(g), B);
}

namespace {

void registerStdBrick(Registry& r) {
  r.elements.add("stdBrick", [](CommandArgs& a, Domain& d) { return solidargs::brick<StdBrick>(a, d, "stdBrick"); });
}

}  // namespace

BEAMSOLID_REGISTER(registerStdBrick);

}  // namespace beamsolid
