#pragma once
// Argument reading shared by the 2D and 3D ElasticTimoshenkoBeam commands.
#include <initializer_list>
#include <string>
#include <utility>

#include "core/CommandArgs.h"
#include "elements/transforms/CorotationalCrdTransf.h"
#include "elements/transforms/LinearCrdTransf.h"

namespace beamsolid::timoshenko_args {

// The geomTransf's joint offsets on a small-displacement transformation: the element is linear.
inline Vector3 offsetOf(const CrdTransf& t, bool jEnd) {
  if (const auto* linear = dynamic_cast<const LinearCrdTransf*>(&t))
    return jEnd ? linear->jointOffsetJ() : linear->jointOffsetI();
  if (const auto* corotational = dynamic_cast<const CorotationalCrdTransf*>(&t))
    return jEnd ? corotational->jointOffsetJ() : corotational->jointOffsetI();
  return Vector3::Zero();
}

inline void readMassOptions(CommandArgs& args, double& massPerLength, bool& consistent) {
  while (!args.done()) {
    if (args.nextFlag("-mass")) {
      const std::size_t at = args.position();
      massPerLength = args.nextDouble("massPerLength");
      if (massPerLength < 0.0) args.failAt(at, "massPerLength", "a number >= 0");
    } else if (args.nextFlag("-cMass")) {
      consistent = true;
    } else if (args.nextFlag("-lMass")) {
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() + "' (expected '-mass', '-cMass' or '-lMass')");
    } else {
      args.expectEnd();
    }
  }
}

inline void readPositive(CommandArgs& args, std::initializer_list<std::pair<double*, const char*>> items) {
  for (const auto& [value, name] : items) {
    const std::size_t at = args.position();
    *value = args.nextDouble(name);
    if (!(*value > 0.0)) args.failAt(at, name, "a positive number");
  }
}

inline std::size_t numbersAhead(const CommandArgs& args) {
  std::size_t n = 0;
  while (args.position() + n < args.size() && !std::holds_alternative<std::string>(args.at(args.position() + n))) ++n;
  return n;
}

}  // namespace beamsolid::timoshenko_args
