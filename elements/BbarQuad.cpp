#include "elements/BbarQuad.h"

#include "core/Registry.h"

namespace beamsolid {

BbarQuad::BbarQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, double thickness)
    : GaussPointSolid(tag, nodeTags, material, "AxiSymmetric", thickness, Eigen::Vector2d::Zero()) {}

void BbarQuad::formStrainDisplacement(int g, StrainDisplacement& B) const {
  B.setZero();
  const Cell::ShapeGradients& d = cell().gradients(g);
  for (int a = 0; a < kNodes; ++a) {
    for (int i = 0; i < 2; ++i) {
      const double shift = (meanGradients_(a, i) - d(a, i)) / 3.0;
      for (int row = 0; row < 3; ++row) B(row, 2 * a + i) = shift;
      B(i, 2 * a + i) += d(a, i);
    }
    B(3, 2 * a) = d(a, 1);  // gamma_12
    B(3, 2 * a + 1) = d(a, 0);
  }
}

namespace {

std::unique_ptr<Element> buildBbarQuad(CommandArgs& args, Domain& domain) {
  const auto [tag, nodeTags] = solidargs::quadTagAndNodes(args, domain, "bbarQuad");
  const double thickness = solidargs::thickness(args);
  const NDMaterial& material =
      solidargs::material(args, domain, "AxiSymmetric", "bbarQuad (nor a ThreeDimensional one to use with e23 = e13 = 0)");
  if (!args.done())
    args.fail("bbarQuad takes no arguments after matTag (element('bbarQuad', tag, *4 nodes, thick, matTag)); got " +
              std::to_string(args.remaining()) + " more");
  return std::make_unique<BbarQuad>(tag, nodeTags, material, thickness);
}

void registerBbarQuad(Registry& r) { r.elements.add("bbarQuad", &buildBbarQuad); }

}  // namespace

BEAMSOLID_REGISTER(registerBbarQuad);

}  // namespace beamsolid
