#include "analysis/QuasiNewton.h"

#include <memory>

#include "analysis/AnalysisModel.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "core/Registry.h"

namespace beamsolid {

bool QuasiNewton::prepareTangent(AnalysisModel& model, Integrator& integrator) {
  return formAndFactor(model, integrator, initial_);
}

Vector QuasiNewton::apply(AnalysisModel& model, const Vector& b) const {
  LinearSystem& system = model.system();
  const std::size_t k = s_.size();
  if (update_ == Update::BFGS) {
    Vector q = b;
    std::vector<double> alpha(k);
    for (std::size_t j = k; j-- > 0;) {
      alpha[j] = rho_[j] * s_[j].dot(q);
      q -= alpha[j] * y_[j];
    }
    Vector z;
    system.solve(q, z);
    for (std::size_t j = 0; j < k; ++j) z += s_[j] * (alpha[j] - rho_[j] * y_[j].dot(z));
    return z;
  }
  Vector p;
  system.solve(b, p);
  for (std::size_t j = 0; j < k; ++j) p += a_[j] * s_[j].dot(p);
  return p;
}

// As OpenSees runs it: a cycle forms the tangent, takes the Newton step and
// up to `count` quasi-Newton steps while the test's tolerance is not met,
// and only then consults the test, once. So testIter counts cycles (1 when
// the first cycle converges) and maxIter bounds them.
int QuasiNewton::solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) {
  singular_ = false;
  lastError_.clear();
  LinearSystem& system = model.system();
  integrator.formUnbalance(model);
  test.start(system);
  for (;;) {
    s_.clear();
    y_.clear();
    a_.clear();
    rho_.clear();
    if (!prepareTangent(model, integrator)) return -3;
    for (int iteration = 0; iteration <= count_; ++iteration) {
      if (iteration > 0 && test.wouldConverge(system)) break;
      const Vector b = system.b();
      const Vector s = apply(model, b);
      system.x() = s;
      if (integrator.update(model, system.x()) < 0) {
        lastError_ = "the integrator could not update the step";
        return -3;
      }
      integrator.formUnbalance(model);
      const Vector y = b - system.b();
      if (update_ == Update::BFGS) {
        const double ys = y.dot(s);
        if (ys == 0.0) continue;  // no curvature seen along s: keep H as it is
        s_.push_back(s);
        y_.push_back(y);
        rho_.push_back(1.0 / ys);
      } else {
        const Vector hy = apply(model, y);
        const double shy = s.dot(hy);
        if (shy == 0.0) continue;
        a_.push_back((s - hy) / shy);
        s_.push_back(s);
      }
    }
    switch (test.test(system)) {
      case ConvergenceTest::Result::Converged: return 0;
      case ConvergenceTest::Result::Failed:
        return notConverged(test, "cycles of " + std::to_string(count_ + 1) + " iterations");
      case ConvergenceTest::Result::Continue: break;
    }
  }
}

namespace {

std::unique_ptr<Algorithm> build(CommandArgs& args, QuasiNewton::Update update) {
  bool initial = false;
  int count = 10;
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-initial") initial = true;
    else if (opt == "-count") count = args.nextInt("count");
    else if (opt == "-secant")
      args.fail("option -secant (secant element stiffness) is not supported; use the default tangent or -initial");
    else args.fail("unknown option '" + opt + "' (expected -initial or -count)");
  }
  if (count < 1) args.fail("-count must be at least 1, got " + std::to_string(count));
  return std::make_unique<QuasiNewton>(update, initial, count);
}

void registerQuasiNewton(Registry& r) {
  r.algorithms.add("BFGS", [](CommandArgs& args, Domain&) { return build(args, QuasiNewton::Update::BFGS); });
  r.algorithms.add("Broyden", [](CommandArgs& args, Domain&) { return build(args, QuasiNewton::Update::Broyden); });
}

}  // namespace
BEAMSOLID_REGISTER(registerQuasiNewton);
}  // namespace beamsolid
