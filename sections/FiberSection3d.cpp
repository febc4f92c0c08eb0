#include "sections/FiberSection3d.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "sections/FiberSection2d.h"

namespace beamsolid {

FiberSection3d::FiberSection3d(int tag, double torsionalStiffness)
    : SectionForceDeformation(tag), torsionalStiffness_(torsionalStiffness) {
  formInitialTangent();
  sumFibers();
}

FiberSection3d::FiberSection3d(int tag, std::unique_ptr<UniaxialMaterial> torsion)
    : SectionForceDeformation(tag), torsion_(std::move(torsion)) {
  formInitialTangent();
  sumFibers();
}

FiberSection3d::FiberSection3d(const FiberSection3d& other)
    : SectionForceDeformation(other.tag()),
      torsionalStiffness_(other.torsionalStiffness_),
      torsion_(other.torsion_ ? other.torsion_->clone() : nullptr),
      area_(other.area_),
      areaY_(other.areaY_),
      areaZ_(other.areaZ_),
      yBar_(other.yBar_),
      zBar_(other.zBar_),
      deformation_(other.deformation_),
      committedDeformation_(other.committedDeformation_),
      force_(other.force_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_) {
  fibers_.reserve(other.fibers_.size());
  for (const Fiber& f : other.fibers_) fibers_.push_back(Fiber{f.material->clone(), f.y, f.z, f.area});
}

std::unique_ptr<SectionForceDeformation> FiberSection3d::clone() const {
  return std::make_unique<FiberSection3d>(*this);
}

void FiberSection3d::addFiber(const UniaxialMaterial& material, double y, double z, double area) {
  if (!(area > 0.0) || !std::isfinite(y) || !std::isfinite(z))
    throw OpenSeesError(context() + ": a fiber needs a positive area and finite coordinates, got y " +
                        std::to_string(y) + ", z " + std::to_string(z) + ", area " + std::to_string(area));
  fibers_.push_back(Fiber{material.clone(), y, z, area});
  area_ += area;
  areaY_ += area * y;
  areaZ_ += area * z;
  yBar_ = areaY_ / area_;
  zBar_ = areaZ_ / area_;
  // The centroid moved, so every fiber's lever arm did: sum again (once per
  // patch or layer when they come through addFibers).
  if (!deferred_) refresh();
}

void FiberSection3d::addFibers(const UniaxialMaterial& material, const std::vector<FiberPoint>& points) {
  deferred_ = true;
  try {
    for (const FiberPoint& p : points) addFiber(material, p.y, p.z, p.area);
  } catch (...) {
    deferred_ = false;
    refresh();
    throw;
  }
  deferred_ = false;
  refresh();
}

void FiberSection3d::refresh() {
  formInitialTangent();
  setTrialDeformation(deformation_);
}

void FiberSection3d::formInitialTangent() {
  initialTangent_.setZero();
  for (const Fiber& f : fibers_) {
    const double stiffness = f.material->initialTangent() * f.area;
    const Eigen::Vector3d a(1.0, -(f.y - yBar_), f.z - zBar_);
    initialTangent_.topLeftCorner<3, 3>() += stiffness * a * a.transpose();
  }
  initialTangent_(3, 3) = torsion_ ? torsion_->initialTangent() : torsionalStiffness_;
}

void FiberSection3d::setTrialDeformation(const Vector4& e) {
  deformation_ = e;
  for (Fiber& f : fibers_) f.material->setTrialStrain(e[0] - (f.y - yBar_) * e[1] + (f.z - zBar_) * e[2]);
  if (torsion_) torsion_->setTrialStrain(e[3]);
  sumFibers();
}

void FiberSection3d::sumFibers() {
  // Upper triangle of the axial-flexural block, mirrored at the end.
  double fP = 0.0, fMz = 0.0, fMy = 0.0;
  double kPP = 0.0, kPZ = 0.0, kPY = 0.0, kZZ = 0.0, kZY = 0.0, kYY = 0.0;
  for (const Fiber& f : fibers_) {
    const double fiberForce = f.material->stress() * f.area;
    const double fiberStiffness = f.material->tangent() * f.area;
    const double y = f.y - yBar_, z = f.z - zBar_;
    fP += fiberForce;
    fMz -= fiberForce * y;
    fMy += fiberForce * z;
    kPP += fiberStiffness;
    kPZ -= fiberStiffness * y;
    kPY += fiberStiffness * z;
    kZZ += fiberStiffness * y * y;
    kZY -= fiberStiffness * y * z;
    kYY += fiberStiffness * z * z;
  }
  force_ << fP, fMz, fMy, torsion_ ? torsion_->stress() : torsionalStiffness_ * deformation_[3];
  tangent_ << kPP, kPZ, kPY, 0.0,  //
      kPZ, kZZ, kZY, 0.0,          //
      kPY, kZY, kYY, 0.0,          //
      0.0, 0.0, 0.0, torsion_ ? torsion_->tangent() : torsionalStiffness_;
}

void FiberSection3d::commitState() {
  for (Fiber& f : fibers_) f.material->commitState();
  if (torsion_) torsion_->commitState();
  committedDeformation_ = deformation_;
}

void FiberSection3d::revertToLastCommit() {
  for (Fiber& f : fibers_) f.material->revertToLastCommit();
  if (torsion_) torsion_->revertToLastCommit();
  deformation_ = committedDeformation_;
  sumFibers();
}

void FiberSection3d::revertToStart() {
  for (Fiber& f : fibers_) f.material->revertToStart();
  if (torsion_) torsion_->revertToStart();
  deformation_.setZero();
  committedDeformation_.setZero();
  sumFibers();
}

int FiberSection3d::nearestFiber(double y, double z, int materialTag) const {
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < fibers_.size(); ++i) {
    const Fiber& f = fibers_[i];
    if (materialTag >= 0 && f.material->tag() != materialTag) continue;
    const double d = (f.y - y) * (f.y - y) + (f.z - z) * (f.z - z);
    if (d < bestDistance) {
      bestDistance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

namespace {

// A response argument that is a number (eleResponse passes numbers as text).
bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0 && std::isfinite(value);
}

}  // namespace

Response FiberSection3d::setResponse(const std::vector<std::string>& args) {
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
      index = nearestFiber(numbers[0], numbers[1]);
    } else if (numbers.size() == 3) {
      index = nearestFiber(numbers[0], numbers[1], static_cast<int>(numbers[2]));
    }
    if (index < 0 || next >= args.size()) return {};
    return fibers_[index].material->setResponse(std::vector<std::string>(args.begin() + next, args.end()));
  }
  if (what == "fiberData") {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < fibers_.size(); ++i)
      for (const char* n : {"y", "z", "area", "stress", "strain"}) names.push_back(n + std::to_string(i));
    return Response::named(std::move(names), [this] {
      Vector out(5 * fibers_.size());
      for (std::size_t i = 0; i < fibers_.size(); ++i) {
        const Fiber& f = fibers_[i];
        out.segment<5>(5 * i) << f.y, f.z, f.area, f.material->stress(), f.material->strain();
      }
      return out;
    });
  }
  if (what == "numFibers")
    return Response::named({"numFibers"}, [this] { return Vector::Constant(1, static_cast<double>(fibers_.size())); });
  return SectionForceDeformation::setResponse(args);
}

void FiberSection3d::print(std::ostream& os) const {
  os << "Section " << tag() << " type Fiber, " << fibers_.size() << " fibers, torsion ";
  if (torsion_) os << "uniaxialMaterial " << torsion_->tag();
  else os << "GJ " << torsionalStiffness_;
  os << ", EA " << initialTangent_(0, 0) << ", EIz " << initialTangent_(1, 1) << ", EIy " << initialTangent_(2, 2)
     << '\n';
}

namespace {

std::unique_ptr<BeamSection> buildFiberSection3d(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section Fiber " + std::to_string(tag));
  if (domain.spaceDim() == 2) return FiberSection2d::build(args, domain, tag);
  std::unique_ptr<FiberSection3d> section;
  while (!args.done()) {
    if (args.nextFlag("-GJ")) {
      if (section) args.fail("torsion is given twice (use one of '-GJ' or '-torsion')");
      const std::size_t at = args.position();
      const double GJ = args.nextDouble("GJ");
      if (!(GJ > 0.0)) args.failAt(at, "GJ", "a positive number");
      section = std::make_unique<FiberSection3d>(tag, GJ);
    } else if (args.nextFlag("-torsion")) {
      if (section) args.fail("torsion is given twice (use one of '-GJ' or '-torsion')");
      const int matTag = args.nextInt("torsionMatTag");
      section = std::make_unique<FiberSection3d>(tag, domain.uniaxialMaterials.get(matTag, args.context()).clone());
    } else if (args.nextIsString()) {
      args.fail("unknown option '" + *args.peekString() + "' (expected '-GJ' or '-torsion')");
    } else {
      args.expectEnd();
    }
  }
  if (!section)
    args.fail("a 3D fiber section needs its torsional response: give '-GJ', GJ or '-torsion', matTag");
  return section;
}

void registerFiberSection3d(Registry& r) { r.sections.add("Fiber", &buildFiberSection3d); }

}  // namespace

BEAMSOLID_REGISTER(registerFiberSection3d);

}  // namespace beamsolid
