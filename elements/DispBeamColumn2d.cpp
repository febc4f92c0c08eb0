#include "elements/DispBeamColumn2d.h"

#include <algorithm>
#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"

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

int DispBeamColumn2d::sensitivityParameter(const std::vector<std::string>& args) {
  for (std::size_t k = 0; k < sensitivity_.size(); ++k)
    if (sensitivity_[k].args == args) return static_cast<int>(k) + 1;
  SensitivityBinding b{args, {}};
  bool any = false;
  for (auto& section : sections_) {
    b.sectionIds.push_back(section->sensitivityParameter(args));
    any = any || b.sectionIds.back() > 0;
  }
  if (!any) return 0;
  sensitivity_.push_back(std::move(b));
  return static_cast<int>(sensitivity_.size());
}

std::vector<SectionBeamColumn2d::SectionVector> DispBeamColumn2d::sectionDeformations() {
  transf_->update();
  const Vector3 v = transf_->basicTrialDisp();
  std::vector<SectionVector> e;
  for (int i = 0; i < numSections(); ++i) e.push_back(strainDisplacement_[i] * v);
  return e;
}

void DispBeamColumn2d::moveNode(int node, int dim, double value) {
  nodes()[node]->setCoordinate(dim, value);
  rereadGeometry();
}

namespace {
// Step of a central difference in a coordinate: small against the element.
double coordinateStep(double length) { return 1e-6 * length; }
}  // namespace

Vector DispBeamColumn2d::resistingForceSensitivity(int gradient, const SensitivityParameter& p) {
  const SensitivityBinding* b = p.id > 0 ? &sensitivity_.at(p.id - 1) : nullptr;
  // The sections' part at the trial deformations: dq = sum w L B^T ds.
  Vector3 dq = Vector3::Zero();
  for (int i = 0; i < numSections(); ++i) {
    const SectionVector ds = sections_[i]->forceSensitivity(gradient, b ? b->sectionIds[i] : 0);
    dq.noalias() += weights_[i] * length_ * strainDisplacement_[i].transpose() * ds;
  }
  // Global forces are linear in q at fixed displacements (every 2D transformation).
  Vector dR = transf_->globalResistingForce(dq, Vector6::Zero());
  if (p.node >= 0) {
    Node& node = *nodes()[p.node];
    const double x = node.crd()[p.dim], h = coordinateStep(length_);
    moveNode(p.node, p.dim, x + h);
    update();
    const Vector plus = resistingForce();
    moveNode(p.node, p.dim, x - h);
    update();
    const Vector minus = resistingForce();
    moveNode(p.node, p.dim, x);
    update();
    dR += (plus - minus) / (2.0 * h);
  }
  return dR;
}

void DispBeamColumn2d::commitSensitivity(int gradient, const SensitivityParameter& p, const Vector& dU,
                                         int numGradients) {
  const SensitivityBinding* b = p.id > 0 ? &sensitivity_.at(p.id - 1) : nullptr;
  // d e / d theta: the derivative of the sections' deformations along the
  // displacements' sensitivity (and the coordinate's), by central differences
  // of B v, exact for the linear transformations and second order for the
  // corotational one. The step t makes the largest move 1e-6 L.
  const double rotationScale = length_;
  double largest = p.node >= 0 ? 1.0 : 0.0;
  for (int k = 0; k < 6; ++k) largest = std::max(largest, std::fabs(dU[k]) * (k % 3 == 2 ? rotationScale : 1.0));
  std::vector<SectionVector> de(numSections(), SectionVector::Zero(2));
  for (int i = 0; i < numSections(); ++i) de[i] = SectionVector::Zero(sections_[i]->order());
  if (largest > 0.0) {
    const double t = coordinateStep(length_) / largest;
    Node* end[2] = {nodes()[0], nodes()[1]};
    const Vector u[2] = {end[0]->trialDisp(), end[1]->trialDisp()};
    const double x = p.node >= 0 ? end[p.node]->crd()[p.dim] : 0.0;
    auto deformationsAt = [&](double s) {
      for (int k = 0; k < 2; ++k) end[k]->setTrialDisp(u[k] + s * dU.segment<3>(3 * k));
      if (p.node >= 0) moveNode(p.node, p.dim, x + s);
      return sectionDeformations();
    };
    const std::vector<SectionVector> plus = deformationsAt(t);
    const std::vector<SectionVector> minus = deformationsAt(-t);
    for (int k = 0; k < 2; ++k) end[k]->setTrialDisp(u[k]);
    if (p.node >= 0) moveNode(p.node, p.dim, x);
    update();
    for (int i = 0; i < numSections(); ++i) de[i] = (plus[i] - minus[i]) / (2.0 * t);
  }
  for (int i = 0; i < numSections(); ++i)
    sections_[i]->commitSensitivity(de[i], gradient, b ? b->sectionIds[i] : 0, numGradients);
}

std::unique_ptr<Element> DispBeamColumn2d::build(CommandArgs& args, Domain& domain) {
  auto d = SectionBeamColumn2d::parse(args, domain, "dispBeamColumn", BeamIntegration::Rule::Legendre, false);
  const int tag = d.tag;
  return std::make_unique<DispBeamColumn2d>(tag, std::move(d));
}

}  // namespace beamsolid
