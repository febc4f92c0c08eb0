#include "materials/nd/NDMaterial.h"

namespace beamsolid {

Response NDMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "stress" || what == "stresses")
    return {Response::numberedNames("sigma", static_cast<int>(stress().size())),
            [this] { return Vector(stress()); }};
  if (what == "strain" || what == "strains")
    return {Response::numberedNames("eps", static_cast<int>(strain().size())),
            [this] { return Vector(strain()); }};
  if (what == "tangent") {
    const int n = static_cast<int>(tangent().size());
    return {Response::numberedNames("D", n), [this] {
              Matrix d = tangent();
              return Vector(Eigen::Map<Vector>(d.data(), d.size()));
            }};
  }
  return {};
}

void NDMaterial::print(std::ostream& os) const {
  os << "NDMaterial " << tag_ << " type " << className() << '\n';
}

}  // namespace beamsolid
