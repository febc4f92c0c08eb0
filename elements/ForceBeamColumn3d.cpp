#include "elements/ForceBeamColumn3d.h"

#include <cmath>
#include <iostream>
#include <variant>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/ForceBeamColumn2d.h"

namespace beamsolid {

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

ForceBeamTraits3dShear::Interpolation ForceBeamColumn3d::forceInterpolation(const SectionForceDeformation& section,
                                                                          double xi, double L) {
  const int shear = section.numShear();
  ForceBeamTraits3dShear::Interpolation b = ForceBeamTraits3dShear::Interpolation::Zero(4 + shear, 6);
  b.topRows<4>() = forceInterpolation(xi);
  for (int k = 0; k < shear; ++k) {
    // V = dM/dx of the linear moment of the same plane.
    const int first = section.shearCode(k) == SectionCode::Vy ? 1 : 3;
    b(4 + k, first) = b(4 + k, first + 1) = 1.0 / L;
  }
  return b;
}

void ForceBeamColumn3d::initializeState() {
  shear_ = false;
  for (const auto& s : sections_) shear_ = shear_ || s->numShear() > 0;
  std::vector<double> weightLength;
  for (std::size_t i = 0; i < sections_.size(); ++i) weightLength.push_back(weights_[i] * length_);
  if (shear_) {
    std::vector<ForceBeamTraits3dShear::Interpolation> interpolation;
    for (std::size_t i = 0; i < sections_.size(); ++i)
      interpolation.push_back(forceInterpolation(*sections_[i], xi_[i], length_));
    initialBasicStiffness_ = shearState_.initialize(sections_, std::move(interpolation), std::move(weightLength),
                                                    options().maxIterations, options().tolerance);
    return;
  }
  std::vector<ForceBeamTraits3d::Interpolation> interpolation;
  for (std::size_t i = 0; i < sections_.size(); ++i) interpolation.push_back(forceInterpolation(xi_[i]));
  initialBasicStiffness_ = state_.initialize(sections_, std::move(interpolation), std::move(weightLength),
                                             options().maxIterations, options().tolerance);
}

void ForceBeamColumn3d::solveState(const Vector6& v) {
  // As OpenSees, an element that cannot reach compatibility warns and keeps
  // the state of its last attempt; the global iterations go on from it.
  if (!withState([&](auto& state) { return state.update(v); }))
    std::cerr << "WARNING " << context() << ": element compatibility not reached (" << options().maxIterations
              << " iterations, tol " << options().tolerance << "); going on with the last state\n";
}

void ForceBeamColumn3d::ensureState() {
  withState([&](auto& state) {
    if (state.loadsChanged()) solveState(state.deformation());
  });
}

void ForceBeamColumn3d::update() {
  transf_->update();
  const Vector6 v = transf_->basicTrialDisp();
  // An unchanged v leaves the element as it is, as in OpenSees; new element
  // loads alone (as right after a load step is applied) wait for the next
  // change of v: the first residual of a step sees them through p0 only.
  if (withState([&](auto& state) { return v == state.deformation(); })) return;
  solveState(v);
}

// As OpenSees (and the 2D element), new element loads reach q at the next
// state determination; until then only the basic system's reactions p0 follow them.
ForceBeamColumn3d::Vector6 ForceBeamColumn3d::basicForce() {
  return withState([](auto& state) -> Vector6 { return state.force(); });
}

const ForceBeamColumn3d::Matrix6& ForceBeamColumn3d::basicStiffness() {
  return withState([](auto& state) -> const Matrix6& { return state.stiffness(); });
}

ForceBeamColumn3d::Vector6 ForceBeamColumn3d::plasticDeformation() {
  // v minus the elastic deformations of the section forces b q + s_load:
  // an elastic element under element loads has none (as OpenSees).
  Vector6 elastic = Vector6::Zero();
  if (shear_) {
    for (int i = 0; i < numSections(); ++i) {
      const auto b = forceInterpolation(*sections_[i], xi_[i], length_);
      elastic += weights_[i] * length_ * b.transpose() * shearState_.initialFlexibility(i) *
                 (b * shearState_.force() + shearState_.loadForces(std::size_t(i)));
    }
  } else {
    for (int i = 0; i < numSections(); ++i) {
      const Eigen::Matrix<double, 4, 6> b = forceInterpolation(xi_[i]);
      elastic += weights_[i] * length_ * b.transpose() * state_.initialFlexibility(i) *
                 (b * state_.force() + state_.loadForces(std::size_t(i)));
    }
  }
  return basicDeformation() - elastic;
}

void ForceBeamColumn3d::commitState() {
  ensureState();
  transf_->commitState();
  for (auto& s : sections_) s->commitState();
  withState([](auto& state) { state.commit(); });
}

void ForceBeamColumn3d::revertToLastCommit() {
  transf_->revertToLastCommit();
  for (auto& s : sections_) s->revertToLastCommit();
  withState([](auto& state) { state.revertToLastCommit(); });
}

void ForceBeamColumn3d::revertToStart() {
  transf_->revertToStart();
  for (auto& s : sections_) s->revertToStart();
  withState([](auto& state) { state.revertToStart(); });
}

void ForceBeamColumn3d::zeroLoad() {
  zeroLoadReactions();
  withState([](auto& state) { state.zeroLoad(); });
}

void ForceBeamColumn3d::addLoad(const ElementLoad& load, double factor) {
  const BeamLoad l = readLoad(load, factor);
  addLoadReactions(l);
  const double L = length_;
  // Section forces of the simply supported basic system (axially held at I):
  // Mz = -w x (L - x) / 2 for a load along +y (v'' < 0), My = +w x (L - x) / 2
  // along +z, and the shears V = dM/dx.
  withState([&](auto& state) {
    for (int i = 0; i < numSections(); ++i) {
      const double x = xi_[i] * L;
      auto& s = state.changeLoadForces(std::size_t(i));
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
      for (int k = 0; k < static_cast<int>(s.size()) - 4; ++k) {
        const bool y = sections_[i]->shearCode(k) == SectionCode::Vy;
        // d(influence)/dx: (L - a)/L before the load, -a/L after it.
        const double slope = l.uniform ? 0.0 : (x <= l.a ? (L - l.a) / L : -l.a / L);
        if (y) s[4 + k] += l.uniform ? l.wy * (x - 0.5 * L) : -l.py * slope;
        else s[4 + k] += l.uniform ? l.wz * (0.5 * L - x) : l.pz * slope;
      }
    }
  });
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

// element('mixedBeamColumn', tag, i, j, transfTag, integrationTag, <'-mass', m>, <'-doRayleigh', 1>):
// OpenSees' mixed (Hellinger-Reissner) beam. Without '-geomNonlinear' it reaches the force-based
// element's state iteration by iteration: OpenSeesPy 3.7.1 gives the same load factors,
// displacements and local forces (to 1e-15) and the same Newton iteration counts for Linear,
// PDelta and Corotational transformations, fiber sections that yield, element loads, 2D and 3D,
// and the same lumped mass (eigenvalues to 1e-15). So it is the force-based element here.
// As OpenSees, only the (transfTag, integrationTag) form; other options ('-iter', '-cMass',
// '-orient', ...) are ignored with a warning.
std::unique_ptr<Element> buildMixedBeamColumn(CommandArgs& args, Domain& domain) {
  using Value = CommandArgs::Value;
  const std::size_t start = args.position();
  std::vector<Value> kept;
  std::size_t at = start;
  auto isString = [&](std::size_t i) { return std::holds_alternative<std::string>(args.at(i)); };
  while (at < args.size() && !isString(at)) kept.push_back(args.at(at++));
  const std::string context =
      "element mixedBeamColumn" + (kept.empty() ? std::string() : " " + CommandArgs::describe(kept.front()));
  if (kept.size() != 5)
    throw OpenSeesError(context + ": expected eleTag, iNode, jNode, transfTag, integrationTag (got " +
                        std::to_string(kept.size()) + " numbers before the options); OpenSees' mixedBeamColumn "
                        "has no (numIntgrPts, secTag, transfTag) form");
  while (at < args.size()) {
    const std::string option = std::get<std::string>(args.at(at++));
    if (option == "-mass") {
      kept.push_back(option);
      if (at < args.size()) kept.push_back(args.at(at++));
    } else if (option == "-doRayleigh") {
      // Rayleigh damping is on by default; 0 (off) is not available for this element here.
      if (at < args.size() && !isString(at)) {
        const Value& flag = args.at(at++);
        const double v = std::holds_alternative<long long>(flag) ? double(std::get<long long>(flag))
                                                                 : std::get<double>(flag);
        if (v == 0.0) throw OpenSeesError(context + ": '-doRayleigh 0' is not available (its Rayleigh damping is on)");
      }
    } else if (option == "-geomNonlinear") {
      throw OpenSeesError(context + ": '-geomNonlinear' (the mixed formulation's internal P-small-delta) is not "
                          "built; use a PDelta or Corotational geomTransf");
    } else {
      std::cerr << "WARNING " << context << " - unknown option " << option << " ignored, as OpenSees ignores it\n";
      while (at < args.size() && !isString(at)) ++at;
    }
  }
  CommandArgs filtered(args.command(), std::move(kept));
  return buildForceBeamColumn3d(filtered, domain, "mixedBeamColumn");
}

void registerForceBeamColumn3d(Registry& r) {
  r.elements.add("forceBeamColumn", [](CommandArgs& args, Domain& domain) {
    return buildForceBeamColumn3d(args, domain, "forceBeamColumn");
  });
  r.elements.add("nonlinearBeamColumn", [](CommandArgs& args, Domain& domain) {
    return buildForceBeamColumn3d(args, domain, "nonlinearBeamColumn");
  });
  r.elements.add("mixedBeamColumn", buildMixedBeamColumn);
}

}  // namespace

BEAMSOLID_REGISTER(registerForceBeamColumn3d);

}  // namespace beamsolid
