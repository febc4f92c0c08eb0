#include "elements/ForceBeamColumn2d.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/ElementStateError.h"

namespace beamsolid {

namespace {

using SectionMatrix = SectionBeamColumn2d::SectionMatrix;

// f = ks^-1, regularized as in ForceBeamColumn3d when a mode has lost all
// stiffness (every fiber yielded).
void sectionFlexibility(const SectionMatrix& k, const SectionMatrix& initial, SectionMatrix& f) {
  const int n = static_cast<int>(k.rows());
  Eigen::LDLT<SectionMatrix> ldlt(k);
  const auto d = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() == Eigen::Success && d.minCoeff() > 1e-12 * d.maxCoeff()) {
    f = ldlt.solve(SectionMatrix::Identity(n, n));
    return;
  }
  SectionMatrix regularized = k;
  regularized.diagonal() += 1e-9 * initial.diagonal().cwiseAbs();
  f = regularized.fullPivLu().solve(SectionMatrix::Identity(n, n));
}

}  // namespace

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
  const std::size_t n = sections_.size();
  interpolation_.clear();
  loadForces_.clear();
  flexibility_.clear();
  unbalance_.clear();
  Matrix3 F = Matrix3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const int order = sections_[i]->order();
    interpolation_.push_back(forceInterpolation(sections_[i]->codes(), xi_[i], length_));
    loadForces_.push_back(SectionVector::Zero(order));
    unbalance_.push_back(SectionVector::Zero(order));
    SectionMatrix f(order, order);
    sectionFlexibility(sections_[i]->initialTangent(), sections_[i]->initialTangent(), f);
    flexibility_.push_back(f);
    const Interpolation& b = interpolation_.back();
    F += weights_[i] * length_ * b.transpose() * f * b;
  }
  initialBasicStiffness_ = F.ldlt().solve(Matrix3::Identity());
  q_.setZero();
  kb_ = initialBasicStiffness_;
  solvedDeformation_.setZero();
  committedForce_.setZero();
  committedStiffness_ = kb_;
  committedDeformation_.setZero();
}

bool ForceBeamColumn2d::iterate(const Vector3& v) {
  const int n = numSections();
  double reference = 0.0;
  for (int iteration = 0;; ++iteration) {
    Matrix3 F = Matrix3::Zero();
    Vector3 compatible = Vector3::Zero();
    double sectionWork = 0.0;
    for (int i = 0; i < n; ++i) {
      const SectionForceDeformation2d& s = *sections_[i];
      const Interpolation& b = interpolation_[i];
      sectionFlexibility(s.tangent(), s.initialTangent(), flexibility_[i]);
      unbalance_[i] = b * q_ + loadForces_[i] - s.force();
      const SectionVector correction = flexibility_[i] * unbalance_[i];
      const double wL = weights_[i] * length_;
      F.noalias() += wL * b.transpose() * flexibility_[i] * b;
      compatible.noalias() += wL * b.transpose() * (s.deformation() + correction);
      sectionWork += wL * std::fabs(unbalance_[i].dot(correction));
    }
    const Eigen::LDLT<Matrix3> flexibility(F);
    if (flexibility.info() != Eigen::Success) return false;
    const Vector3 dv = v - compatible;
    const Vector3 dq = flexibility.solve(dv);
    const double work = std::fabs(dq.dot(dv)) + sectionWork;
    if (!std::isfinite(work)) return false;
    if (iteration == 0) reference = work;
    // The correction is applied before the test (as in OpenSees): the
    // element always follows a changed v, and the q it answers with carries
    // the last correction, so Newton keeps its quadratic rate. tol bounds the
    // work of the residuals itself (force x length in the model's units), as
    // OpenSees' tol; the ratio 1e-28 only ends iterations on round-off.
    ++lastIterations_;
    q_ += dq;
    for (int i = 0; i < n; ++i) {
      const SectionVector de = flexibility_[i] * (unbalance_[i] + interpolation_[i] * dq);
      sections_[i]->setTrialDeformation(sections_[i]->deformation() + de);
    }
    if (work <= options().tolerance || work <= 1e-28 * std::max(reference, std::fabs(q_.dot(v)))) {
      kb_ = flexibility.solve(Matrix3::Identity());
      return true;
    }
    if (iteration + 1 >= options().maxIterations) return false;
  }
}

void ForceBeamColumn2d::restoreCommitted() {
  for (auto& s : sections_) s->revertToLastCommit();
  q_ = committedForce_;
  kb_ = committedStiffness_;
}

void ForceBeamColumn2d::solveState(const Vector3& v) {
  lastIterations_ = 0;
  loadsChanged_ = false;
  solvedDeformation_ = v;
  converged_ = iterate(v);
  if (converged_) return;
  for (int substeps = 2; substeps <= 32 && !converged_; substeps *= 2) {
    restoreCommitted();
    converged_ = true;
    for (int k = 1; k <= substeps && converged_; ++k)
      converged_ = iterate(committedDeformation_ + (double(k) / substeps) * (v - committedDeformation_));
  }
  if (!converged_)
    throw ElementStateError(context() + ": element compatibility not reached (" +
                            std::to_string(options().maxIterations) + " iterations per substep, tol " +
                            std::to_string(options().tolerance) + ")");
}

void ForceBeamColumn2d::ensureState() {
  if (loadsChanged_) solveState(solvedDeformation_);
}

void ForceBeamColumn2d::update() {
  transf_->update();
  const Vector3 v = transf_->basicTrialDisp();
  // New element loads alone (v unchanged, as right after a load step is
  // applied) wait for the next change of v, as in OpenSees: the first
  // residual of a step then sees them through p0 only.
  if (converged_ && v == solvedDeformation_) return;
  solveState(v);
}

// As OpenSees, new element loads reach q at the next state determination
// (update()): until then the element answers with the forces it has, and
// only the basic system's reactions p0 follow the loads at once.
ForceBeamColumn2d::Vector3 ForceBeamColumn2d::basicForce() { return q_; }

const ForceBeamColumn2d::Matrix3& ForceBeamColumn2d::basicStiffness() { return kb_; }

ForceBeamColumn2d::Vector3 ForceBeamColumn2d::plasticDeformation() {
  // v minus the elastic deformations of the section forces b q + s_load:
  // an elastic element under element loads has none.
  Vector3 elastic = Vector3::Zero();
  for (int i = 0; i < numSections(); ++i) {
    const SectionForceDeformation2d& s = *sections_[i];
    SectionMatrix f(s.order(), s.order());
    sectionFlexibility(s.initialTangent(), s.initialTangent(), f);
    elastic += weights_[i] * length_ * interpolation_[i].transpose() * f * (interpolation_[i] * q_ + loadForces_[i]);
  }
  return basicDeformation() - elastic;
}

void ForceBeamColumn2d::commitState() {
  ensureState();
  transf_->commitState();
  for (auto& s : sections_) s->commitState();
  committedForce_ = q_;
  committedStiffness_ = kb_;
  committedDeformation_ = solvedDeformation_;
}

void ForceBeamColumn2d::revertToLastCommit() {
  transf_->revertToLastCommit();
  restoreCommitted();
  solvedDeformation_ = committedDeformation_;
  converged_ = true;
  loadsChanged_ = true;
}

void ForceBeamColumn2d::revertToStart() {
  transf_->revertToStart();
  for (auto& s : sections_) s->revertToStart();
  q_.setZero();
  kb_ = initialBasicStiffness_;
  solvedDeformation_.setZero();
  committedForce_.setZero();
  committedStiffness_ = kb_;
  committedDeformation_.setZero();
  converged_ = true;
  loadsChanged_ = true;
}

void ForceBeamColumn2d::zeroLoad() {
  zeroLoadReactions();
  for (SectionVector& s : loadForces_) {
    if (!s.isZero(0.0)) loadsChanged_ = true;
    s.setZero();
  }
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
    SectionVector& s = loadForces_[i];
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
  loadsChanged_ = true;
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
