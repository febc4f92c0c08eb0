#include "analysis/Newmark.h"

#include <cmath>
#include <memory>

#include "core/Domain.h"
#include "core/Registry.h"

namespace beamsolid {

Newmark::Newmark(double gamma, double beta, Form form, double alpha, std::string name, double alphaM)
    : gamma_(gamma), beta_(beta), alpha_(alpha), alphaM_(alphaM), form_(form), name_(std::move(name)) {}

void Newmark::setNode(const AnalysisModel& model, int f) const {
  const DofMap& map = model.dofMap();
  const double u = alpha_ == 1.0 ? u1_[f] : (1.0 - alpha_) * un_[f] + alpha_ * u1_[f];
  const double v = alpha_ == 1.0 ? v1_[f] : (1.0 - alpha_) * vn_[f] + alpha_ * v1_[f];
  const double a = alphaM_ == 1.0 ? a1_[f] : (1.0 - alphaM_) * an_[f] + alphaM_ * a1_[f];
  map.nodeOfFull(f)->setTrialResponse(map.dofOfFull(f), u, v, a);
}

int Newmark::newStep(AnalysisModel& model) {
  if (dt_ <= 0.0 || beta_ == 0.0 || gamma_ == 0.0) return -1;
  const double dt = dt_;
  // d(U, V, A)_n+1 / dx for the chosen unknown x (from v = c dU, a = c' dU).
  switch (form_) {
    case Form::D: cu_ = 1.0, cv_ = gamma_ / (beta_ * dt), ca_ = 1.0 / (beta_ * dt * dt); break;
    case Form::V: cu_ = beta_ * dt / gamma_, cv_ = 1.0, ca_ = 1.0 / (gamma_ * dt); break;
    case Form::A: cu_ = beta_ * dt * dt, cv_ = gamma_ * dt, ca_ = 1.0; break;
  }
  cK_ = alpha_ * cu_, cC_ = alpha_ * cv_, cM_ = alphaM_ * ca_;
  const DofMap& map = model.dofMap();
  const int n = map.numFullDofs();
  un_.resize(n), vn_.resize(n), an_.resize(n), u1_.resize(n), v1_.resize(n), a1_.resize(n);
  // Predictor: U_n+1 = U_n, and V, A from the Newmark relations with it.
  for (int f = 0; f < n; ++f) {
    const Node& node = *map.nodeOfFull(f);
    const int d = map.dofOfFull(f);
    const double u = node.committedDisp()[d], v = node.committedVel()[d], a = node.committedAccel()[d];
    un_[f] = u1_[f] = u;
    vn_[f] = v;
    an_[f] = a;
    v1_[f] = (1.0 - gamma_ / beta_) * v + dt * (1.0 - 0.5 * gamma_ / beta_) * a;
    a1_[f] = -v / (beta_ * dt) + (1.0 - 0.5 / beta_) * a;
    setNode(model, f);
  }
  Domain& domain = model.domain();
  timeAtStart_ = domain.currentTime();
  domain.applyLoad(timeAtStart_ + alpha_ * dt);
  model.enforcePrescribed();
  domain.update();
  return 0;
}

int Newmark::update(AnalysisModel& model, const Vector& x) {
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f) {
    double dx = 0.0;
    for (auto* t = map.fullTermsBegin(f); t != map.fullTermsEnd(f); ++t) dx += t->coefficient * x[t->equation];
    if (dx == 0.0) continue;
    u1_[f] += cu_ * dx;
    v1_[f] += cv_ * dx;
    a1_[f] += ca_ * dx;
    setNode(model, f);
  }
  model.domain().update();
  return 0;
}

void Newmark::commit(AnalysisModel& model, int) {
  if (alpha_ == 1.0 && alphaM_ == 1.0) return;
  // HHT / generalized alpha converged at the alpha-state: the domain commits the n+1 state.
  const DofMap& map = model.dofMap();
  for (int f = 0; f < map.numFullDofs(); ++f)
    map.nodeOfFull(f)->setTrialResponse(map.dofOfFull(f), u1_[f], v1_[f], a1_[f]);
  Domain& domain = model.domain();
  domain.applyLoad(timeAtStart_ + dt_);
  model.enforcePrescribed();
  domain.update();
}

namespace {
Newmark::Form readForm(CommandArgs& args) {
  const std::string opt = args.nextString("option");
  if (opt != "-form") args.fail("unknown option '" + opt + "' (expected -form)");
  const std::string f = args.nextString("form");
  if (f == "D" || f == "d") return Newmark::Form::D;
  if (f == "V" || f == "v") return Newmark::Form::V;
  if (f == "A" || f == "a") return Newmark::Form::A;
  args.fail("form must be D, V or A, got '" + f + "'");
  return Newmark::Form::D;
}

std::unique_ptr<Integrator> buildNewmark(CommandArgs& args, Domain&) {
  const double gamma = args.nextDouble("gamma");
  const double beta = args.nextDouble("beta");
  if (gamma <= 0.0) args.fail("gamma must be positive");
  if (beta <= 0.0) args.fail("beta must be positive (explicit Newmark: use CentralDifference)");
  Newmark::Form form = Newmark::Form::D;
  if (!args.done()) form = readForm(args);
  args.expectEnd();
  return std::make_unique<Newmark>(gamma, beta, form);
}

// HHT alpha <gamma beta>: defaults gamma = 3/2 - alpha, beta = (2 - alpha)^2 / 4
// (second order, unconditionally stable for 2/3 <= alpha <= 1).
std::unique_ptr<Integrator> buildHHT(CommandArgs& args, Domain&) {
  const double alpha = args.nextDouble("alpha");
  if (alpha <= 0.0 || alpha > 1.0) args.fail("alpha must be in (0, 1] (2/3 <= alpha <= 1 is stable), got " +
                                             std::to_string(alpha));
  double gamma = 1.5 - alpha, beta = 0.25 * (2.0 - alpha) * (2.0 - alpha);
  if (!args.done()) {
    gamma = args.nextDouble("gamma");
    beta = args.nextDouble("beta");
    if (gamma <= 0.0 || beta <= 0.0) args.fail("gamma and beta must be positive");
  }
  args.expectEnd();
  return std::make_unique<Newmark>(gamma, beta, Newmark::Form::D, alpha, "HHT");
}

// GeneralizedAlpha alphaM alphaF <gamma beta>: defaults gamma = 1/2 + alphaM -
// alphaF, beta = (1 + alphaM - alphaF)^2 / 4 (second order; unconditionally
// stable for alphaM >= alphaF >= 1/2).
std::unique_ptr<Integrator> buildGeneralizedAlpha(CommandArgs& args, Domain&) {
  const std::size_t atM = args.position();
  const double alphaM = args.nextDouble("alphaM");
  const std::size_t atF = args.position();
  const double alphaF = args.nextDouble("alphaF");
  if (!(alphaM > 0.0) || !std::isfinite(alphaM)) args.failAt(atM, "alphaM", "a positive number (alphaM = 1: HHT)");
  if (!(alphaF > 0.0 && alphaF <= 1.0)) args.failAt(atF, "alphaF", "a number in (0, 1] (alphaF = 1: no force averaging)");
  double gamma = 0.5 + alphaM - alphaF, beta = 0.25 * (1.0 + alphaM - alphaF) * (1.0 + alphaM - alphaF);
  if (!args.done()) {
    gamma = args.nextDouble("gamma");
    beta = args.nextDouble("beta");
  }
  args.expectEnd();
  if (!(gamma > 0.0) || !(beta > 0.0)) args.fail("gamma and beta must be positive");
  return std::make_unique<Newmark>(gamma, beta, Newmark::Form::D, alphaF, "GeneralizedAlpha", alphaM);
}

// HHTGeneralized alphaI alphaF <beta gamma>: OpenSees' name for the same
// method with alphaI = alphaM, and beta before gamma.
std::unique_ptr<Integrator> buildHHTGeneralized(CommandArgs& args, Domain&) {
  const std::size_t atI = args.position();
  const double alphaI = args.nextDouble("alphaI");
  const std::size_t atF = args.position();
  const double alphaF = args.nextDouble("alphaF");
  if (!(alphaI > 0.0) || !std::isfinite(alphaI)) args.failAt(atI, "alphaI", "a positive number (alphaI = 1: HHT)");
  if (!(alphaF > 0.0 && alphaF <= 1.0)) args.failAt(atF, "alphaF", "a number in (0, 1] (alphaF = 1: no force averaging)");
  double beta = 0.25 * (1.0 + alphaI - alphaF) * (1.0 + alphaI - alphaF), gamma = 0.5 + alphaI - alphaF;
  if (!args.done()) {
    beta = args.nextDouble("beta");
    gamma = args.nextDouble("gamma");
  }
  args.expectEnd();
  if (!(gamma > 0.0) || !(beta > 0.0)) args.fail("beta and gamma must be positive");
  return std::make_unique<Newmark>(gamma, beta, Newmark::Form::D, alphaF, "HHTGeneralized", alphaI);
}

void registerNewmark(Registry& r) {
  r.integrators.add("HHTGeneralized", &buildHHTGeneralized);
  r.integrators.add("GeneralizedAlpha", &buildGeneralizedAlpha);
  r.integrators.add("Newmark", &buildNewmark);
  r.integrators.add("HHT", &buildHHT);
}
}  // namespace
BEAMSOLID_REGISTER(registerNewmark);

}  // namespace beamsolid
