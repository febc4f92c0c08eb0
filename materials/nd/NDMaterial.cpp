#include "materials/nd/NDMaterial.h"

namespace beamsolid {

namespace {
// Voigt component names as OpenSees writes them for a 3D material (11, 22,
// 33, 12, 23, 13); other sizes are numbered.
std::vector<std::string> componentNames(const std::string& prefix, int size) {
  if (size != 6) return Response::numberedNames(prefix, size);
  std::vector<std::string> names;
  for (const char* ij : {"11", "22", "33", "12", "23", "13"}) names.push_back(prefix + ij);
  return names;
}
}  // namespace

Response NDMaterial::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "stress" || what == "stresses")
    return {componentNames("sigma", static_cast<int>(stress().size())), [this] { return Vector(stress()); }};
  if (what == "strain" || what == "strains")
    return {componentNames("eps", static_cast<int>(strain().size())), [this] { return Vector(strain()); }};
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
