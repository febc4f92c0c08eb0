#include "sections/SectionAggregator3d.h"

#include <algorithm>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "sections/SectionAggregator2d.h"

namespace beamsolid {

int SectionAggregator3d::componentOf(SectionCode code) { return index3d(code); }

SectionAggregator3d::SectionAggregator3d(int tag, std::unique_ptr<SectionForceDeformation> section,
                                         std::array<std::unique_ptr<UniaxialMaterial>, 4> materials)
    : SectionForceDeformation(tag), section_(std::move(section)), materials_(std::move(materials)) {
  assemble(true);
  assemble(false);
}

SectionAggregator3d::SectionAggregator3d(const SectionAggregator3d& other)
    : SectionForceDeformation(other.tag()),
      section_(other.section_ ? other.section_->clone() : nullptr),
      deformation_(other.deformation_),
      committedDeformation_(other.committedDeformation_),
      force_(other.force_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_) {
  for (int k = 0; k < 4; ++k)
    if (other.materials_[k]) materials_[k] = other.materials_[k]->clone();
  for (const ShearMaterial& m : other.shear_) shear_.push_back({m.code, m.material->clone()});
}

void SectionAggregator3d::addShear(SectionCode code, std::unique_ptr<UniaxialMaterial> material) {
  shear_.push_back({code, std::move(material)});
}

SectionCode SectionAggregator3d::shearCode(int k) const {
  if (k < 0 || k >= numShear()) return SectionForceDeformation::shearCode(k);
  return shear_[std::size_t(k)].code;
}

void SectionAggregator3d::setTrialShear(const ShearVector& gamma) {
  if (gamma.size() != numShear()) {
    SectionForceDeformation::setTrialShear(gamma);
    return;
  }
  for (int k = 0; k < numShear(); ++k) shear_[std::size_t(k)].material->setTrialStrain(gamma[k]);
}

SectionAggregator3d::ShearVector SectionAggregator3d::shearDeformation() const {
  ShearVector out(numShear());
  for (int k = 0; k < numShear(); ++k) out[k] = shear_[std::size_t(k)].material->strain();
  return out;
}

SectionAggregator3d::ShearVector SectionAggregator3d::shearForce() const {
  ShearVector out(numShear());
  for (int k = 0; k < numShear(); ++k) out[k] = shear_[std::size_t(k)].material->stress();
  return out;
}

SectionAggregator3d::ShearVector SectionAggregator3d::shearTangent() const {
  ShearVector out(numShear());
  for (int k = 0; k < numShear(); ++k) out[k] = shear_[std::size_t(k)].material->tangent();
  return out;
}

SectionAggregator3d::ShearVector SectionAggregator3d::shearInitialTangent() const {
  ShearVector out(numShear());
  for (int k = 0; k < numShear(); ++k) out[k] = shear_[std::size_t(k)].material->initialTangent();
  return out;
}

std::unique_ptr<SectionForceDeformation> SectionAggregator3d::clone() const {
  return std::make_unique<SectionAggregator3d>(*this);
}

void SectionAggregator3d::assemble(bool initial) {
  Matrix4& k = initial ? initialTangent_ : tangent_;
  k.setZero();
  if (section_) {
    k = initial ? section_->initialTangent() : section_->tangent();
    if (!initial) force_ = section_->force();
  }
  for (int c = 0; c < 4; ++c) {
    if (!materials_[c]) continue;
    // The material takes the component over: no coupling to the others.
    k.row(c).setZero();
    k.col(c).setZero();
    k(c, c) = initial ? materials_[c]->initialTangent() : materials_[c]->tangent();
    if (!initial) force_[c] = materials_[c]->stress();
  }
}

void SectionAggregator3d::setTrialDeformation(const Vector4& e) {
  deformation_ = e;
  if (section_) section_->setTrialDeformation(e);
  for (int c = 0; c < 4; ++c)
    if (materials_[c]) materials_[c]->setTrialStrain(e[c]);
  assemble(false);
}

void SectionAggregator3d::commitState() {
  if (section_) section_->commitState();
  for (auto& m : materials_)
    if (m) m->commitState();
  for (auto& m : shear_) m.material->commitState();
  committedDeformation_ = deformation_;
}

void SectionAggregator3d::revertToLastCommit() {
  if (section_) section_->revertToLastCommit();
  for (auto& m : materials_)
    if (m) m->revertToLastCommit();
  for (auto& m : shear_) m.material->revertToLastCommit();
  deformation_ = committedDeformation_;
  assemble(false);
}

void SectionAggregator3d::revertToStart() {
  if (section_) section_->revertToStart();
  for (auto& m : materials_)
    if (m) m->revertToStart();
  for (auto& m : shear_) m.material->revertToStart();
  deformation_.setZero();
  committedDeformation_.setZero();
  assemble(false);
}

Response SectionAggregator3d::setResponse(const std::vector<std::string>& args) {
  if (Response r = SectionForceDeformation::setResponse(args)) return r;
  return section_ ? section_->setResponse(args) : Response{};
}

void SectionAggregator3d::print(std::ostream& os) const {
  os << "Section " << tag() << " type Aggregator (3D), materials for";
  static const char* const names[4] = {"P", "Mz", "My", "T"};
  for (int c = 0; c < 4; ++c)
    if (materials_[c]) os << ' ' << names[c] << " (" << materials_[c]->tag() << ')';
  for (const ShearMaterial& m : shear_) os << ' ' << sectionCodeName(m.code) << " (" << m.material->tag() << ')';
  if (section_) os << ", section " << section_->className() << ' ' << section_->tag();
  os << '\n';
}

namespace {

std::unique_ptr<BeamSection> buildSectionAggregator(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("secTag");
  args.setContext("section Aggregator " + std::to_string(tag));
  if (domain.spaceDim() == 2) return SectionAggregator2d::build(args, domain, tag);
  if (domain.spaceDim() != 3) args.fail("Aggregator needs a 2D or 3D model (-ndm 2 or 3)");
  std::array<std::unique_ptr<UniaxialMaterial>, 4> materials;
  std::unique_ptr<SectionForceDeformation> section;
  std::vector<std::pair<SectionCode, std::unique_ptr<UniaxialMaterial>>> shear;
  int given = 0;
  while (!args.done()) {
    if (args.nextFlag("-section")) {
      const int secTag = args.nextInt("secTag");
      section = SectionForceDeformation::of(domain.sections.get(secTag, args.context()), args.context()).clone();
      if (section->numShear() > 0)
        args.fail("'-section' " + std::to_string(secTag) +
                  " is shear-deformable; aggregating it is not supported (give its shear by Vy, Vz materials)");
      args.expectEnd();
      break;
    }
    if (args.nextIsString())
      args.fail("unknown option '" + *args.peekString() + "' (expected matTag, code pairs or '-section')");
    const int matTag = args.nextInt("matTag");
    const std::size_t at = args.position();
    const std::string name = args.nextString("code");
    const auto code = parseSectionCode(name);
    if (!code) args.failAt(at, "code", "one of P, Mz, My, T, Vy, Vz, got '" + name + "'");
    const int c = SectionAggregator3d::componentOf(*code);
    const bool repeated = c >= 0 ? materials[c] != nullptr
                                 : std::any_of(shear.begin(), shear.end(), [&](const auto& m) { return m.first == *code; });
    if (repeated) args.failAt(at, "code", std::string("a code not given before ('") + name + "' is given twice)");
    auto material = domain.uniaxialMaterials.get(matTag, args.context()).clone();
    if (c >= 0) materials[c] = std::move(material);
    else shear.emplace_back(*code, std::move(material));
    ++given;
  }
  if (given == 0) args.fail("expected at least one matTag, code pair");
  if (!section && std::any_of(materials.begin(), materials.end(), [](const auto& m) { return !m; }))
    args.fail("without '-section' a 3D Aggregator needs materials for all of P, Mz, My and T");
  auto aggregator = std::make_unique<SectionAggregator3d>(tag, std::move(section), std::move(materials));
  for (auto& [code, material] : shear) aggregator->addShear(code, std::move(material));
  return aggregator;
}

void registerSectionAggregator(Registry& r) { r.sections.add("Aggregator", &buildSectionAggregator); }

}  // namespace

BEAMSOLID_REGISTER(registerSectionAggregator);

}  // namespace beamsolid
