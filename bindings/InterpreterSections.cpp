// Section and beam-integration commands of the Interpreter: section, patch,
// layer, fiber (which add to the most recent section, as in OpenSeesPy) and
// beamIntegration.
#include <array>
#include <cmath>

#include "bindings/Interpreter.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "sections/BeamIntegration.h"
#include "sections/FiberGeometry.h"
#include "sections/FiberSection2d.h"
#include "sections/FiberSection3d.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {

// The section the patch, layer and fiber commands fill: a 3D fiber section,
// or a 2D one that keeps only the fibers' y.
struct FiberTarget {
  FiberSection3d* section3d = nullptr;
  FiberSection2d* section2d = nullptr;
  void add(const UniaxialMaterial& material, double y, double z, double area) const {
    if (section3d) section3d->addFiber(material, y, z, area);
    else section2d->addFiber(material, y, area);
  }
};

FiberTarget currentFiberSection(const Domain& domain, int tag, const CommandArgs& a) {
  if (tag < 0) a.fail("no section to add fibers to: call section('Fiber', secTag, '-GJ', GJ) first");
  BeamSection* s = domain.sections.find(tag);
  if (!s) a.fail("the most recent section (" + std::to_string(tag) + ") no longer exists");
  FiberTarget target{dynamic_cast<FiberSection3d*>(s), dynamic_cast<FiberSection2d*>(s)};
  if (!target.section3d && !target.section2d)
    a.fail("the most recent section (" + s->className() + " " + std::to_string(tag) +
           ") is not a Fiber section; fibers need section('Fiber', ...)");
  return target;
}

// Fibers one patch, layer or section may hold. Real sections have hundreds;
// without a ceiling a typo such as 2**31 - 1 subdivisions asks for hundreds of
// gigabytes and ends the process instead of raising OpenSeesError.
constexpr long long kMaxFibers = 1'000'000;

int readCount(CommandArgs& a, const char* what) {
  const std::size_t at = a.position();
  const int n = a.nextInt(what);
  if (n < 1) a.failAt(at, what, "an integer >= 1");
  if (n > kMaxFibers) a.failAt(at, what, "at most " + std::to_string(kMaxFibers));
  return n;
}

// Checks the fiber count of a patch (n1 x n2 subdivisions) before any is made.
void checkFiberCount(const CommandArgs& a, std::size_t at, const char* what, int n1, int n2) {
  const long long fibers = static_cast<long long>(n1) * n2;
  if (fibers > kMaxFibers)
    a.failAt(at, what, "at most " + std::to_string(kMaxFibers) + " fibers per patch (" + std::to_string(n1) +
                           " x " + std::to_string(n2) + " = " + std::to_string(fibers) + ")");
}

double readPositive(CommandArgs& a, const char* what) {
  const std::size_t at = a.position();
  const double v = a.nextDouble(what);
  if (!(v > 0.0)) a.failAt(at, what, "a positive number");
  return v;
}

void addFibers(const FiberTarget& section, const UniaxialMaterial& material, const std::vector<FiberPoint>& points) {
  if (section.section3d) section.section3d->addFibers(material, points);
  else section.section2d->addFibers(material, points);
}

}  // namespace

Result Interpreter::section(CommandArgs& a) {
  std::shared_ptr<BeamSection> s = Registry::global().sections.build(a, *domain_);
  const int tag = s->tag();
  domain_->sections.add(tag, s, a.context());
  currentSectionTag_ = tag;
  return {};
}

Result Interpreter::patch(CommandArgs& a) {
  const std::string type = a.nextString("type");
  a.setContext("patch " + type + (currentSectionTag_ >= 0 ? " (section " + std::to_string(currentSectionTag_) + ")" : ""));
  const FiberTarget section = currentFiberSection(*domain_, currentSectionTag_, a);
  const int matTag = a.nextInt("matTag");
  const UniaxialMaterial& material = domain_->uniaxialMaterials.get(matTag, a.context());
  if (type == "rect" || type == "rectangular") {
    const int ny = readCount(a, "numSubdivY");
    const std::size_t nzAt = a.position();
    const int nz = readCount(a, "numSubdivZ");
    checkFiberCount(a, nzAt, "numSubdivZ", ny, nz);
    const double yI = a.nextDouble("yI"), zI = a.nextDouble("zI");
    const double yJ = a.nextDouble("yJ"), zJ = a.nextDouble("zJ");
    a.expectEnd();
    if (yI == yJ || zI == zJ) a.fail("the rectangle has no area: corners (yI, zI) and (yJ, zJ) must differ in y and z");
    addFibers(section, material, fibergeometry::rectPatch(ny, nz, yI, zI, yJ, zJ));
  } else if (type == "quad" || type == "quadr" || type == "quadrilateral") {
    const int nIJ = readCount(a, "numSubdivIJ");
    const std::size_t nJKAt = a.position();
    const int nJK = readCount(a, "numSubdivJK");
    checkFiberCount(a, nJKAt, "numSubdivJK", nIJ, nJK);
    std::array<Eigen::Vector2d, 4> v;
    static const char* const names[4][2] = {{"yI", "zI"}, {"yJ", "zJ"}, {"yK", "zK"}, {"yL", "zL"}};
    for (int k = 0; k < 4; ++k) {
      v[k].x() = a.nextDouble(names[k][0]);
      v[k].y() = a.nextDouble(names[k][1]);
    }
    a.expectEnd();
    double twiceArea = 0.0;
    for (int k = 0; k < 4; ++k) twiceArea += v[k].x() * v[(k + 1) % 4].y() - v[(k + 1) % 4].x() * v[k].y();
    if (!(std::fabs(twiceArea) > 0.0)) a.fail("the quadrilateral I-J-K-L has no area");
    addFibers(section, material, fibergeometry::quadPatch(nIJ, nJK, v));
  } else if (type == "circ" || type == "circular") {
    const int nCirc = readCount(a, "numSubdivCirc");
    const std::size_t nRadAt = a.position();
    const int nRad = readCount(a, "numSubdivRad");
    checkFiberCount(a, nRadAt, "numSubdivRad", nCirc, nRad);
    const double yC = a.nextDouble("yCenter"), zC = a.nextDouble("zCenter");
    std::size_t at = a.position();
    const double inner = a.nextDouble("intRad");
    if (!(inner >= 0.0)) a.failAt(at, "intRad", "a radius >= 0");
    at = a.position();
    const double outer = a.nextDouble("extRad");
    if (!(outer > inner)) a.failAt(at, "extRad", "a radius larger than intRad (" + std::to_string(inner) + ")");
    double start = 0.0, end = 360.0;
    if (!a.done()) {
      start = a.nextDouble("startAng");
      end = a.nextDouble("endAng");
    }
    a.expectEnd();
    if (start == end) a.fail("startAng and endAng are equal: the patch has no area");
    addFibers(section, material, fibergeometry::circPatch(nCirc, nRad, yC, zC, inner, outer, start, end));
  } else {
    a.fail("patch type '" + type + "' is unknown (expected rect, quad or circ)");
  }
  return {};
}

Result Interpreter::layer(CommandArgs& a) {
  const std::string type = a.nextString("type");
  a.setContext("layer " + type + (currentSectionTag_ >= 0 ? " (section " + std::to_string(currentSectionTag_) + ")" : ""));
  const FiberTarget section = currentFiberSection(*domain_, currentSectionTag_, a);
  const int matTag = a.nextInt("matTag");
  const UniaxialMaterial& material = domain_->uniaxialMaterials.get(matTag, a.context());
  const int n = readCount(a, "numFiber");
  const double area = readPositive(a, "areaFiber");
  if (type == "straight") {
    const double yS = a.nextDouble("yStart"), zS = a.nextDouble("zStart");
    const double yE = a.nextDouble("yEnd"), zE = a.nextDouble("zEnd");
    a.expectEnd();
    addFibers(section, material, fibergeometry::straightLayer(n, area, yS, zS, yE, zE));
  } else if (type == "circ" || type == "circular") {
    const double yC = a.nextDouble("yCenter"), zC = a.nextDouble("zCenter");
    const double radius = readPositive(a, "radius");
    // Default: n fibers evenly around the full circle.
    double start = 0.0, end = 360.0 - 360.0 / n;
    if (!a.done()) {
      start = a.nextDouble("startAng");
      end = a.nextDouble("endAng");
    }
    a.expectEnd();
    addFibers(section, material, fibergeometry::circLayer(n, area, yC, zC, radius, start, end));
  } else {
    a.fail("layer type '" + type + "' is unknown (expected straight or circ)");
  }
  return {};
}

Result Interpreter::fiber(CommandArgs& a) {
  if (currentSectionTag_ >= 0) a.setContext("fiber (section " + std::to_string(currentSectionTag_) + ")");
  const FiberTarget section = currentFiberSection(*domain_, currentSectionTag_, a);
  const double y = a.nextDouble("yLoc");
  const double z = a.nextDouble("zLoc");
  const double area = readPositive(a, "A");
  const int matTag = a.nextInt("matTag");
  a.expectEnd();
  section.add(domain_->uniaxialMaterials.get(matTag, a.context()), y, z, area);
  return {};
}

Result Interpreter::beamIntegration(CommandArgs& a) {
  std::shared_ptr<BeamIntegration> rule = Registry::global().beamIntegrations.build(a, *domain_);
  domain_->beamIntegrations.add(rule->tag(), rule, a.context());
  return {};
}

}  // namespace beamsolid
