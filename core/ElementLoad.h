#pragma once
#include <string>
#include <vector>

namespace beamsolid {

// An element load of a load pattern (eleLoad), scaled by the pattern's factor.
struct ElementLoad {
  enum class Type { BeamUniform, BeamPoint, SelfWeight };
  Type type = Type::BeamUniform;
  // BeamUniform: {Wy, Wz, Wx}; BeamPoint: {Py, Pz, xL, Px}; SelfWeight: {bx, by, bz}.
  std::vector<double> values;

  static const char* typeName(Type t) {
    switch (t) {
      case Type::BeamUniform: return "-beamUniform";
      case Type::BeamPoint: return "-beamPoint";
      case Type::SelfWeight: return "-selfWeight";
    }
    return "?";
  }
};

}  // namespace beamsolid
