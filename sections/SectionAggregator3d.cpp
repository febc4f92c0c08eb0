#include "sections/SectionAggregator3d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "sections/SectionAggregator2d.h"

namespace beamsolid {

int SectionAggregator3d::componentOf(SectionCode code) {
  switch (code) {
    case SectionCode::P: return 0;
    case SectionCode::Mz: return 1;
    case SectionCode::My: return 2;
    case SectionCode::T: return 3;
    default: return -1;
  }
}

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
  committedDeformation_ = deformation_;
}

void SectionAggregator3d::revertToLastCommit() {
  if (section_) section_->revertToLastCommit();
  for (auto& m : materials_)
    if (m) m->revertToLastCommit();
  deformation_ = committedDeformation_;
  assemble(false);
}

void SectionAggregator3d::revertToStart() {
  if (section_) section_->revertToStart();
  for (auto& m : materials_)
    if (m) m->revertToStart();
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
  int given = 0;
  while (!args.done()) {
    if (args.nextFlag("-section")) {
      const int secTag = args.nextInt("secTag");
      section = SectionForceDeformation::of(domain.sections.get(secTag, args.context()), args.context()).clone();
      args.expectEnd();
      break;
    }
    if (args.nextIsString())
      args.fail("unknown option '" + *args.peekString() + "' (expected matTag, code pairs or '-section')");
    const int matTag = args.nextInt("matTag");
    const std::size_t at = args.position();
    const std::string name = args.nextString("code");
    const auto code = parseSectionCode(name);
    if (!code) args.failAt(at, "code", "one of P, Mz, My, T, got '" + name + "'");
    const int c = SectionAggregator3d::componentOf(*code);
    if (c < 0)
      args.failAt(at, "code", "one of P, Mz, My, T: shear ('" + name + "') is not supported in 3D sections");
    if (materials[c]) args.failAt(at, "code", std::string("a code not given before ('") + name + "' is given twice)");
    materials[c] = domain.uniaxialMaterials.get(matTag, args.context()).clone();
    ++given;
  }
  if (given == 0) args.fail("expected at least one matTag, code pair");
  if (!section && given < 4)
    args.fail("without '-section' a 3D Aggregator needs materials for all of P, Mz, My and T");
  return std::make_unique<SectionAggregator3d>(tag, std::move(section), std::move(materials));
}

void registerSectionAggregator(Registry& r) { r.sections.add("Aggregator", &buildSectionAggregator); }

}  // namespace

BEAMSOLID_REGISTER(registerSectionAggregator);

}  // namespace beamsolid
