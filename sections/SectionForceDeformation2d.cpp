#include "sections/SectionForceDeformation2d.h"

#include "core/OpenSeesError.h"

namespace beamsolid {

const SectionForceDeformation2d& SectionForceDeformation2d::of(const BeamSection& section,
                                                               const std::string& context) {
  const auto* s = dynamic_cast<const SectionForceDeformation2d*>(&section);
  if (!s)
    throw OpenSeesError(context + ": " + section.context() + " is a " + std::to_string(section.ndm()) +
                        "D section; a 2D element needs a section made in a 2D model (-ndm 2)");
  return *s;
}

SectionForceDeformation2d::Vector SectionForceDeformation2d::forceSensitivity(int, int) {
  throw OpenSeesError(context() + " does not compute sensitivities (sensitivityAlgorithm)");
}

void SectionForceDeformation2d::commitSensitivity(const Vector&, int gradient, int parameterId, int) {
  forceSensitivity(gradient, parameterId);
}

Response SectionForceDeformation2d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  std::vector<std::string> forces, deformations;
  for (SectionCode c : codes()) {
    forces.push_back(sectionCodeName(c));
    deformations.push_back(sectionDeformationName(c));
  }
  if (what == "force" || what == "forces")
    return Response::named(forces, [this] { return beamsolid::Vector(force()); });
  if (what == "deformation" || what == "deformations")
    return Response::named(deformations, [this] { return beamsolid::Vector(deformation()); });
  if (what == "forceAndDeformation" || what == "forceDeformation") {
    std::vector<std::string> names = deformations;
    names.insert(names.end(), forces.begin(), forces.end());
    return Response::named(std::move(names), [this] {
      const int n = order();
      beamsolid::Vector out(2 * n);
      out << deformation(), force();
      return out;
    });
  }
  if (what == "stiffness" || what == "tangent") {
    std::vector<std::string> names;
    for (const auto& row : forces)
      for (const auto& col : deformations) names.push_back("d" + row + "_d" + col);
    return Response::named(std::move(names), [this] {
      const int n = order();
      beamsolid::Vector out(n * n);
      const Matrix& k = tangent();
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) out[n * r + c] = k(r, c);
      return out;
    });
  }
  return {};
}

}  // namespace beamsolid
