#include "sections/UniaxialSection3d.h"

#include <array>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "sections/UniaxialSection2d.h"

namespace beamsolid {

namespace {

std::array<std::unique_ptr<UniaxialMaterial>, 4> inComponent(std::unique_ptr<UniaxialMaterial> material,
                                                             SectionCode code) {
  std::array<std::unique_ptr<UniaxialMaterial>, 4> materials;
  const int c = SectionAggregator3d::componentOf(code);
  if (c < 0) throw OpenSeesError("section Uniaxial: shear components have no 3D section here");
  materials[c] = std::move(material);
  return materials;
}

}  // namespace

UniaxialSection3d::UniaxialSection3d(int tag, std::unique_ptr<UniaxialMaterial> material, SectionCode code)
    : SectionAggregator3d(tag, nullptr, inComponent(std::move(material), code)),
      code_(code),
      component_(componentOf(code)) {}

std::unique_ptr<SectionForceDeformation> UniaxialSection3d::clone() const {
  return std::make_unique<UniaxialSection3d>(*this);
}

Response UniaxialSection3d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  const std::string force = sectionCodeName(code_);
  const std::string deformation = sectionDeformationName(code_);
  const int c = component_;
  if (what == "force" || what == "forces")
    return Response::named({force}, [this, c] { return Vector::Constant(1, this->force()[c]); });
  if (what == "deformation" || what == "deformations")
    return Response::named({deformation}, [this, c] { return Vector::Constant(1, this->deformation()[c]); });
  if (what == "forceAndDeformation" || what == "forceDeformation")
    return Response::named({deformation, force}, [this, c] {
      Vector out(2);
      out << this->deformation()[c], this->force()[c];
      return out;
    });
  if (what == "stiffness" || what == "tangent")
    return Response::named({"d" + force + "_d" + deformation},
                           [this, c] { return Vector::Constant(1, tangent()(c, c)); });
  return {};
}

namespace {

std::unique_ptr<BeamSection> buildUniaxialSection(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section Uniaxial " + std::to_string(tag));
  const int matTag = args.nextInt("matTag");
  const std::size_t at = args.position();
  const std::string name = args.nextString("quantity");
  args.expectEnd();
  const auto code = parseSectionCode(name);
  if (domain.spaceDim() == 2) {
    if (!code || (*code != SectionCode::P && *code != SectionCode::Mz && *code != SectionCode::Vy))
      args.failAt(at, "quantity", "one of P, Mz, Vy in a 2D model, got '" + name + "'");
    return std::make_unique<UniaxialSection2d>(tag, domain.uniaxialMaterials.get(matTag, args.context()).clone(),
                                               *code);
  }
  if (domain.spaceDim() != 3) args.fail("Uniaxial needs a 2D or 3D model (-ndm 2 or 3)");
  if (!code) args.failAt(at, "quantity", "one of P, Mz, My, T in a 3D model, got '" + name + "'");
  if (SectionAggregator3d::componentOf(*code) < 0)
    args.failAt(at, "quantity", "one of P, Mz, My, T: shear ('" + name + "') is not supported in 3D sections");
  return std::make_unique<UniaxialSection3d>(tag, domain.uniaxialMaterials.get(matTag, args.context()).clone(),
                                             *code);
}

void registerUniaxialSection(Registry& r) { r.sections.add("Uniaxial", &buildUniaxialSection); }

}  // namespace

BEAMSOLID_REGISTER(registerUniaxialSection);

}  // namespace beamsolid
