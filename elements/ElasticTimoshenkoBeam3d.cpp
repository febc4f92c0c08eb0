#include "elements/ElasticTimoshenkoBeam3d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "elements/ElasticTimoshenkoBeamArgs.h"

namespace beamsolid {

using namespace timoshenko_args;

std::unique_ptr<Element> ElasticTimoshenkoBeam3d::build(CommandArgs& args, Domain& domain, int tag, int nodeI,
                                                        int nodeJ) {
  const std::size_t numbers = numbersAhead(args);
  if (numbers != 9)
    args.fail("expected E, G, A, Jx, Iy, Iz, Avy, Avz, transfTag (9 numbers) after the nodes in a 3D model, got " +
              std::to_string(numbers) + (numbers == 6 ? " (the 2D form needs -ndm 2)" : ""));
  Properties p;
  readPositive(args, {{&p.E, "E"}, {&p.G, "G"}, {&p.A, "A"}, {&p.J, "Jx"}, {&p.Iy, "Iy"}, {&p.Iz, "Iz"},
                      {&p.Avy, "Avy"}, {&p.Avz, "Avz"}});
  const int transfTag = args.nextInt("transfTag");
  readMassOptions(args, p.massPerLength, p.consistentMass);
  p.torsionalInertia = p.consistentMass;  // OpenSeesPy 3.7.1: m J / A in the consistent mass only
  const CrdTransf& definition = domain.geomTransfs.get(transfTag, args.context());
  auto transf = std::make_unique<LinearCrdTransf>(transfTag, definition.vecxz(), offsetOf(definition, false),
                                                  offsetOf(definition, true));
  return std::make_unique<ElasticTimoshenkoBeam3d>(tag, nodeI, nodeJ, p, std::move(transf));
}

}  // namespace beamsolid
