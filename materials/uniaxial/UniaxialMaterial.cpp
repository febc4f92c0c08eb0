#include "materials/uniaxial/UniaxialMaterial.h"

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

void UniaxialMaterial::print(std::ostream& os) const {
  os << "UniaxialMaterial " << tag_ << " type " << className() << '\n';
}

}  // namespace beamsolid
