#include "elements/FourNodeQuad.h"

#include <variant>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/SmallStrain.h"

namespace beamsolid {

namespace {
const std::string& planeType(int tag, const std::string& type) {
  if (type != "PlaneStrain" && type != "PlaneStress")
    throw OpenSeesError("element quad " + std::to_string(tag) + ": type must be 'PlaneStrain' or 'PlaneStress', got '" +
                        type + "'");
  return type;
}
}  // namespace

FourNodeQuad::FourNodeQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                           const Properties& properties)
    : GaussPointSolid(tag, nodeTags, material, planeType(tag, properties.type), properties.thickness,
                      properties.bodyForce),
      properties_(properties) {}

void FourNodeQuad::prepare() {
  // Pressure: edge a -> a+1 with chord d takes p (dy, -dx), half per end.
  const Cell::NodeCoordinates& X = cell().nodeCoordinates();
  pressureLoad_.setZero();
  for (int a = 0; a < kNodes; ++a) {
    const int b = (a + 1) % kNodes;
    const Eigen::Vector2d d = X.row(b).transpose() - X.row(a).transpose();
    const Eigen::Vector2d half = 0.5 * properties_.pressure * Eigen::Vector2d(d.y(), -d.x());
    pressureLoad_.segment<2>(2 * a) += half;
    pressureLoad_.segment<2>(2 * b) += half;
  }
}

double FourNodeQuad::density() const {
  return properties_.rho != 0.0 ? properties_.rho : materials_[0]->density();
}

void FourNodeQuad::formStrainDisplacement(int g, StrainDisplacement& B) const {
  smallstrain::strainDisplacement(cell().gradients(g), B);
}

FourNodeQuad::NodalVector FourNodeQuad::appliedLoad() const {
  return GaussPointSolid::appliedLoad() + pressureLoad_;
}

namespace {

std::unique_ptr<Element> buildFourNodeQuad(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element quad " + std::to_string(tag));
  solidargs::requireSpace(args, domain, 2, "quad");
  // The nodes and thick are the numbers before the type string.
  std::size_t numbers = 0;
  while (args.position() + numbers < args.size() &&
         !std::holds_alternative<std::string>(args.at(args.position() + numbers)))
    ++numbers;
  if (numbers != FourNodeQuad::kNodes + 1)
    args.fail("expected 4 node tags and thick before the type ('PlaneStrain' or 'PlaneStress'), got " +
              std::to_string(numbers) + " numbers (quad has exactly 4 nodes)");
  const auto nodeTags = solidargs::nodeTags<4>(args);
  FourNodeQuad::Properties p;
  p.thickness = solidargs::thickness(args);
  p.type = solidargs::planeType(args);
  const NDMaterial& material = solidargs::material(args, domain, p.type, "a quad");
  const std::vector<double> extra = args.nextDoubles("pressure rho b1 b2");
  if (extra.size() > 4)
    args.fail("expected at most 4 optional numbers after matTag (pressure, rho, b1, b2), got " +
              std::to_string(extra.size()));
  args.expectEnd();
  if (extra.size() > 0) p.pressure = extra[0];
  if (extra.size() > 1) p.rho = extra[1];
  if (extra.size() > 2) p.bodyForce.x() = extra[2];
  if (extra.size() > 3) p.bodyForce.y() = extra[3];
  return std::make_unique<FourNodeQuad>(tag, nodeTags, material, p);
}

void registerFourNodeQuad(Registry& r) { r.elements.add("quad", &buildFourNodeQuad); }

}  // namespace

BEAMSOLID_REGISTER(registerFourNodeQuad);

}  // namespace beamsolid
