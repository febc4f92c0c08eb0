#include "elements/ForceBeamColumn3d.h"

#include "core/ElementStateError.h"

#include <cmath>
#include <iostream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Registry.h"
#include "elements/ForceBeamColumn2d.h"

namespace beamsolid {

namespace {

using Matrix4 = SectionForceDeformation::Matrix4;

// f = ks^-1. A section that has lost all stiffness in some mode (every fiber
// yielded) gets a tiny fraction of its initial stiffness there, so the
// element stays flexible instead of singular.
void sectionFlexibility(const Matrix4& k, const Matrix4& initial, Matrix4& f) {
  Eigen::LDLT<Matrix4> ldlt(k);
  const auto d = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() == Eigen::Success && d.minCoeff() > 1e-12 * d.maxCoeff()) {
    f = ldlt.solve(Matrix4::Identity());
    return;
  }
  Matrix4 regularized = k;
  regularized.diagonal() += 1e-9 * initial.diagonal().cwiseAbs();
  f = regularized.fullPivLu().solve(Matrix4::Identity());
}

}  // namespace

ForceBeamColumn3d::ForceBeamColumn3d(int tag, Definition&& definition)
    : SectionBeamColumn3d(tag, std::move(definition)) {}

Eigen::Matrix<double, 4, 6> ForceBeamColumn3d::forceInterpolation(double xi) {
  Eigen::Matrix<double, 4, 6> b = Eigen::Matrix<double, 4, 6>::Zero();
  b(0, 0) = 1.0;
  b(1, 1) = b(2, 3) = xi - 1.0;
  b(1, 2) = b(2, 4) = xi;
  b(3, 5) = 1.0;
  return b;
}

void ForceBeamColumn3d::initializeState() {
  const std::size_t n = sections_.size();
  loadForces_.assign(n, Vector4::Zero());
  flexibility_.assign(n, Matrix4::Zero());
  unbalance_.assign(n, Vector4::Zero());
  Matrix6 F = Matrix6::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    Matrix4 f;
    sectionFlexibility(sections_[i]->initialTangent(), sections_[i]->initialTangent(), f);
    const Eigen::Matrix<double, 4, 6> b = forceInterpolation(xi_[i]);
    F += weights_[i] * length_ * b.transpose() * f * b;
  }
  initialBasicStiffness_ = F.ldlt().solve(Matrix6::Identity());
  q_.setZero();
  kb_ = initialBasicStiffness_;
  solvedDeformation_.setZero();
  committedForce_.setZero();
  committedStiffness_ = kb_;
  committedDeformation_.setZero();
}

bool ForceBeamColumn3d::iterate(const Vector6& v) {
  const int n = numSections();
  double reference = 0.0;
  for (int iteration = 0;; ++iteration) {
    Matrix6 F = Matrix6::Zero();
    Vector6 compatible = Vector6::Zero();
    double sectionWork = 0.0;
    for (int i = 0; i < n; ++i) {
      const SectionForceDeformation& s = *sections_[i];
      sectionFlexibility(s.tangent(), s.initialTangent(), flexibility_[i]);
      const Eigen::Matrix<double, 4, 6> b = forceInterpolation(xi_[i]);
      unbalance_[i] = b * q_ + loadForces_[i] - s.force();
      const Vector4 correction = flexibility_[i] * unbalance_[i];
      const double wL = weights_[i] * length_;
      F.noalias() += wL * b.transpose() * flexibility_[i] * b;
      compatible.noalias() += wL * b.transpose() * (s.deformation() + correction);
      sectionWork += wL * std::fabs(unbalance_[i].dot(correction));
    }
    const Eigen::LDLT<Matrix6> flexibility(F);
    if (flexibility.info() != Eigen::Success) return false;
    const Vector6 dv = v - compatible;
    const Vector6 dq = flexibility.solve(dv);
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
      const Vector4 de = flexibility_[i] * (unbalance_[i] + forceInterpolation(xi_[i]) * dq);
      sections_[i]->setTrialDeformation(sections_[i]->deformation() + de);
    }
    if (work <= options().tolerance || work <= 1e-28 * std::max(reference, std::fabs(q_.dot(v)))) {
      kb_ = flexibility.solve(Matrix6::Identity());
      return true;
    }
    if (iteration + 1 >= options().maxIterations) return false;
  }
}

void ForceBeamColumn3d::restoreCommitted() {
  for (auto& s : sections_) s->revertToLastCommit();
  q_ = committedForce_;
  kb_ = committedStiffness_;
}

void ForceBeamColumn3d::solveState(const Vector6& v) {
  lastIterations_ = 0;
  loadsChanged_ = false;
  solvedDeformation_ = v;
  converged_ = iterate(v);
  if (converged_) return;
  // From the committed state in ever smaller substeps.
  for (int substeps = 2; substeps <= 32 && !converged_; substeps *= 2) {
    restoreCommitted();
    converged_ = true;
    for (int k = 1; k <= substeps && converged_; ++k)
      converged_ = iterate(committedDeformation_ + (double(k) / substeps) * (v - committedDeformation_));
  }
  // A step the element cannot follow fails, as in OpenSees: the analysis
  // reverts and returns a negative code so the script can cut the step.
  if (!converged_)
    throw ElementStateError(context() + ": element compatibility not reached (" +
                            std::to_string(options().maxIterations) + " iterations per substep, tol " +
                            std::to_string(options().tolerance) + ")");
}

void ForceBeamColumn3d::ensureState() {
  if (loadsChanged_) solveState(solvedDeformation_);
}

void ForceBeamColumn3d::update() {
  transf_->update();
  const Vector6 v = transf_->basicTrialDisp();
  // New element loads alone (v unchanged, as right after a load step is
  // applied) wait for the next change of v, as in OpenSees: the first
  // residual of a step then sees them through p0 only.
  if (converged_ && v == solvedDeformation_) return;
  solveState(v);
}

ForceBeamColumn3d::Vector6 ForceBeamColumn3d::basicForce() {
  ensureState();
  return q_;
}

const ForceBeamColumn3d::Matrix6& ForceBeamColumn3d::basicStiffness() {
  ensureState();
  return kb_;
}

ForceBeamColumn3d::Vector6 ForceBeamColumn3d::plasticDeformation() {
  // v minus the elastic deformations of the section forces b q + s_load:
  // an elastic element under element loads has none (as OpenSees).
  Vector6 elastic = Vector6::Zero();
  Matrix4 f;
  for (int i = 0; i < numSections(); ++i) {
    const SectionForceDeformation& s = *sections_[i];
    sectionFlexibility(s.initialTangent(), s.initialTangent(), f);
    const Eigen::Matrix<double, 4, 6> b = forceInterpolation(xi_[i]);
    elastic += weights_[i] * length_ * b.transpose() * f * (b * q_ + loadForces_[i]);
  }
  return basicDeformation() - elastic;
}

void ForceBeamColumn3d::commitState() {
  ensureState();
  transf_->commitState();
  for (auto& s : sections_) s->commitState();
  committedForce_ = q_;
  committedStiffness_ = kb_;
  committedDeformation_ = solvedDeformation_;
}

void ForceBeamColumn3d::revertToLastCommit() {
  transf_->revertToLastCommit();
  restoreCommitted();
  solvedDeformation_ = committedDeformation_;
  converged_ = true;
  // The loads may be those of the abandoned step: check against them.
  loadsChanged_ = true;
}

void ForceBeamColumn3d::revertToStart() {
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

void ForceBeamColumn3d::zeroLoad() {
  zeroLoadReactions();
  for (Vector4& s : loadForces_) {
    if (!s.isZero(0.0)) loadsChanged_ = true;
    s.setZero();
  }
}

void ForceBeamColumn3d::addLoad(const ElementLoad& load, double factor) {
  const BeamLoad l = readLoad(load, factor);
  addLoadReactions(l);
  const double L = length_;
  // Section forces of the simply supported basic system (axially held at I):
  // Mz = -w x (L - x) / 2 for a load along +y (v'' < 0), My = +w x (L - x) / 2 along +z.
  for (int i = 0; i < numSections(); ++i) {
    const double x = xi_[i] * L;
    Vector4& s = loadForces_[i];
    if (l.uniform) {
      s[0] += l.wx * (L - x);
      s[1] -= 0.5 * l.wy * x * (L - x);
      s[2] += 0.5 * l.wz * x * (L - x);
    } else {
      const double influence = x <= l.a ? x * (L - l.a) / L : l.a * (L - x) / L;
      if (x < l.a) s[0] += l.px;
      s[1] -= l.py * influence;
      s[2] += l.pz * influence;
    }
  }
  loadsChanged_ = true;
}

namespace {

std::unique_ptr<Element> buildForceBeamColumn3d(CommandArgs& args, Domain& domain, const std::string& type) {
  if (domain.spaceDim() == 2) return ForceBeamColumn2d::build(args, domain, type);
  auto d = SectionBeamColumn3d::parse(args, domain, type, BeamIntegration::Rule::Lobatto, true);
  // OpenSees' force-based element takes '-cMass' but keeps its mass lumped
  // (checked against OpenSeesPy, as in 2D).
  d.options.consistentMass = false;
  const int tag = d.tag;
  return std::make_unique<ForceBeamColumn3d>(tag, std::move(d));
}

void registerForceBeamColumn3d(Registry& r) {
  r.elements.add("forceBeamColumn", [](CommandArgs& args, Domain& domain) {
    return buildForceBeamColumn3d(args, domain, "forceBeamColumn");
  });
  r.elements.add("nonlinearBeamColumn", [](CommandArgs& args, Domain& domain) {
    return buildForceBeamColumn3d(args, domain, "nonlinearBeamColumn");
  });
}

}  // namespace

BEAMSOLID_REGISTER(registerForceBeamColumn3d);

}  // namespace beamsolid
