#include "elements/BeamColumnCommand.h"

#include <variant>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

BeamColumnCommand BeamColumnCommand::parse(CommandArgs& args, Domain& domain, const std::string& type,
                                           BeamIntegration::Rule defaultRule, bool forceBased, bool forceCMass) {
  BeamColumnCommand d;
  d.tag = args.nextInt("eleTag");
  args.setContext("element " + type + " " + std::to_string(d.tag));
  d.nodeI = args.nextInt("iNode");
  d.nodeJ = args.nextInt("jNode");

  // The number of numbers up to the first option tells the forms apart.
  std::size_t numbers = 0;
  while (args.position() + numbers < args.size() &&
         !std::holds_alternative<std::string>(args.at(args.position() + numbers)))
    ++numbers;
  int integrationTag = 0;
  int numPoints = 0, sectionTag = 0;
  std::size_t numPointsAt = 0;
  const bool olderForm = numbers == 3;
  if (numbers == 2) {
    d.transfTag = args.nextInt("transfTag");
    integrationTag = args.nextInt("integrationTag");
  } else if (olderForm) {
    numPointsAt = args.position();
    numPoints = args.nextInt("numIntgrPts");
    sectionTag = args.nextInt("secTag");
    d.transfTag = args.nextInt("transfTag");
  } else {
    args.fail("expected transfTag, integrationTag (or numIntgrPts, secTag, transfTag) after the nodes, got " +
              std::to_string(numbers) + " number(s)");
  }

  BeamIntegration::Rule rule = defaultRule;
  while (!args.done()) {
    if (args.nextFlag("-mass")) {
      const std::size_t at = args.position();
      d.options.massPerLength = args.nextDouble("massPerLength");
      if (!(d.options.massPerLength >= 0.0)) args.failAt(at, "massPerLength", "a number >= 0");
    } else if (args.nextFlag("-cMass")) {
      if (forceBased && !forceCMass) args.fail("'-cMass' is not available: " + type + " has a lumped mass only");
      d.options.consistentMass = true;
    } else if (args.nextFlag("-lMass")) {
      // Lumped is the default; OpenSees accepts the flag and '-cMass' wins whatever the order.
    } else if (args.nextFlag("-iter")) {
      if (!forceBased) args.fail("'-iter' is only for force-based elements (forceBeamColumn)");
      std::size_t at = args.position();
      d.options.maxIterations = args.nextInt("maxIter");
      if (d.options.maxIterations < 1) args.failAt(at, "maxIter", "an integer >= 1");
      at = args.position();
      d.options.tolerance = args.nextDouble("tol");
      if (!(d.options.tolerance > 0.0)) args.failAt(at, "tol", "a positive number");
    } else if (args.nextFlag("-integration")) {
      if (!olderForm)
        args.fail("'-integration' belongs to the older form (numIntgrPts, secTag, transfTag); with an "
                  "integrationTag the rule comes from beamIntegration");
      const std::string name = args.nextString("integration rule");
      using Rule = BeamIntegration::Rule;
      bool known = false;
      for (Rule r : {Rule::Lobatto, Rule::Legendre, Rule::Radau, Rule::NewtonCotes})
        if (name == BeamIntegration::ruleName(r)) {
          rule = r;
          known = true;
        }
      if (!known) args.fail("unknown integration rule '" + name + "' (expected Lobatto, Legendre, Radau or NewtonCotes)");
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() + "' (expected '-mass', '-lMass'" +
                (forceBased ? std::string(", '-iter'") : "") + (!forceBased || forceCMass ? ", '-cMass'" : "") +
                (olderForm ? ", '-integration'" : "") + ")");
    } else {
      args.expectEnd();
    }
  }

  if (olderForm) {
    if (numPoints < BeamIntegration::minPoints(rule) || numPoints > BeamIntegration::maxPoints(rule))
      args.failAt(numPointsAt, "numIntgrPts",
                  "a number of points in " + std::to_string(BeamIntegration::minPoints(rule)) + ".." +
                      std::to_string(BeamIntegration::maxPoints(rule)) + " for " + BeamIntegration::ruleName(rule));
    domain.sections.get(sectionTag, args.context());
    d.integration = std::make_shared<BeamIntegration>(0, rule, std::vector<int>(numPoints, sectionTag));
  } else {
    d.integration = domain.beamIntegrations.shared(integrationTag, args.context());
  }
  return d;
}

}  // namespace beamsolid
