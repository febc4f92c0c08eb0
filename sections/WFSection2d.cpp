#include "sections/WFSection2d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

WFSection2d::WFSection2d(int tag, const UniaxialMaterial& material, const Dimensions& w)
    : FiberSection2d(tag), dimensions_(w) {
  for (const Strip& s : layout(w)) addFiber(material, s.y, s.area);
}

std::vector<WFSection2d::Strip> WFSection2d::layout(const Dimensions& w) {
  const double webHeight = w.d - 2.0 * w.tf;
  // Nfw or Nff = 0 leaves the web or the flanges out, as OpenSees does.
  const double webStrip = w.webFibers > 0 ? webHeight / w.webFibers : 0.0;
  const double flangeStrip = w.flangeFibers > 0 ? w.tf / w.flangeFibers : 0.0;
  // tf = 0: flanges of no area carry nothing; they get no fibers.
  const int flangeFibers = w.tf > 0.0 ? w.flangeFibers : 0;
  // Fibers run from the top of the section down (top flange, web, bottom
  // flange): OpenSees numbers them so, and 'fiber $i' responses use that order.
  std::vector<Strip> strips;
  for (int k = 0; k < flangeFibers; ++k) strips.push_back({0.5 * w.d - (k + 0.5) * flangeStrip, w.bf * flangeStrip});
  for (int k = 0; k < w.webFibers; ++k) strips.push_back({0.5 * webHeight - (k + 0.5) * webStrip, w.tw * webStrip});
  for (int k = 0; k < flangeFibers; ++k)
    strips.push_back({-0.5 * webHeight - (k + 0.5) * flangeStrip, w.bf * flangeStrip});
  return strips;
}

int WFSection2d::geometryParameter(const std::vector<std::string>& args) const {
  if (args.empty()) return 0;
  const std::string& n = args[0];
  if (n == "d") return 1;
  if (n == "tw") return 2;
  if (n == "bf") return 3;
  if (n == "tf") return 4;
  return 0;
}

double WFSection2d::geometryValue(int id) const {
  const Dimensions& w = dimensions_;
  return id == 1 ? w.d : id == 2 ? w.tw : id == 3 ? w.bf : w.tf;
}

void WFSection2d::setGeometry(int id, double value) {
  Dimensions w = dimensions_;
  (id == 1 ? w.d : id == 2 ? w.tw : id == 3 ? w.bf : w.tf) = value;
  const std::vector<Strip> strips = layout(w);
  // The fibers keep their materials' states: only their places change, so
  // the layout must keep its number of fibers (no flanges appear or vanish).
  if (strips.size() != numFibers() || !(w.d > 2.0 * w.tf) || !(w.tw > 0.0) || !(w.bf > 0.0) ||
      (dimensions_.tf > 0.0) != (w.tf > 0.0))
    throw OpenSeesError(context() + ": cannot take " + std::string(id == 1 ? "d" : id == 2 ? "tw" : id == 3 ? "bf" : "tf") +
                        " = " + std::to_string(value) + " (the section would change its fibers or vanish)");
  dimensions_ = w;
  for (std::size_t i = 0; i < strips.size(); ++i) placeFiber(i, strips[i].y, strips[i].area);
}

std::unique_ptr<SectionForceDeformation2d> WFSection2d::clone() const { return std::make_unique<WFSection2d>(*this); }

namespace {

std::unique_ptr<BeamSection> buildWFSection2d(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section WFSection2d " + std::to_string(tag));
  if (domain.spaceDim() != 2) args.fail("WFSection2d is a 2D section: it needs a 2D model (-ndm 2)");
  const int matTag = args.nextInt("matTag");
  const UniaxialMaterial& material = domain.uniaxialMaterials.get(matTag, args.context());
  WFSection2d::Dimensions w;
  struct Dimension {
    double* value;
    const char* name;
  };
  for (const Dimension& item : {Dimension{&w.d, "d"}, Dimension{&w.tw, "tw"}, Dimension{&w.bf, "bf"}}) {
    const std::size_t at = args.position();
    *item.value = args.nextDouble(item.name);
    if (!(*item.value > 0.0)) args.failAt(at, item.name, "a positive number");
  }
  // tf = 0 (a web alone) is allowed, as in OpenSees.
  std::size_t at = args.position();
  w.tf = args.nextDouble("tf");
  if (!(w.tf >= 0.0)) args.failAt(at, "tf", "a number >= 0");
  at = args.position();
  w.webFibers = args.nextInt("Nfw");
  if (w.webFibers < 0 || w.webFibers > 100000) args.failAt(at, "Nfw", "an integer in 0..100000");
  at = args.position();
  w.flangeFibers = args.nextInt("Nff");
  if (w.flangeFibers < 0 || w.flangeFibers > 100000) args.failAt(at, "Nff", "an integer in 0..100000");
  args.expectEnd();
  if (w.webFibers + (w.tf > 0.0 ? w.flangeFibers : 0) == 0)
    args.fail("Nfw = 0 with no flanges (Nff = 0 or tf = 0) leaves the section without fibers");
  if (!(2.0 * w.tf <= w.d)) args.fail("the flanges (2 tf = " + std::to_string(2.0 * w.tf) + ") are deeper than d = " +
                                      std::to_string(w.d));
  return std::make_unique<WFSection2d>(tag, material, w);
}

void registerWFSection2d(Registry& r) { r.sections.add("WFSection2d", &buildWFSection2d); }

}  // namespace

BEAMSOLID_REGISTER(registerWFSection2d);

}  // namespace beamsolid
