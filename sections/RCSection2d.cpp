#include "sections/RCSection2d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

RCSection2d::RCSection2d(int tag, const UniaxialMaterial& core, const UniaxialMaterial& cover,
                         const UniaxialMaterial& steel, const Definition& r)
    : FiberSection2d(tag), definition_(r) {
  const double coreHalf = 0.5 * r.d - r.cover;  // the bars' y as well
  const double coreStrip = 2.0 * coreHalf / r.coreFibers;
  const double coverStrip = r.cover / r.coverFibers;
  for (int k = 0; k < r.coreFibers; ++k)
    addFiber(core, -coreHalf + (k + 0.5) * coreStrip, (r.b - 2.0 * r.cover) * coreStrip);
  for (int k = 0; k < r.coverFibers; ++k) {
    addFiber(cover, coreHalf + (k + 0.5) * coverStrip, r.b * coverStrip);
    addFiber(cover, -coreHalf - (k + 0.5) * coverStrip, r.b * coverStrip);
  }
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < r.coreFibers; ++k) addFiber(cover, -coreHalf + (k + 0.5) * coreStrip, r.cover * coreStrip);
  for (int k = 0; k < r.bars; ++k) {
    addFiber(steel, coreHalf, r.areaTop);
    addFiber(steel, -coreHalf, r.areaBottom);
  }
  const double spacing = 2.0 * coreHalf / (r.bars - 1);
  for (int side = 0; side < 2; ++side)
    for (int k = 1; k < r.bars - 1; ++k) addFiber(steel, coreHalf - k * spacing, r.areaSide);
}

std::unique_ptr<SectionForceDeformation2d> RCSection2d::clone() const { return std::make_unique<RCSection2d>(*this); }

namespace {

std::unique_ptr<BeamSection> buildRCSection2d(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section RCSection2d " + std::to_string(tag));
  if (domain.spaceDim() != 2) args.fail("RCSection2d is a 2D section: it needs a 2D model (-ndm 2)");
  const UniaxialMaterial& core = domain.uniaxialMaterials.get(args.nextInt("coreMatTag"), args.context());
  const UniaxialMaterial& cover = domain.uniaxialMaterials.get(args.nextInt("coverMatTag"), args.context());
  const UniaxialMaterial& steel = domain.uniaxialMaterials.get(args.nextInt("steelMatTag"), args.context());
  RCSection2d::Definition r;
  struct Positive {
    double* value;
    const char* name;
  };
  for (const Positive& item : {Positive{&r.d, "d"}, Positive{&r.b, "b"}, Positive{&r.cover, "cover_depth"},
                               Positive{&r.areaTop, "Atop"}, Positive{&r.areaBottom, "Abot"},
                               Positive{&r.areaSide, "Aside"}}) {
    const std::size_t at = args.position();
    *item.value = args.nextDouble(item.name);
    if (!(*item.value > 0.0)) args.failAt(at, item.name, "a positive number");
  }
  struct Count {
    int* value;
    const char* name;
    int least;
  };
  for (const Count& item : {Count{&r.coreFibers, "Nfcore", 1}, Count{&r.coverFibers, "Nfcover", 1},
                            Count{&r.bars, "Nfs", 2}}) {
    const std::size_t at = args.position();
    *item.value = args.nextInt(item.name);
    if (*item.value < item.least || *item.value > 100000)
      args.failAt(at, item.name, "an integer in " + std::to_string(item.least) + "..100000");
  }
  args.expectEnd();
  if (!(2.0 * r.cover < r.d) || !(2.0 * r.cover < r.b))
    args.fail("the cover (2 x " + std::to_string(r.cover) + ") leaves no core in d = " + std::to_string(r.d) +
              ", b = " + std::to_string(r.b));
  return std::make_unique<RCSection2d>(tag, core, cover, steel, r);
}

void registerRCSection2d(Registry& r) { r.sections.add("RCSection2d", &buildRCSection2d); }

}  // namespace

BEAMSOLID_REGISTER(registerRCSection2d);

}  // namespace beamsolid
