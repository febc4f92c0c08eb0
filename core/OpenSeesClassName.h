#pragma once
#include <string>

namespace beamsolid {

// OpenSees' C++ class name for a BeamSolid element command name, which is
// what OpenSees reports in eleType and in XML recorder headers
// ("elasticBeamColumn" -> "ElasticBeam3d", "stdBrick" -> "Brick", ...;
// checked against OpenSeesPy 3.7.1). Other names come back unchanged.
std::string openSeesClassName(const std::string& elementClassName);

}  // namespace beamsolid
