#include "core/OpenSeesClassName.h"

#include <map>

#include "core/Node.h"
#include "elements/Element.h"

namespace beamsolid {

std::string openSeesClassName(const std::string& elementClassName) {
  static const std::map<std::string, std::string> table = {
      {"elasticBeamColumn", "ElasticBeam3d"},   {"truss", "Truss"},
      {"trussSection", "TrussSection"},
      {"ElasticTimoshenkoBeam", "ElasticTimoshenkoBeam3d"},
      {"corotTruss", "CorotTruss"},             {"zeroLength", "ZeroLength"},
      {"stdBrick", "Brick"},                    {"bbarBrick", "BbarBrick"},
      {"dispBeamColumn", "DispBeamColumn3d"},   {"forceBeamColumn", "ForceBeamColumn3d"},
      {"nonlinearBeamColumn", "ForceBeamColumn3d"}, {"quad", "FourNodeQuad"},
      {"bbarQuad", "ConstantPressureVolumeQuad"}, {"SSPquad", "SSPquad"},
      {"SSPbrick", "SSPbrick"},                 {"tri31", "Tri31"},
      {"twoNodeLink", "TwoNodeLink"},
  };
  const auto it = table.find(elementClassName);
  return it == table.end() ? elementClassName : it->second;
}

std::string openSeesClassName(const Element& element) {
  std::string name = openSeesClassName(element.className());
  const bool planar = !element.nodes().empty() && element.nodes().front() && element.nodes().front()->ndm() == 2;
  if (planar && name.size() > 2 && name.compare(name.size() - 2, 2, "3d") == 0) name.replace(name.size() - 2, 2, "2d");
  return name;
}

}  // namespace beamsolid
