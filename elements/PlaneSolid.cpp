#include "elements/PlaneSolid.h"

#include <variant>

#include "core/OpenSeesError.h"
#include "elements/SolidElement.h"

namespace beamsolid::planesolid {

const std::string& checkedType(const std::string& className, int tag, const std::string& type) {
  if (type != "PlaneStrain" && type != "PlaneStress")
    throw OpenSeesError("element " + className + " " + std::to_string(tag) +
                        ": type must be 'PlaneStrain' or 'PlaneStress', got '" + type + "'");
  return type;
}

template <int N>
Command<N> parse(CommandArgs& args, Domain& domain, const std::string& className, bool allOrNone) {
  Command<N> c;
  c.tag = args.nextInt("eleTag");
  args.setContext("element " + className + " " + std::to_string(c.tag));
  solidargs::requireSpace(args, domain, 2, className);
  // The nodes and thick are the numbers before the type string.
  std::size_t numbers = 0;
  while (args.position() + numbers < args.size() &&
         !std::holds_alternative<std::string>(args.at(args.position() + numbers)))
    ++numbers;
  if (numbers != N + 1)
    args.fail("expected " + std::to_string(N) + " node tags and thick before the type ('PlaneStrain' or " +
              "'PlaneStress'), got " + std::to_string(numbers) + " numbers (" + className + " has exactly " +
              std::to_string(N) + " nodes)");
  c.nodes = solidargs::nodeTags<N>(args);
  PlaneSolidProperties& p = c.properties;
  p.thickness = solidargs::thickness(args);
  p.type = solidargs::planeType(args);
  c.material = &solidargs::material(args, domain, p.type, "a " + className);
  const std::vector<double> extra = args.nextDoubles("pressure rho b1 b2");
  if (extra.size() > 4)
    args.fail("expected at most 4 optional numbers after matTag (pressure, rho, b1, b2), got " +
              std::to_string(extra.size()));
  if (allOrNone && !extra.empty() && extra.size() != 4)
    args.fail("expected all 4 optional numbers after matTag (pressure, rho, b1, b2) or none, got " +
              std::to_string(extra.size()) + " (OpenSees' " + className + " ignores a partial list)");
  args.expectEnd();
  if (extra.size() > 0) p.pressure = extra[0];
  if (extra.size() > 1) p.rho = extra[1];
  if (extra.size() > 2) p.bodyForce.x() = extra[2];
  if (extra.size() > 3) p.bodyForce.y() = extra[3];
  return c;
}

template Command<3> parse<3>(CommandArgs&, Domain&, const std::string&, bool);
template Command<4> parse<4>(CommandArgs&, Domain&, const std::string&, bool);

}  // namespace beamsolid::planesolid
