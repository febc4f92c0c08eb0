#pragma once
#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <vector>

namespace beamsolid {

// The element state determination of the force-based beam-columns
// (ForceBeamColumn2d and ForceBeamColumn3d share it through their Traits):
// given basic deformations v, find basic forces q and section deformations e
// with equilibrium s(e) = b q + s_p (s_p: element loads) and compatibility
// v = sum w L b^T e, by the Newton iterations of Spacone, Filippou and Taucer
// (1996) in the form of Neuenhofer and Filippou (1997). The Traits say how
// a section's deformations, forces and tangents are read and set
// (Traits::force(section), ...), so one element can see more of a section
// than another (the 3D shear components).
//
// The order of the steps, the stopping rule and the fallbacks follow what
// OpenSees 3.7 does (found by black-box runs of OpenSeesPy, see
// docs/commands.md): one iteration is
//   q += dq;  e += fS (b q + s_p - s(e))  for every section;
//   F = sum w L b^T f b,  r = f (b q + s_p - s),  dv = v - sum w L b^T (e + r);
//   dq = F^-1 dv;  dW = |dv . dq|;
// and the element stops when dW < tol, after adding that last dq to q: the
// answer's q runs one correction ahead of its sections (so section forces
// differ from b q by the size of that correction) and the stiffness is F^-1
// of the last sections. The first dq is the previous stiffness times the
// change of v. fS is the sections' tangent flexibility (first attempt,
// maxIter iterations); if that fails the element starts again from where the
// update began with fS the sections' initial flexibility (10 maxIter
// iterations, the tangent still in F). If both fail it retries in 2, 4, ...,
// 32 substeps from that start; if nothing converges it keeps the state of
// the last attempt and reports it (OpenSees warns and goes on).
template <class Traits>
class ForceBeamCompatibility {
 public:
  using Section = typename Traits::Section;
  using SectionVector = typename Traits::SectionVector;
  using SectionMatrix = typename Traits::SectionMatrix;
  using Interpolation = typename Traits::Interpolation;
  static constexpr int kBasic = Traits::kBasic;
  using BasicVector = Eigen::Matrix<double, kBasic, 1>;
  using BasicMatrix = Eigen::Matrix<double, kBasic, kBasic>;
  using Sections = std::vector<std::unique_ptr<Section>>;

  // The sections (owned by the element), b(xi) of each, its weight times L,
  // and the iteration limits. Returns the initial basic stiffness.
  BasicMatrix initialize(Sections& sections, std::vector<Interpolation> interpolation, std::vector<double> weightLength,
                         int maxIterations, double tolerance) {
    sections_ = &sections;
    b_ = std::move(interpolation);
    wL_ = std::move(weightLength);
    maxIterations_ = maxIterations;
    tolerance_ = tolerance;
    const std::size_t n = sections.size();
    initialFlexibility_.clear();
    flexibility_.clear();
    loadForces_.clear();
    BasicMatrix F = BasicMatrix::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const SectionMatrix k0 = Traits::initialTangent(*sections[i]);
      SectionMatrix f0 = k0;
      invert(k0, k0, f0);
      initialFlexibility_.push_back(f0);
      flexibility_.push_back(f0);
      loadForces_.push_back(SectionVector::Zero(k0.rows()));
      F.noalias() += wL_[i] * b_[i].transpose() * f0 * b_[i];
    }
    initialStiffness_ = F.ldlt().solve(BasicMatrix::Identity());
    revertToStart();
    return initialStiffness_;
  }

  // Brings the element to v. Returns whether it converged.
  bool update(const BasicVector& v) {
    iterations_ = 0;
    loadsChanged_ = false;
    const BasicVector v0 = v_;
    const Snapshot start = snapshot();
    v_ = v;
    converged_ = attempts(v, v - v0, start);
    for (int substeps = 2; substeps <= 32 && !converged_; substeps *= 2) {
      restore(start);
      converged_ = true;
      BasicVector previous = v0;
      for (int k = 1; k <= substeps && converged_; ++k) {
        const BasicVector target = v0 + (double(k) / substeps) * (v - v0);
        converged_ = attempts(target, target - previous, snapshot());
        previous = target;
      }
    }
    return converged_;
  }

  // Element loads: the simply supported basic system's section forces.
  void zeroLoad() {
    for (SectionVector& s : loadForces_) {
      if (!s.isZero(0.0)) loadsChanged_ = true;
      s.setZero();
    }
  }
  // For addLoad: marks the loads changed.
  SectionVector& changeLoadForces(std::size_t section) {
    loadsChanged_ = true;
    return loadForces_[section];
  }
  const SectionVector& loadForces(std::size_t section) const { return loadForces_[section]; }
  bool loadsChanged() const { return loadsChanged_; }

  // v of the last update; whether it converged; its element iterations.
  const BasicVector& deformation() const { return v_; }
  bool converged() const { return converged_; }
  int iterations() const { return iterations_; }
  const BasicVector& force() const { return q_; }
  const BasicMatrix& stiffness() const { return kb_; }
  const BasicMatrix& initialStiffness() const { return initialStiffness_; }
  const SectionMatrix& initialFlexibility(std::size_t section) const { return initialFlexibility_[section]; }

  void commit() {
    committedForce_ = q_;
    committedStiffness_ = kb_;
    committedDeformation_ = v_;
  }
  // The sections are reverted by the element.
  void revertToLastCommit() {
    q_ = committedForce_;
    kb_ = committedStiffness_;
    v_ = committedDeformation_;
    converged_ = true;
    loadsChanged_ = true;
  }
  void revertToStart() {
    q_.setZero();
    kb_ = initialStiffness_;
    v_.setZero();
    commit();
    converged_ = true;
    loadsChanged_ = true;
  }

  // f = k^-1; a section that has lost all stiffness in some mode (every
  // fiber yielded) gets a tiny fraction of its initial stiffness there.
  static void invert(const SectionMatrix& k, const SectionMatrix& initial, SectionMatrix& f) {
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

 private:
  struct Snapshot {
    BasicVector q;
    BasicMatrix kb;
    std::vector<SectionVector> e;
  };
  Snapshot snapshot() const {
    Snapshot state{q_, kb_, {}};
    for (const auto& s : *sections_) state.e.push_back(Traits::deformation(*s));
    return state;
  }
  void restore(const Snapshot& state) {
    q_ = state.q;
    kb_ = state.kb;
    for (std::size_t i = 0; i < sections_->size(); ++i) Traits::setTrialDeformation(*(*sections_)[i], state.e[i]);
  }
  // The tangent attempt, then (from the same start) the initial-flexibility one.
  bool attempts(const BasicVector& v, const BasicVector& dv, const Snapshot& start) {
    if (attempt(v, dv, start.kb, maxIterations_, false)) return true;
    restore(start);
    return attempt(v, dv, start.kb, 10 * maxIterations_, true);
  }

  // Iterations towards v from the current state, the first correction being
  // k dv; the sections move with their tangent flexibility, or with the
  // initial one when `initialFlexibility`.
  bool attempt(const BasicVector& v, const BasicVector& dv, const BasicMatrix& k, int maxIterations,
               bool initialFlexibility) {
    Sections& sections = *sections_;
    const std::size_t n = sections.size();
    if (!initialFlexibility)
      for (std::size_t i = 0; i < n; ++i) invert(Traits::tangent(*sections[i]), Traits::initialTangent(*sections[i]), flexibility_[i]);
    BasicVector dq = k * dv;
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
      ++iterations_;
      q_ += dq;
      BasicMatrix F = BasicMatrix::Zero();
      BasicVector compatible = BasicVector::Zero();
      for (std::size_t i = 0; i < n; ++i) {
        Section& s = *sections[i];
        const SectionMatrix& fS = initialFlexibility ? initialFlexibility_[i] : flexibility_[i];
        const SectionVector unbalance = b_[i] * q_ + loadForces_[i] - Traits::force(s);
        Traits::setTrialDeformation(s, Traits::deformation(s) + fS * unbalance);
        invert(Traits::tangent(s), Traits::initialTangent(s), flexibility_[i]);
        const SectionVector residual = b_[i] * q_ + loadForces_[i] - Traits::force(s);
        F.noalias() += wL_[i] * b_[i].transpose() * flexibility_[i] * b_[i];
        compatible.noalias() += wL_[i] * b_[i].transpose() * (Traits::deformation(s) + flexibility_[i] * residual);
      }
      const Eigen::LDLT<BasicMatrix> flexibility(F);
      if (flexibility.info() != Eigen::Success) return false;
      kb_ = flexibility.solve(BasicMatrix::Identity());
      const BasicVector dvr = v - compatible;
      dq = kb_ * dvr;
      const double work = std::fabs(dvr.dot(dq));
      if (!std::isfinite(work)) return false;
      if (work < tolerance_) {
        q_ += dq;
        return true;
      }
    }
    return false;
  }

  Sections* sections_ = nullptr;
  std::vector<Interpolation> b_;
  std::vector<double> wL_;
  int maxIterations_ = 10;
  double tolerance_ = 1e-12;

  std::vector<SectionMatrix> initialFlexibility_;
  std::vector<SectionMatrix> flexibility_;  // tangent flexibility of the sections' current state
  std::vector<SectionVector> loadForces_;

  BasicVector q_ = BasicVector::Zero();
  BasicMatrix kb_ = BasicMatrix::Zero();
  BasicVector v_ = BasicVector::Zero();
  BasicMatrix initialStiffness_ = BasicMatrix::Zero();
  BasicVector committedForce_ = BasicVector::Zero();
  BasicMatrix committedStiffness_ = BasicMatrix::Zero();
  BasicVector committedDeformation_ = BasicVector::Zero();
  bool converged_ = true;
  bool loadsChanged_ = false;
  int iterations_ = 0;
};

}  // namespace beamsolid
