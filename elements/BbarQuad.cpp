#include "elements/BbarQuad.h"

#include "core/Registry.h"

namespace beamsolid {

namespace {
// The [11 22 33 12] components of a 3D Voigt vector [11 22 33 12 23 13].
Vector axiSymmetricPart(const Vector& v, int points) {
  Vector out(4 * points);
  for (int p = 0; p < points; ++p) out.segment<4>(4 * p) = v.segment<4>(6 * p);
  return out;
}
}  // namespace

BbarQuad::BbarQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, double thickness)
    : GaussPointSolid(tag, nodeTags, material, "ThreeDimensional", thickness, Eigen::Vector2d::Zero()) {}

void BbarQuad::formStrainDisplacement(int g, StrainDisplacement& B) const {
  B.setZero();  // rows 23 and 13 stay zero
  const Cell::ShapeGradients& d = cell().gradients(g);
  const Cell::ShapeGradients& mean = cell().meanGradients();
  for (int a = 0; a < kNodes; ++a) {
    for (int i = 0; i < 2; ++i) {
      const double shift = (mean(a, i) - d(a, i)) / 3.0;
      for (int row = 0; row < 3; ++row) B(row, 2 * a + i) = shift;
      B(i, 2 * a + i) += d(a, i);
    }
    B(3, 2 * a) = d(a, 1);  // gamma_12
    B(3, 2 * a + 1) = d(a, 0);
  }
}

Response BbarQuad::setResponse(const std::vector<std::string>& args) {
  // Stresses and strains as OpenSees' AxiSymmetric material form gives them: [11 22 33 12].
  auto isStress = [](const std::string& s) { return s == "stress" || s == "stresses"; };
  auto isStrain = [](const std::string& s) { return s == "strain" || s == "strains"; };
  const std::vector<std::string> stressNames = {"sigma11", "sigma22", "sigma33", "sigma12"};
  const std::vector<std::string> strainNames = {"eta11", "eta22", "eta33", "eta12"};
  if (!args.empty() && (isStress(args[0]) || isStrain(args[0]))) {
    Response full = GaussPointSolid::setResponse(args);
    std::vector<std::string> names;
    for (int p = 0; p < kGaussPoints; ++p)
      for (const std::string& n : isStress(args[0]) ? stressNames : strainNames) names.push_back(n);
    return {names, [full] { return axiSymmetricPart(full.value(), kGaussPoints); }};
  }
  if (args.size() == 3 && (args[0] == "material" || args[0] == "integrPoint") && (isStress(args[2]) || isStrain(args[2]))) {
    Response full = GaussPointSolid::setResponse(args);
    if (!full) return full;
    return {isStress(args[2]) ? stressNames : strainNames, [full] { return axiSymmetricPart(full.value(), 1); }};
  }
  return GaussPointSolid::setResponse(args);
}

namespace {

std::unique_ptr<Element> buildBbarQuad(CommandArgs& args, Domain& domain) {
  const auto [tag, nodeTags] = solidargs::quadTagAndNodes(args, domain, "bbarQuad");
  const double thickness = solidargs::thickness(args);
  const NDMaterial& material = solidargs::material(args, domain, "ThreeDimensional", "bbarQuad (used with e23 = e13 = 0)");
  if (!args.done())
    args.fail("bbarQuad takes no arguments after matTag (element('bbarQuad', tag, *4 nodes, thick, matTag)); got " +
              std::to_string(args.remaining()) + " more");
  return std::make_unique<BbarQuad>(tag, nodeTags, material, thickness);
}

void registerBbarQuad(Registry& r) { r.elements.add("bbarQuad", &buildBbarQuad); }

}  // namespace

BEAMSOLID_REGISTER(registerBbarQuad);

}  // namespace beamsolid
