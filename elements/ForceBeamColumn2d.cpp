#include "elements/ForceBeamColumn2d.h"

#include <cmath>
#include <iostream>

#include "core/CommandArgs.h"
#include "core/Domain.h"

namespace beamsolid {

ForceBeamColumn2d::ForceBeamColumn2d(int tag, Definition&& definition)
    : SectionBeamColumn2d(tag, std::move(definition)) {}

SectionBeamColumn2d::Interpolation ForceBeamColumn2d::forceInterpolation(const std::vector<SectionCode>& codes,
                                                                        double xi, double L) {
  Interpolation b = Interpolation::Zero(static_cast<int>(codes.size()), 3);
  for (int r = 0; r < static_cast<int>(codes.size()); ++r) switch (codes[r]) {
      case SectionCode::P: b(r, 0) = 1.0; break;
      case SectionCode::Mz:
        b(r, 1) = xi - 1.0;
        b(r, 2) = xi;
        break;
      case SectionCode::Vy: b(r, 1) = b(r, 2) = 1.0 / L; break;
      default: break;  // 3D components have no 2D basic force
    }
  return b;
}

void ForceBeamColumn2d::initializeState() {
  interpolation_.clear();
  std::vector<double> weightLength;
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    interpolation_.push_back(forceInterpolation(sections_[i]->codes(), xi_[i], length_));
    weightLength.push_back(weights_[i] * length_);
  }
  initialBasicStiffness_ =
      state_.initialize(sections_, interpolation_, std::move(weightLength), options().maxIterations, options().tolerance);
}

void ForceBeamColumn2d::solveState(const Vector3& v) {
  // As OpenSees, an element that cannot reach compatibility warns and keeps
  // the state of its last attempt; the global iterations go on from it.
  if (!state_.update(v))
    std::cerr << "WARNING " << context() << ": element compatibility not reached (" << options().maxIterations
              << " iterations, tol " << options().tolerance << "); going on with the last state\n";
}

void ForceBeamColumn2d::ensureState() {
  if (state_.loadsChanged()) solveState(state_.deformation());
}

void ForceBeamColumn2d::update() {
  transf_->update();
  const Vector3 v = transf_->basicTrialDisp();
  // An unchanged v leaves the element as it is, as in OpenSees; new element
  // loads alone (as right after a load step is applied) wait for the next
  // change of v: the first residual of a step sees them through p0 only.
  if (v == state_.deformation()) return;
  solveState(v);
}

// As OpenSees, new element loads reach q at the next state determination
// (update()): until then the element answers with the forces it has, and
// only the basic system's reactions p0 follow the loads at once.
ForceBeamColumn2d::Vector3 ForceBeamColumn2d::basicForce() { return state_.force(); }

const ForceBeamColumn2d::Matrix3& ForceBeamColumn2d::basicStiffness() { return state_.stiffness(); }

ForceBeamColumn2d::Vector3 ForceBeamColumn2d::plasticDeformation() {
  // v minus the elastic deformations of the section forces b q + s_load:
  // an elastic element under element loads has none.
  Vector3 elastic = Vector3::Zero();
  for (int i = 0; i < numSections(); ++i) {
    elastic += weights_[i] * length_ * interpolation_[i].transpose() * state_.initialFlexibility(i) *
               (interpolation_[i] * state_.force() + state_.loadForces(std::size_t(i)));
  }
  return basicDeformation() - elastic;
}

void ForceBeamColumn2d::commitState() {
  ensureState();
  transf_->commitState();
  for (auto& s : sections_) s->commitState();
  state_.commit();
}

void ForceBeamColumn2d::revertToLastCommit() {
  transf_->revertToLastCommit();
  for (auto& s : sections_) s->revertToLastCommit();
  state_.revertToLastCommit();
}

void ForceBeamColumn2d::revertToStart() {
  transf_->revertToStart();
  for (auto& s : sections_) s->revertToStart();
  state_.revertToStart();
}

void ForceBeamColumn2d::zeroLoad() {
  zeroLoadReactions();
  state_.zeroLoad();
}

void ForceBeamColumn2d::addLoad(const ElementLoad& load, double factor) {
  const BeamLoad l = readLoad(load, factor);
  addLoadReactions(l);
  const double L = length_;
  // Section forces of the simply supported basic system (axially held at I):
  // M = -w x (L - x) / 2 for a load along +y, and V = dM/dx.
  for (int i = 0; i < numSections(); ++i) {
    const double x = xi_[i] * L;
    const std::vector<SectionCode>& codes = sections_[i]->codes();
    SectionVector& s = state_.changeLoadForces(std::size_t(i));
    for (int r = 0; r < static_cast<int>(codes.size()); ++r) {
      switch (codes[r]) {
        case SectionCode::P:
          if (l.uniform) s[r] += l.wx * (L - x);
          else if (x < l.a) s[r] += l.px;
          break;
        case SectionCode::Mz:
          if (l.uniform) s[r] -= 0.5 * l.wy * x * (L - x);
          else s[r] -= l.py * (x <= l.a ? x * (L - l.a) / L : l.a * (L - x) / L);
          break;
        case SectionCode::Vy:
          if (l.uniform) s[r] += l.wy * (x - 0.5 * L);
          else s[r] += x <= l.a ? -l.py * (L - l.a) / L : l.py * l.a / L;
          break;
        default: break;
      }
    }
  }
}

std::unique_ptr<Element> ForceBeamColumn2d::build(CommandArgs& args, Domain& domain, const std::string& type) {
  auto d = SectionBeamColumn2d::parse(args, domain, type, BeamIntegration::Rule::Lobatto, true);
  // OpenSees' 2D force-based element takes '-cMass' but keeps its mass
  // lumped (checked against OpenSeesPy); scripts written for it get the same.
  d.options.consistentMass = false;
  const int tag = d.tag;
  return std::make_unique<ForceBeamColumn2d>(tag, std::move(d));
}

}  // namespace beamsolid
