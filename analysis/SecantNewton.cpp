#include "analysis/SecantNewton.h"

#include <memory>

#include "analysis/AnalysisModel.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "core/Registry.h"

namespace beamsolid {

bool SecantNewton::prepareTangent(AnalysisModel& model, Integrator& integrator, Tangent which) {
  if (which == Tangent::NoTangent && model.system().isFactored()) return true;
  return formAndFactor(model, integrator, which == Tangent::Initial);
}

int SecantNewton::solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) {
  singular_ = false;
  lastError_.clear();
  LinearSystem& system = model.system();
  integrator.formUnbalance(model);
  test.start(system);
  if (!prepareTangent(model, integrator, increment_)) return -3;
  // The previous iteration: its v, its unbalance and its correction; empty after a (re)start.
  Vector previousV, previousB, previousS;
  int accelerated = 0;
  for (;;) {
    const Vector b = system.b();
    system.solve();
    const Vector v = system.x();
    Vector correction = v;
    if (previousS.size() == v.size()) {
      const Vector y = previousB - b;
      const double ys = y.dot(previousS);
      bool use = ys != 0.0;
      if (use && cutOutHigh_ > 0.0) {
        const double ratio = previousS.dot(previousB) / ys;
        use = ratio <= cutOutHigh_ && ratio >= cutOutLow_;
      }
      if (use) {
        const double rho = 1.0 / ys;
        const Vector z = numTerms_ >= 3 ? Vector(previousV - v) : Vector(previousS - v);
        const double sb = previousS.dot(b);
        const Vector q = v - rho * sb * z;
        correction = q + rho * (sb - y.dot(q)) * previousS;
      }
      ++accelerated;
    }
    system.x() = correction;
    if (integrator.update(model, system.x()) < 0) {
      lastError_ = "the integrator could not update the step";
      return -3;
    }
    previousV = v;
    previousB = b;
    previousS = correction;
    integrator.formUnbalance(model);
    switch (test.test(system)) {
      case ConvergenceTest::Result::Converged: return 0;
      case ConvergenceTest::Result::Failed: return notConverged(test);
      case ConvergenceTest::Result::Continue: break;
    }
    if (accelerated + 1 >= maxDimension_) {
      accelerated = 0;
      previousS.resize(0);
      if (!prepareTangent(model, integrator, iterate_)) return -3;
    }
  }
}

namespace {

SecantNewton::Tangent readTangent(CommandArgs& args, const char* option) {
  const std::string t = args.nextString(option);
  if (t == "current" || t == "Current") return SecantNewton::Tangent::Current;
  if (t == "initial" || t == "Initial") return SecantNewton::Tangent::Initial;
  if (t == "noTangent" || t == "NoTangent") return SecantNewton::Tangent::NoTangent;
  args.fail(std::string(option) + " '" + t + "' is unknown (expected current, initial or noTangent)");
}

std::unique_ptr<Algorithm> buildSecantNewton(CommandArgs& args, Domain&) {
  auto iterate = SecantNewton::Tangent::Current, increment = SecantNewton::Tangent::Current;
  int maxDim = 3, numTerms = 2;
  double high = 0.0, low = 0.0;
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-iterate") iterate = readTangent(args, "-iterate");
    else if (opt == "-increment") increment = readTangent(args, "-increment");
    else if (opt == "-maxDim") maxDim = args.nextInt("maxDim");
    else if (opt == "-numTerms") numTerms = args.nextInt("numTerms");
    else if (opt == "-cutOut") {
      high = args.nextDouble("R1");
      low = args.nextDouble("R2");
    } else if (opt == "-initial") continue;  // accepted and ignored, as KrylovNewton
    else args.fail("unknown option '" + opt + "' (expected -iterate, -increment, -maxDim, -numTerms or -cutOut)");
  }
  if (maxDim < 1) args.fail("-maxDim must be at least 1, got " + std::to_string(maxDim));
  if (numTerms < 1 || numTerms > 3) args.fail("-numTerms must be 1, 2 or 3, got " + std::to_string(numTerms));
  return std::make_unique<SecantNewton>(iterate, increment, maxDim, numTerms, high, low);
}

void registerSecantNewton(Registry& r) { r.algorithms.add("SecantNewton", &buildSecantNewton); }

}  // namespace
BEAMSOLID_REGISTER(registerSecantNewton);
}  // namespace beamsolid
