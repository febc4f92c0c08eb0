#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

Response UniaxialMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "stress") return {{"stress"}, [this] { return Vector::Constant(1, stress()); }};
  if (what == "strain") return {{"strain"}, [this] { return Vector::Constant(1, strain()); }};
  if (what == "tangent") return {{"tangent"}, [this] { return Vector::Constant(1, tangent()); }};
  if (what == "stressStrain" || what == "stressANDstrain")
    return {{"stress", "strain"}, [this] {
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
