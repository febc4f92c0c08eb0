#include "sections/PlateSection.h"

#include "core/OpenSeesError.h"

namespace beamsolid {

const PlateSection& PlateSection::of(const BeamSection& section, const std::string& context) {
  const auto* plate = dynamic_cast<const PlateSection*>(&section);
  if (!plate)
    throw OpenSeesError(context + ": " + section.context() +
                        " is a beam section; a shell needs a plate section (ElasticMembranePlateSection)");
  return *plate;
}

const char* const* PlateSection::forceNames() {
  static const char* const names[kOrder] = {"p11", "p22", "p12", "m11", "m22", "m12", "q1", "q2"};
  return names;
}

const char* const* PlateSection::deformationNames() {
  static const char* const names[kOrder] = {"eps11", "eps22", "gamma12", "theta11",
                                            "theta22", "theta12", "gamma13", "gamma23"};
  return names;
}

Response PlateSection::setResponse(const std::vector<std::string>& args) {
  if (args.size() != 1) return {};
  const std::string& name = args[0];
  const bool forces = name == "force" || name == "forces";
  if (!forces && name != "deformation" && name != "deformations") return {};
  const char* const* labels = forces ? forceNames() : deformationNames();
  return Response::named(std::vector<std::string>(labels, labels + kOrder), [this, forces]() -> Vector {
    return forces ? Vector(force()) : Vector(reportedDeformation());
  });
}

PlateSection::Vector8 PlateSection::reportedDeformation() const {
  Vector8 e = deformation();
  e.segment<3>(3) *= -1.0;
  return e;
}

}  // namespace beamsolid
