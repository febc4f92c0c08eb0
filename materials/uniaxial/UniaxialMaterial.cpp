#include "materials/uniaxial/UniaxialMaterial.h"

#include "core/OpenSeesError.h"

namespace beamsolid {

Response UniaxialMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  // Component names as OpenSees writes them in XML recorder headers.
  if (what == "stress") return {{"sigma11"}, [this] { return Vector::Constant(1, stress()); }};
  if (what == "strain") return {{"eps11"}, [this] { return Vector::Constant(1, strain()); }};
  if (what == "tangent") return {{"C11"}, [this] { return Vector::Constant(1, tangent()); }};
  if (what == "stressStrain" || what == "stressANDstrain")
    return {{"sig11", "eps11"}, [this] {
              Vector v(2);
              v << stress(), strain();
              return v;
            }};
  return {};
}

double UniaxialMaterial::stressSensitivity(int, int parameterId) {
  if (isLinear() && parameterId == 0) return 0.0;
  throw OpenSeesError("uniaxialMaterial " + className() + " " + std::to_string(tag_) +
                      " does not compute sensitivities (sensitivityAlgorithm)");
}

void UniaxialMaterial::commitSensitivity(double, int gradient, int parameterId, int) {
  stressSensitivity(gradient, parameterId);  // the same refusal for materials with history
}

void UniaxialMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag_ << " type " << className() << '\n';
}

}  // namespace beamsolid
