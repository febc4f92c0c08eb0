#include "sections/FiberSection2d.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

FiberSection2d::FiberSection2d(int tag) : SectionForceDeformation2d(tag) {}

FiberSection2d::FiberSection2d(const FiberSection2d& other)
    : SectionForceDeformation2d(other.tag()),
      area_(other.area_),
      areaY_(other.areaY_),
      yBar_(other.yBar_),
      initialSums_(other.initialSums_),
      deformation_(other.deformation_),
      committedDeformation_(other.committedDeformation_),
      force_(other.force_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_) {
  fibers_.reserve(other.fibers_.size());
  for (const Fiber& f : other.fibers_) fibers_.push_back(Fiber{f.material->clone(), f.y, f.area});
}

std::unique_ptr<SectionForceDeformation2d> FiberSection2d::clone() const {
  return std::make_unique<FiberSection2d>(*this);
}

const std::vector<SectionCode>& FiberSection2d::codes() const {
  static const std::vector<SectionCode> codes = {SectionCode::P, SectionCode::Mz};
  return codes;
}

void FiberSection2d::addFiber(const UniaxialMaterial& material, double y, double area) {
  if (!(area > 0.0) || !std::isfinite(y))
    throw OpenSeesError(context() + ": a fiber needs a positive area and a finite y, got y " + std::to_string(y) +
                        ", area " + std::to_string(area));
  fibers_.push_back(Fiber{material.clone(), y, area});
  area_ += area;
  areaY_ += area * y;
  yBar_ = areaY_ / area_;
  const double E = fibers_.back().material->initialTangent() * area;
  initialSums_.stiffness += E;
  initialSums_.stiffY += E * y;
  initialSums_.stiffYY += E * y * y;
  if (!deferred_) refresh();
}

void FiberSection2d::addFibers(const UniaxialMaterial& material, const std::vector<FiberPoint>& points) {
  deferred_ = true;
  try {
    for (const FiberPoint& p : points) addFiber(material, p.y, p.area);
  } catch (...) {
    deferred_ = false;
    refresh();
    throw;
  }
  deferred_ = false;
  refresh();
}

void FiberSection2d::refresh() {
  // The centroid moved: every fiber's strain follows (sections are filled
  // before any analysis, so this is one pass per fiber at zero deformation).
  if (deformation_.isZero(0.0)) {
    for (Fiber& f : fibers_) f.material->setTrialStrain(0.0);
    Sums current;
    // Unstrained fibers may still carry stress (initial stress materials).
    for (const Fiber& g : fibers_) {
      const double s = g.material->stress() * g.area, k = g.material->tangent() * g.area;
      current.force += s;
      current.firstMoment += s * g.y;
      current.stiffness += k;
      current.stiffY += k * g.y;
      current.stiffYY += k * g.y * g.y;
    }
    fromSums(current, initialSums_);
  } else {
    setTrialDeformation(deformation_);
  }
}

void FiberSection2d::fromSums(const Sums& c, const Sums& i) {
  // About the centroid: sum k (y - yBar) = sum k y - yBar sum k, and so on.
  const double b = yBar_;
  force_ << c.force, -(c.firstMoment - b * c.force);
  const double kPM = -(c.stiffY - b * c.stiffness);
  tangent_ << c.stiffness, kPM, kPM, c.stiffYY - 2.0 * b * c.stiffY + b * b * c.stiffness;
  const double iPM = -(i.stiffY - b * i.stiffness);
  initialTangent_ << i.stiffness, iPM, iPM, i.stiffYY - 2.0 * b * i.stiffY + b * b * i.stiffness;
}

void FiberSection2d::setTrialDeformation(const Vector& e) {
  deformation_ = e;
  for (Fiber& f : fibers_) f.material->setTrialStrain(e[0] - (f.y - yBar_) * e[1]);
  sumFibers();
}

void FiberSection2d::sumFibers() {
  double fP = 0.0, fM = 0.0, kPP = 0.0, kPM = 0.0, kMM = 0.0;
  for (const Fiber& f : fibers_) {
    const double y = f.y - yBar_;
    const double s = f.material->stress() * f.area, k = f.material->tangent() * f.area;
    fP += s;
    fM -= s * y;
    kPP += k;
    kPM -= k * y;
    kMM += k * y * y;
  }
  force_ << fP, fM;
  tangent_ << kPP, kPM, kPM, kMM;
}

void FiberSection2d::commitState() {
  for (Fiber& f : fibers_) f.material->commitState();
  committedDeformation_ = deformation_;
}

void FiberSection2d::revertToLastCommit() {
  for (Fiber& f : fibers_) f.material->revertToLastCommit();
  deformation_ = committedDeformation_;
  sumFibers();
}

void FiberSection2d::revertToStart() {
  for (Fiber& f : fibers_) f.material->revertToStart();
  deformation_.setZero();
  committedDeformation_.setZero();
  sumFibers();
}

int FiberSection2d::nearestFiber(double y, int materialTag) const {
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < fibers_.size(); ++i) {
    const Fiber& f = fibers_[i];
    if (materialTag >= 0 && f.material->tag() != materialTag) continue;
    const double d = std::fabs(f.y - y);
    if (d < bestDistance) {
      bestDistance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

namespace {

bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0 && std::isfinite(value);
}

}  // namespace

Response FiberSection2d::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  if (what == "fiber" || what == "-fiber") {
    std::vector<double> numbers;
    std::size_t next = 1;
    double value = 0.0;
    while (next < args.size() && numbers.size() < 3 && parseNumber(args[next], value)) {
      numbers.push_back(value);
      ++next;
    }
    int index = -1;
    if (numbers.size() == 1) {
      if (numbers[0] >= 0.0 && numbers[0] < static_cast<double>(fibers_.size()) &&
          std::floor(numbers[0]) == numbers[0])
        index = static_cast<int>(numbers[0]);
    } else if (numbers.size() == 2) {
      index = nearestFiber(numbers[0]);
    } else if (numbers.size() == 3) {
      index = nearestFiber(numbers[0], static_cast<int>(numbers[2]));
    }
    if (index < 0 || next >= args.size()) return {};
    return fibers_[index].material->setResponse(std::vector<std::string>(args.begin() + next, args.end()));
  }
  if (what == "fiberData") {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < fibers_.size(); ++i)
      for (const char* n : {"y", "z", "area", "stress", "strain"}) names.push_back(n + std::to_string(i));
    return Response::named(std::move(names), [this] {
      beamsolid::Vector out(5 * fibers_.size());
      for (std::size_t i = 0; i < fibers_.size(); ++i) {
        const Fiber& f = fibers_[i];
        out.segment<5>(5 * i) << f.y, 0.0, f.area, f.material->stress(), f.material->strain();
      }
      return out;
    });
  }
  if (what == "numFibers")
    return Response::named({"numFibers"},
                           [this] { return beamsolid::Vector::Constant(1, static_cast<double>(fibers_.size())); });
  return SectionForceDeformation2d::setResponse(args);
}

void FiberSection2d::print(std::ostream& os) const {
  os << "Section " << tag() << " type " << className() << " (2D), " << fibers_.size() << " fibers, centroid y "
     << yBar_ << ", EA " << initialTangent_(0, 0) << ", EIz " << initialTangent_(1, 1) << '\n';
}

void FiberSection2d::placeFiber(std::size_t i, double y, double area) {
  fibers_.at(i).y = y;
  fibers_.at(i).area = area;
}

void FiberSection2d::updateGeometry() {
  area_ = areaY_ = 0.0;
  initialSums_ = Sums{};
  for (const Fiber& f : fibers_) {
    area_ += f.area;
    areaY_ += f.area * f.y;
    const double E = f.material->initialTangent() * f.area;
    initialSums_.stiffness += E;
    initialSums_.stiffY += E * f.y;
    initialSums_.stiffYY += E * f.y * f.y;
  }
  yBar_ = area_ > 0.0 ? areaY_ / area_ : 0.0;
  const double b = yBar_;
  const Sums& i = initialSums_;
  const double iPM = -(i.stiffY - b * i.stiffness);
  initialTangent_ << i.stiffness, iPM, iPM, i.stiffYY - 2.0 * b * i.stiffY + b * b * i.stiffness;
}

bool FiberSection2d::setParameter(const std::vector<std::string>& args, double value) {
  if (const int id = geometryParameter(args)) {
    setGeometry(id, value);
    updateGeometry();
    setTrialDeformation(deformation_);
    return true;
  }
  bool accepted = false;
  for (Fiber& f : fibers_) accepted = f.material->setParameter(args, value) || accepted;
  if (accepted) {
    updateGeometry();  // the initial tangent follows E
    setTrialDeformation(deformation_);
  }
  return accepted;
}

int FiberSection2d::sensitivityParameter(const std::vector<std::string>& args) {
  for (std::size_t k = 0; k < sensitivity_.size(); ++k)
    if (sensitivity_[k].args == args) return static_cast<int>(k) + 1;
  SensitivityBinding b{args, geometryParameter(args), {}};
  bool any = b.geometry > 0;
  for (const Fiber& f : fibers_) {
    b.fiberIds.push_back(f.material->sensitivityParameter(args));
    any = any || b.fiberIds.back() > 0;
  }
  if (!any) return 0;
  sensitivity_.push_back(std::move(b));
  return static_cast<int>(sensitivity_.size());
}

std::vector<double> FiberSection2d::offsetsAt(int id, double value) {
  setGeometry(id, value);
  updateGeometry();
  std::vector<double> offsets;
  offsets.reserve(fibers_.size());
  for (const Fiber& f : fibers_) offsets.push_back(f.y - yBar_);
  return offsets;
}

namespace {
// The step of a central difference in a geometric value.
double geometryStep(double value) { return 1e-6 * (value != 0.0 ? std::fabs(value) : 1.0); }
}  // namespace

SectionForceDeformation2d::Vector FiberSection2d::forceSensitivity(int gradient, int parameterId) {
  const SensitivityBinding* b = parameterId > 0 ? &sensitivity_.at(parameterId - 1) : nullptr;
  Vector ds = Vector::Zero(2);
  for (std::size_t i = 0; i < fibers_.size(); ++i) {
    const Fiber& f = fibers_[i];
    const double dsigma = f.material->stressSensitivity(gradient, b ? b->fiberIds[i] : 0) * f.area;
    ds[0] += dsigma;
    ds[1] -= dsigma * (f.y - yBar_);
  }
  if (b && b->geometry > 0) {
    const double value = geometryValue(b->geometry), h = geometryStep(value);
    const Vector e = deformation_;
    Vector plus, minus;
    setGeometry(b->geometry, value + h);
    updateGeometry();
    setTrialDeformation(e);
    plus = force_;
    setGeometry(b->geometry, value - h);
    updateGeometry();
    setTrialDeformation(e);
    minus = force_;
    setGeometry(b->geometry, value);
    updateGeometry();
    setTrialDeformation(e);
    ds += (plus - minus) / (2.0 * h);
  }
  return ds;
}

void FiberSection2d::commitSensitivity(const Vector& de, int gradient, int parameterId, int numGradients) {
  const SensitivityBinding* b = parameterId > 0 ? &sensitivity_.at(parameterId - 1) : nullptr;
  // A geometric parameter moves the fibers: their offsets from the centroid change too.
  std::vector<double> dOffset(fibers_.size(), 0.0);
  if (b && b->geometry > 0) {
    const double value = geometryValue(b->geometry), h = geometryStep(value);
    const std::vector<double> plus = offsetsAt(b->geometry, value + h);
    const std::vector<double> minus = offsetsAt(b->geometry, value - h);
    setGeometry(b->geometry, value);
    updateGeometry();
    for (std::size_t i = 0; i < fibers_.size(); ++i) dOffset[i] = (plus[i] - minus[i]) / (2.0 * h);
  }
  for (std::size_t i = 0; i < fibers_.size(); ++i) {
    Fiber& f = fibers_[i];
    const double dStrain = de[0] - (f.y - yBar_) * de[1] - dOffset[i] * deformation_[1];
    f.material->commitSensitivity(dStrain, gradient, b ? b->fiberIds[i] : 0, numGradients);
  }
}

std::unique_ptr<FiberSection2d> FiberSection2d::build(CommandArgs& args, Domain& domain, int tag) {
  auto section = std::make_unique<FiberSection2d>(tag);
  while (!args.done()) {
    // OpenSees takes these in 2D too; a planar section has no twist for them.
    if (args.nextFlag("-GJ")) {
      const std::size_t at = args.position();
      const double GJ = args.nextDouble("GJ");
      if (!(GJ > 0.0)) args.failAt(at, "GJ", "a positive number");
    } else if (args.nextFlag("-torsion")) {
      domain.uniaxialMaterials.get(args.nextInt("torsionMatTag"), args.context());
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() + "' (expected '-GJ')");
    } else {
      args.expectEnd();
    }
  }
  return section;
}

}  // namespace beamsolid
