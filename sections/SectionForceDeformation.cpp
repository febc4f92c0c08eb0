#include "sections/SectionForceDeformation.h"

#include "core/OpenSeesError.h"
#include "sections/PlateSection.h"

namespace beamsolid {

const SectionForceDeformation& SectionForceDeformation::of(const BeamSection& section, const std::string& context) {
  const auto* s = dynamic_cast<const SectionForceDeformation*>(&section);
  if (!s && dynamic_cast<const PlateSection*>(&section))
    throw OpenSeesError(context + ": " + section.context() + " is a plate section (for shells); a beam needs a beam section");
  if (!s)
    throw OpenSeesError(context + ": " + section.context() + " is a " + std::to_string(section.ndm()) +
                        "D section; a 3D element needs a section made in a 3D model (-ndm 3)");
  return *s;
}

Response SectionForceDeformation::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "force" || what == "forces")
    return Response::named({"P", "Mz", "My", "T"}, [this] { return Vector(force()); });
  if (what == "deformation" || what == "deformations")
    return Response::named({"eps", "kappaZ", "kappaY", "theta"}, [this] { return Vector(deformation()); });
  if (what == "forceAndDeformation" || what == "forceDeformation")
    return Response::named({"eps", "kappaZ", "kappaY", "theta", "P", "Mz", "My", "T"}, [this] {
      Vector out(8);
      out << deformation(), force();
      return out;
    });
  if (what == "stiffness" || what == "tangent") {
    static const char* const names[4] = {"P", "Mz", "My", "T"};
    static const char* const deformations[4] = {"eps", "kappaZ", "kappaY", "theta"};
    std::vector<std::string> componentNames;
    for (const char* row : names)
      for (const char* col : deformations) componentNames.push_back(std::string("d") + row + "_d" + col);
    return Response::named(std::move(componentNames), [this] {
      Vector out(16);
      const Matrix4& k = tangent();
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[4 * r + c] = k(r, c);
      return out;
    });
  }
  return {};
}


}  // namespace beamsolid
