#include "elements/DispBeamColumn2d.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"

namespace beamsolid {

DispBeamColumn2d::DispBeamColumn2d(int tag, Definition&& definition)
    : SectionBeamColumn2d(tag, std::move(definition)) {}

SectionBeamColumn2d::Interpolation DispBeamColumn2d::strainDisplacement(const std::vector<SectionCode>& codes,
                                                                       double xi, double L) {
  Interpolation B = Interpolation::Zero(static_cast<int>(codes.size()), 3);
  // A shear component (Vy) gets no strain: Hermite bending is shear-rigid
  // (OpenSees' 2D dispBeamColumn does the same).
  for (int r = 0; r < static_cast<int>(codes.size()); ++r) {
    if (codes[r] == SectionCode::P) B(r, 0) = 1.0 / L;
    if (codes[r] == SectionCode::Mz) {
      B(r, 1) = (6.0 * xi - 4.0) / L;
      B(r, 2) = (6.0 * xi - 2.0) / L;
    }
  }
  return B;
}

void DispBeamColumn2d::initializeState() {
  strainDisplacement_.clear();
  initialBasicStiffness_.setZero();
  for (int i = 0; i < numSections(); ++i) {
    strainDisplacement_.push_back(strainDisplacement(sections_[i]->codes(), xi_[i], length_));
    const Interpolation& B = strainDisplacement_.back();
    initialBasicStiffness_ += weights_[i] * length_ * B.transpose() * sections_[i]->initialTangent() * B;
  }
  assemble();
}

void DispBeamColumn2d::assemble() {
  sectionForce_.setZero();
  kb_.setZero();
  for (int i = 0; i < numSections(); ++i) {
    const Interpolation& B = strainDisplacement_[i];
    const double wL = weights_[i] * length_;
    sectionForce_.noalias() += wL * B.transpose() * sections_[i]->force();
    kb_.noalias() += wL * B.transpose() * sections_[i]->tangent() * B;
  }
}

void DispBeamColumn2d::update() {
  transf_->update();
  const Vector3 v = transf_->basicTrialDisp();
  for (int i = 0; i < numSections(); ++i) {
    const SectionVector e = strainDisplacement_[i] * v;
    sections_[i]->setTrialDeformation(e);
  }
  assemble();
}

void DispBeamColumn2d::commitState() {
  transf_->commitState();
  for (auto& s : sections_) s->commitState();
}

void DispBeamColumn2d::revertToLastCommit() {
  transf_->revertToLastCommit();
  for (auto& s : sections_) s->revertToLastCommit();
  assemble();
}

void DispBeamColumn2d::revertToStart() {
  transf_->revertToStart();
  for (auto& s : sections_) s->revertToStart();
  assemble();
}

void DispBeamColumn2d::zeroLoad() {
  q0_.setZero();
  zeroLoadReactions();
}

void DispBeamColumn2d::addLoad(const ElementLoad& load, double factor) {
  const BeamLoad l = readLoad(load, factor);
  addLoadReactions(l);
  const double L = length_;
  if (l.uniform) {
    q0_[0] -= 0.5 * l.wx * L;
    const double m = l.wy * L * L / 12.0;
    q0_[1] -= m;
    q0_[2] += m;
  } else {
    const double a = l.a, b = L - l.a;
    q0_[0] -= l.px * a / L;
    q0_[1] -= l.py * a * b * b / (L * L);
    q0_[2] += l.py * a * a * b / (L * L);
  }
}

std::unique_ptr<Element> DispBeamColumn2d::build(CommandArgs& args, Domain& domain) {
  auto d = SectionBeamColumn2d::parse(args, domain, "dispBeamColumn", BeamIntegration::Rule::Legendre, false);
  const int tag = d.tag;
  return std::make_unique<DispBeamColumn2d>(tag, std::move(d));
}

}  // namespace beamsolid
