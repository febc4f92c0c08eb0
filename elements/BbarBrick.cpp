#include "elements/BbarBrick.h"

#include "core/Registry.h"

namespace beamsolid {

void BbarBrick::formStrainDisplacement(int g, StrainDisplacement& B) const {
  StdBrick::formStrainDisplacement(g, B);
  const Cell::ShapeGradients& d = cell().gradients(g);
  const Cell::ShapeGradients& mean = cell().meanGradients();
  for (int a = 0; a < kNodes; ++a)
    for (int i = 0; i < 3; ++i) {
      // The dilatation of dof (a, i) is d(a, i) at the point and mean(a, i) on average.
      const double shift = (mean(a, i) - d(a, i)) / 3.0;
      for (int row = 0; row < 3; ++row) B(row, 3 * a + i) += shift;
    }
}

namespace {
void registerBbarBrick(Registry& r) {
  r.elements.add("bbarBrick", [](CommandArgs& a, Domain& d) { return solidargs::brick<BbarBrick>(a, d, "bbarBrick"); });
}
}  // namespace

BEAMSOLID_REGISTER(registerBbarBrick);

}  // namespace beamsolid
