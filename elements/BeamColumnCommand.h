#pragma once
#include <memory>
#include <string>

#include "sections/BeamIntegration.h"

namespace beamsolid {

class CommandArgs;
class Domain;

// Options of the distributed-plasticity beam-column commands.
struct BeamColumnOptions {
  double massPerLength = 0.0;
  bool consistentMass = false;
  // Element compatibility iterations (force-based only).
  int maxIterations = 10;
  double tolerance = 1e-12;
};

// The arguments of forceBeamColumn, nonlinearBeamColumn and dispBeamColumn
// that do not depend on the space: after the type name,
//   tag, iNode, jNode, transfTag, integrationTag, <options>            or
//   tag, iNode, jNode, numIntgrPts, secTag, transfTag, <options>       (older form)
// with options '-mass', m, '-cMass' (when allowed), '-iter', maxIter, tol
// (when allowed) and, for the older form, '-integration', rule. The 2D and
// 3D elements then take their own kind of sections and transformation.
struct BeamColumnCommand {
  int tag = 0, nodeI = 0, nodeJ = 0, transfTag = 0;
  std::shared_ptr<const BeamIntegration> integration;
  BeamColumnOptions options;

  // forceCMass: whether a force-based element takes '-cMass'.
  static BeamColumnCommand parse(CommandArgs& args, Domain& domain, const std::string& type,
                                 BeamIntegration::Rule defaultRule, bool forceBased, bool forceCMass);
};

}  // namespace beamsolid
