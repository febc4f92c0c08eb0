#pragma once
#include <string>

namespace beamsolid {

// OpenSees' C++ class name for a BeamSolid element command name, which is
// what OpenSees reports in eleType and in XML recorder headers
// ("elasticBeamColumn" -> "ElasticBeam3d", "stdBrick" -> "Brick", ...;
// checked against OpenSeesPy 3.7.1). Other names come back unchanged.
std::string openSeesClassName(const std::string& elementClassName);
// The same for an element in its model: OpenSees' beam-column classes are
// "...2d" in a 2D model ("ElasticBeam2d", "ForceBeamColumn2d").
class Element;
std::string openSeesClassName(const Element& element);

}  // namespace beamsolid
