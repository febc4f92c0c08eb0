#include "analysis/KrylovNewton.h"

#include <algorithm>
#include <memory>

#include "analysis/AnalysisModel.h"
#include "analysis/ConvergenceTest.h"
#include "analysis/Integrator.h"
#include "core/Registry.h"

namespace beamsolid {

bool KrylovNewton::prepareTangent(AnalysisModel& model, Integrator& integrator, Tangent which) {
  if (which == Tangent::NoTangent && model.system().isFactored()) return true;
  const bool initial = which == Tangent::Initial;
  if (!(initial && model.factoredIs(AnalysisModel::Stiffness::Initial))) ++factorizations_;
  return formAndFactor(model, integrator, initial);
}

int KrylovNewton::solveCurrentStep(AnalysisModel& model, Integrator& integrator, ConvergenceTest& test) {
  singular_ = false;
  lastError_.clear();
  factorizations_ = 0;
  corrections_.clear();
  changes_.clear();
  LinearSystem& system = model.system();
  integrator.formUnbalance(model);
  test.start(system);
  if (!prepareTangent(model, integrator, increment_)) return -3;
  Vector previous;  // v of the last iteration, empty after a restart
  Matrix W, U;
  for (;;) {
    system.solve();
    const Vector v = system.x();
    if (previous.size() == v.size()) changes_.push_back(previous - v);
    Vector correction = v;
    const int dim = static_cast<int>(changes_.size());
    if (dim > 0) {
      W.resize(v.size(), dim);
      U.resize(v.size(), dim);
      for (int i = 0; i < dim; ++i) {
        W.col(i) = changes_[i];
        U.col(i) = corrections_[i];
      }
      const Vector c = W.colPivHouseholderQr().solve(v);
      correction = U * c + (v - W * c);
    }
    system.x() = correction;
    corrections_.push_back(correction);
    if (integrator.update(model, system.x()) < 0) {
      lastError_ = "the integrator could not update the step";
      return -3;
    }
    previous = v;
    integrator.formUnbalance(model);
    switch (test.test(system)) {
      case ConvergenceTest::Result::Converged: return 0;
      case ConvergenceTest::Result::Failed: return notConverged(test);
      case ConvergenceTest::Result::Continue: break;
    }
    // The subspace cannot hold more independent directions than there are
    // equations: the effective maximum is min(maxDim, size), as in OpenSees.
    if (dim >= std::min<int>(maxDimension_, static_cast<int>(v.size()))) {
      // The subspace is full: new tangent (per '-iterate'), fresh subspace.
      corrections_.clear();
      changes_.clear();
      previous.resize(0);
      if (!prepareTangent(model, integrator, iterate_)) return -3;
    }
  }
}

namespace {

KrylovNewton::Tangent readTangent(CommandArgs& args, const char* option) {
  const std::string t = args.nextString(option);
  if (t == "current" || t == "Current") return KrylovNewton::Tangent::Current;
  if (t == "initial" || t == "Initial") return KrylovNewton::Tangent::Initial;
  if (t == "noTangent" || t == "NoTangent") return KrylovNewton::Tangent::NoTangent;
  args.fail(std::string(option) + " '" + t + "' is unknown (expected current, initial or noTangent)");
}

std::unique_ptr<Algorithm> buildKrylovNewton(CommandArgs& args, Domain&) {
  auto iterate = KrylovNewton::Tangent::Current, increment = KrylovNewton::Tangent::Current;
  int maxDim = 3;
  while (!args.done()) {
    const std::string opt = args.nextString("option");
    if (opt == "-iterate") iterate = readTangent(args, "-iterate");
    else if (opt == "-increment") increment = readTangent(args, "-increment");
    else if (opt == "-maxDim") maxDim = args.nextInt("maxDim");
    else if (opt == "-initial") continue;  // OpenSees accepts and ignores it (scripts pass it)
    else args.fail("unknown option '" + opt + "' (expected -iterate, -increment or -maxDim)");
  }
  if (maxDim < 1) args.fail("-maxDim must be at least 1, got " + std::to_string(maxDim));
  return std::make_unique<KrylovNewton>(iterate, increment, maxDim);
}

void registerKrylovNewton(Registry& r) { r.algorithms.add("KrylovNewton", &buildKrylovNewton); }

}  // namespace
BEAMSOLID_REGISTER(registerKrylovNewton);
}  // namespace beamsolid
