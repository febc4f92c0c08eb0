#include "analysis/NewtonLineSearch.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "analysis/AnalysisModel.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "core/Registry.h"

namespace beamsolid {

int NewtonLineSearch::move(AnalysisModel& model, Integrator& integrator, const Vector& step, Vector& total) {
  // Path-following integrators replace x by the increment they really
  // applied (with their load-factor share); others leave it as given.
  Vector& x = model.system().x();
  x = step;
  if (integrator.update(model, x) < 0) return -1;
  total += x;
  integrator.formUnbalance(model);
  return 0;
}

int NewtonLineSearch::search(AnalysisModel& model, Integrator& integrator, const Vector& direction, double s0,
                             double s1, Vector& total) {
  const Options& o = options_;
  const Vector& residual = model.system().b();
  double eta = 1.0, s = s1;
  double etaPrevious = 0.0, sPrevious = s0;  // Secant: the point before
  // RegulaFalsi/Bisection: two points, a bracket once their signs differ.
  double a = 0.0, sa = s0, b = 1.0, sb = s1;
  for (int j = 0; j < o.maxIterations; ++j) {
    if (std::fabs(s) <= o.tolerance * std::fabs(s0)) break;
    const bool bracketed = (sa < 0.0) != (sb < 0.0);
    double next = eta;
    switch (o.search) {
      case Search::InitialInterpolated: next = eta * s0 / (s0 - s); break;
      case Search::Secant: next = eta - s * (eta - etaPrevious) / (s - sPrevious); break;
      case Search::RegulaFalsi: next = b - sb * (b - a) / (sb - sa); break;
      case Search::Bisection: next = bracketed ? 0.5 * (a + b) : 2.0 * b; break;
    }
    if (!std::isfinite(next)) break;
    next = std::clamp(next, o.minEta, o.maxEta);
    if (next == eta) break;
    if (move(model, integrator, (next - eta) * direction, total) < 0) return -1;
    ++evaluations_;
    const double sNext = direction.dot(residual);
    if (!std::isfinite(sNext)) break;
    etaPrevious = eta;
    sPrevious = s;
    eta = next;
    s = sNext;
    if (bracketed) {
      // Keep the sign change: replace the end with the same sign.
      if ((s < 0.0) == (sa < 0.0)) {
        a = eta;
        sa = s;
      } else {
        b = eta;
        sb = s;
      }
    } else {
      // No sign change yet: move on with the last two points.
      a = b;
      sa = sb;
      b = eta;
      sb = s;
    }
  }
  return 0;
}

int NewtonLineSearch::solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) {
  singular_ = false;
  lastError_.clear();
  evaluations_ = 0;
  LinearSystem& system = model.system();
  integrator.formUnbalance(model);
  test.start(system);
  Vector direction, total;
  for (;;) {
    if (!formAndFactor(model, integrator, false)) return -3;
    system.solve();
    direction = system.x();
    const double s0 = direction.dot(system.b());
    total = Vector::Zero(direction.size());
    if (move(model, integrator, direction, total) < 0) {
      lastError_ = "the integrator could not update the step";
      return -3;
    }
    const double s1 = direction.dot(system.b());
    if (s0 != 0.0 && std::isfinite(s1) && std::fabs(s1) > options_.tolerance * std::fabs(s0) &&
        search(model, integrator, direction, s0, s1, total) < 0) {
      lastError_ = "the integrator could not update the step during the line search";
      return -3;
    }
    system.x() = total;  // the increment of this iteration, for the test
    switch (test.test(system)) {
      case ConvergenceTest::Result::Converged: return 0;
      case ConvergenceTest::Result::Failed: return notConverged(test);
      case ConvergenceTest::Result::Continue: break;
    }
  }
}

namespace {

bool parseSearchType(const std::string& type, NewtonLineSearch::Search& out) {
  using T = NewtonLineSearch::Search;
  if (type == "InitialInterpolated") out = T::InitialInterpolated;
  else if (type == "Secant") out = T::Secant;
  else if (type == "RegulaFalsi") out = T::RegulaFalsi;
  else if (type == "Bisection") out = T::Bisection;
  else return false;
  return true;
}

std::unique_ptr<Algorithm> buildNewtonLineSearch(CommandArgs& args, Domain&) {
  NewtonLineSearch::Options o;
  // The old form algorithm('NewtonLineSearch', ratio) gives the tolerance alone.
  if (!args.done() && !args.nextIsString()) o.tolerance = args.nextDouble("ratio");
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-type") {
      const std::string type = args.nextString("type");
      if (!parseSearchType(type, o.search))
        args.fail("-type '" + type + "' is unknown (expected Bisection, Secant, RegulaFalsi or InitialInterpolated)");
    } else if (opt == "-tol") {
      o.tolerance = args.nextDouble("tol");
    } else if (opt == "-maxIter") {
      o.maxIterations = args.nextInt("maxIter");
    } else if (opt == "-minEta") {
      o.minEta = args.nextDouble("minEta");
    } else if (opt == "-maxEta") {
      o.maxEta = args.nextDouble("maxEta");
    } else if (!parseSearchType(opt, o.search)) {  // the type may also come without '-type'
      args.fail("unknown option '" + opt + "' (expected -type, -tol, -maxIter, -minEta or -maxEta)");
    }
  }
  if (!(o.tolerance > 0.0)) args.fail("-tol must be positive");
  if (o.maxIterations < 0) args.fail("-maxIter must be non-negative");
  if (!(o.minEta > 0.0) || !(o.maxEta >= o.minEta)) args.fail("expected 0 < minEta <= maxEta");
  return std::make_unique<NewtonLineSearch>(o);
}

void registerNewtonLineSearch(Registry& r) { r.algorithms.add("NewtonLineSearch", &buildNewtonLineSearch); }

}  // namespace
BEAMSOLID_REGISTER(registerNewtonLineSearch);
}  // namespace beamsolid
