#include "sections/SectionAggregator2d.h"

#include <algorithm>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

SectionAggregator2d::SectionAggregator2d(int tag, std::unique_ptr<SectionForceDeformation2d> section,
                                         std::vector<std::unique_ptr<UniaxialMaterial>> materials,
                                         std::vector<SectionCode> materialCodes)
    : SectionForceDeformation2d(tag), section_(std::move(section)), materials_(std::move(materials)) {
  if (section_) codes_ = section_->codes();
  codes_.insert(codes_.end(), materialCodes.begin(), materialCodes.end());
  const int n = order();
  deformation_ = committedDeformation_ = force_ = Vector::Zero(n);
  tangent_ = initialTangent_ = Matrix::Zero(n, n);
  assemble(true);
  assemble(false);
}

SectionAggregator2d::SectionAggregator2d(const SectionAggregator2d& other)
    : SectionForceDeformation2d(other.tag()),
      section_(other.section_ ? other.section_->clone() : nullptr),
      codes_(other.codes_),
      deformation_(other.deformation_),
      committedDeformation_(other.committedDeformation_),
      force_(other.force_),
      tangent_(other.tangent_),
      initialTangent_(other.initialTangent_) {
  for (const auto& m : other.materials_) materials_.push_back(m->clone());
}

std::unique_ptr<SectionForceDeformation2d> SectionAggregator2d::clone() const {
  return std::make_unique<SectionAggregator2d>(*this);
}

void SectionAggregator2d::assemble(bool initial) {
  const int m = sectionOrder();
  Matrix& k = initial ? initialTangent_ : tangent_;
  k.setZero();
  if (section_) {
    k.topLeftCorner(m, m) = initial ? section_->initialTangent() : section_->tangent();
    if (!initial) force_.head(m) = section_->force();
  }
  for (std::size_t i = 0; i < materials_.size(); ++i) {
    const int r = m + static_cast<int>(i);
    k(r, r) = initial ? materials_[i]->initialTangent() : materials_[i]->tangent();
    if (!initial) force_[r] = materials_[i]->stress();
  }
}

void SectionAggregator2d::setTrialDeformation(const Vector& e) {
  deformation_ = e;
  const int m = sectionOrder();
  if (section_) {
    const Vector head = e.head(m);
    section_->setTrialDeformation(head);
  }
  for (std::size_t i = 0; i < materials_.size(); ++i) materials_[i]->setTrialStrain(e[m + static_cast<int>(i)]);
  assemble(false);
}

void SectionAggregator2d::commitState() {
  if (section_) section_->commitState();
  for (auto& mat : materials_) mat->commitState();
  committedDeformation_ = deformation_;
}

void SectionAggregator2d::revertToLastCommit() {
  if (section_) section_->revertToLastCommit();
  for (auto& mat : materials_) mat->revertToLastCommit();
  deformation_ = committedDeformation_;
  assemble(false);
}

void SectionAggregator2d::revertToStart() {
  if (section_) section_->revertToStart();
  for (auto& mat : materials_) mat->revertToStart();
  deformation_.setZero();
  committedDeformation_.setZero();
  assemble(false);
}

Response SectionAggregator2d::setResponse(const std::vector<std::string>& args) {
  if (Response r = SectionForceDeformation2d::setResponse(args)) return r;
  return section_ ? section_->setResponse(args) : Response{};
}

void SectionAggregator2d::print(std::ostream& os) const {
  os << "Section " << tag() << " type Aggregator (2D), codes";
  for (SectionCode c : codes_) os << ' ' << sectionCodeName(c);
  if (section_) os << ", section " << section_->className() << ' ' << section_->tag();
  os << '\n';
}

std::unique_ptr<SectionAggregator2d> SectionAggregator2d::build(CommandArgs& args, Domain& domain, int tag) {
  std::vector<std::unique_ptr<UniaxialMaterial>> materials;
  std::vector<SectionCode> codes;
  std::unique_ptr<SectionForceDeformation2d> section;
  while (!args.done()) {
    if (args.nextFlag("-section")) {
      const int secTag = args.nextInt("secTag");
      section = SectionForceDeformation2d::of(domain.sections.get(secTag, args.context()), args.context()).clone();
      args.expectEnd();
      break;
    }
    if (args.nextIsString()) args.fail("unknown option '" + *args.peekString() + "' (expected matTag, code pairs or '-section')");
    const int matTag = args.nextInt("matTag");
    const std::size_t at = args.position();
    const std::string name = args.nextString("code");
    const auto code = parseSectionCode(name);
    if (!code) args.failAt(at, "code", "one of P, Mz, Vy in a 2D model, got '" + name + "'");
    if (*code != SectionCode::P && *code != SectionCode::Mz && *code != SectionCode::Vy)
      args.failAt(at, "code", "one of P, Mz, Vy in a 2D model ('" + name + "' is a 3D component)");
    materials.push_back(domain.uniaxialMaterials.get(matTag, args.context()).clone());
    codes.push_back(*code);
  }
  if (materials.empty()) args.fail("expected at least one matTag, code pair");
  std::vector<SectionCode> all = section ? section->codes() : std::vector<SectionCode>{};
  for (SectionCode c : codes) {
    if (std::find(all.begin(), all.end(), c) != all.end())
      args.fail(std::string("code ") + sectionCodeName(c) + " is given twice (by the section or another material)");
    all.push_back(c);
  }
  if (static_cast<int>(all.size()) > kMaxOrder)
    args.fail("a 2D section has at most 3 components (P, Mz, Vy), got " + std::to_string(all.size()));
  return std::make_unique<SectionAggregator2d>(tag, std::move(section), std::move(materials), std::move(codes));
}

}  // namespace beamsolid
