#include "elements/SectionAxialMaterial.h"

#include <algorithm>

#include "core/OpenSeesError.h"

namespace beamsolid {

SectionAxialMaterial::SectionAxialMaterial(const BeamSection& section, const std::string& context)
    : UniaxialMaterial(section.tag()), section_(section.cloneSection()) {
  bind();
  bool hasAxial;
  if (section2d_) {
    const auto& codes = section2d_->codes();
    hasAxial = std::find(codes.begin(), codes.end(), SectionCode::P) != codes.end();
  } else {
    const auto codes = section3d_->responseCodes();
    hasAxial = std::find(codes.begin(), codes.end(), SectionCode::P) != codes.end();
  }
  if (!hasAxial)
    throw OpenSeesError(context + ": section " + std::to_string(section.tag()) +
                        " has no axial (P) component for a section truss");
}

SectionAxialMaterial::SectionAxialMaterial(const SectionAxialMaterial& other)
    : UniaxialMaterial(other.tag()),
      section_(other.section_->cloneSection()),
      strain_(other.strain_),
      committedStrain_(other.committedStrain_) {
  bind();
}

void SectionAxialMaterial::bind() {
  section3d_ = dynamic_cast<SectionForceDeformation*>(section_.get());
  section2d_ = dynamic_cast<SectionForceDeformation2d*>(section_.get());
  if (section2d_) {
    const auto& codes = section2d_->codes();
    axialIndex_ = static_cast<int>(std::find(codes.begin(), codes.end(), SectionCode::P) - codes.begin());
  }
}

void SectionAxialMaterial::setTrialStrain(double strain, double) {
  strain_ = strain;
  if (section2d_) {
    SectionForceDeformation2d::Vector e = SectionForceDeformation2d::Vector::Zero(section2d_->order());
    e[axialIndex_] = strain;
    section2d_->setTrialDeformation(e);
  } else {
    SectionForceDeformation::Vector4 e = SectionForceDeformation::Vector4::Zero();
    e[index3d(SectionCode::P)] = strain;
    section3d_->setTrialDeformation(e);
  }
}

double SectionAxialMaterial::stress() const {
  return section2d_ ? section2d_->force()[axialIndex_] : section3d_->force()[index3d(SectionCode::P)];
}

double SectionAxialMaterial::tangent() const {
  if (section2d_) return section2d_->tangent()(axialIndex_, axialIndex_);
  const int p = index3d(SectionCode::P);
  return section3d_->tangent()(p, p);
}

double SectionAxialMaterial::initialTangent() const {
  if (section2d_) return section2d_->initialTangent()(axialIndex_, axialIndex_);
  const int p = index3d(SectionCode::P);
  return section3d_->initialTangent()(p, p);
}

void SectionAxialMaterial::revertToLastCommit() {
  section_->revertToLastCommit();
  strain_ = committedStrain_;
}

void SectionAxialMaterial::revertToStart() {
  section_->revertToStart();
  strain_ = committedStrain_ = 0.0;
}

bool SectionAxialMaterial::setParameter(const std::vector<std::string>& args, double value) {
  return section2d_ && section2d_->setParameter(args, value);
}

}  // namespace beamsolid
