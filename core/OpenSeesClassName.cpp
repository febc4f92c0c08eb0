#include "core/OpenSeesClassName.h"

#include <map>

namespace beamsolid {

std::string openSeesClassName(const std::string& elementClassName) {
  static const std::map<std::string, std::string> table = {
      {"elasticBeamColumn", "ElasticBeam3d"},   {"truss", "Truss"},
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

}  // namespace beamsolid
