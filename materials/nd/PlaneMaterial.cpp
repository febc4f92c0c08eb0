#include "materials/nd/PlaneMaterial.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

PlaneMaterial::PlaneMaterial(int tag, const NDMaterial& threeDimensional, const std::string& plane)
    : NDMaterial(tag), threeDimensional_(threeDimensional.clone("ThreeDimensional")), plane_(plane) {
  if (!threeDimensional_)
    throw OpenSeesError("nDMaterial " + plane + " " + std::to_string(tag) + ": nDMaterial " +
                        std::to_string(threeDimensional.tag()) + " (" + threeDimensional.className() +
                        ") is not a three-dimensional material");
  form_ = threeDimensional_->clone(plane_);
  if (!form_)
    throw OpenSeesError("nDMaterial " + plane + " " + std::to_string(tag) + ": nDMaterial " +
                        std::to_string(threeDimensional.tag()) + " (" + threeDimensional.className() +
                        ") has no " + plane + " form");
}

PlaneMaterial::PlaneMaterial(const PlaneMaterial& other)
    : NDMaterial(other.tag()),
      threeDimensional_(other.threeDimensional_->clone("ThreeDimensional")),
      plane_(other.plane_),
      form_(threeDimensional_->clone(plane_)) {}

std::unique_ptr<NDMaterial> PlaneMaterial::clone(const std::string& kind) const {
  if (kind != "PlaneStress" && kind != "PlaneStrain") return nullptr;
  return threeDimensional_->clone(plane_);
}

namespace {

std::unique_ptr<NDMaterial> buildPlane(CommandArgs& args, Domain& domain, const std::string& plane) {
  const int tag = args.nextInt("matTag");
  args.setContext("nDMaterial " + plane + " " + std::to_string(tag));
  const int inner = args.nextInt("mat3DTag");
  args.expectEnd();
  const NDMaterial& threeDimensional = domain.ndMaterials.get(inner, args.context());
  return std::make_unique<PlaneMaterial>(tag, threeDimensional, plane);
}

void registerPlaneMaterial(Registry& r) {
  for (const char* plane : {"PlaneStress", "PlaneStrain"})
    r.ndMaterials.add(plane, [plane = std::string(plane)](CommandArgs& args, Domain& domain) {
      return buildPlane(args, domain, plane);
    });
}

}  // namespace

BEAMSOLID_REGISTER(registerPlaneMaterial);

}  // namespace beamsolid
