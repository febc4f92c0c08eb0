#include "elements/ElasticTimoshenkoBeam2d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/ElasticTimoshenkoBeam3d.h"
#include "elements/ElasticTimoshenkoBeamArgs.h"
#include "elements/transforms/LinearCrdTransf2d.h"

namespace beamsolid {

namespace {

using namespace timoshenko_args;

std::unique_ptr<Element> buildTimoshenko(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element ElasticTimoshenkoBeam " + std::to_string(tag));
  const int nodeI = args.nextInt("iNode");
  const int nodeJ = args.nextInt("jNode");
  if (domain.spaceDim() == 2) return ElasticTimoshenkoBeam2d::build(args, domain, tag, nodeI, nodeJ);
  if (domain.spaceDim() == 3) return ElasticTimoshenkoBeam3d::build(args, domain, tag, nodeI, nodeJ);
  args.fail("ElasticTimoshenkoBeam needs a 2D or 3D model (-ndm 2 or 3)");
}

void registerElasticTimoshenkoBeam(Registry& r) { r.elements.add("ElasticTimoshenkoBeam", &buildTimoshenko); }

}  // namespace

std::unique_ptr<Element> ElasticTimoshenkoBeam2d::build(CommandArgs& args, Domain& domain, int tag, int nodeI,
                                                        int nodeJ) {
  const std::size_t numbers = numbersAhead(args);
  if (numbers != 6)
    args.fail("expected E, G, A, Iz, Avy, transfTag (6 numbers) after the nodes in a 2D model, got " +
              std::to_string(numbers) + (numbers == 9 ? " (the 3D form needs -ndm 3)" : ""));
  Properties p;
  readPositive(args, {{&p.E, "E"}, {&p.G, "G"}, {&p.A, "A"}, {&p.Iz, "Iz"}, {&p.Avy, "Avy"}});
  const int transfTag = args.nextInt("transfTag");
  readMassOptions(args, p.massPerLength, p.consistentMass);
  const CrdTransf& definition = domain.geomTransfs.get(transfTag, args.context());
  if (!definition.planar())
    args.fail("geomTransf " + definition.className() + " " + std::to_string(transfTag) + " has no 2D form");
  auto transf = std::make_unique<LinearCrdTransf2d>(transfTag, offsetOf(definition, false).head<2>(),
                                                    offsetOf(definition, true).head<2>());
  return std::make_unique<ElasticTimoshenkoBeam2d>(tag, nodeI, nodeJ, p, std::move(transf));
}

BEAMSOLID_REGISTER(registerElasticTimoshenkoBeam);

}  // namespace beamsolid
