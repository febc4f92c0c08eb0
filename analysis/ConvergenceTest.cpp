#include "analysis/ConvergenceTest.h"

#include <cmath>
#include <iostream>
#include <memory>

#include "analysis/LinearSystem.h"
#include "core/Registry.h"

namespace beamsolid {

double ConvergenceTest::norm(const Vector& v) const {
  if (v.size() == 0) return 0.0;
  switch (normType_) {
    case 0: return v.lpNorm<Eigen::Infinity>();
    case 1: return v.lpNorm<1>();
    case 2: return v.norm();
    default: return std::pow(v.array().abs().pow(normType_).sum(), 1.0 / normType_);
  }
}

void ConvergenceTest::start(const LinearSystem&) {
  iteration_ = 0;
  failed_ = false;
  norms_.clear();
}

ConvergenceTest::Result ConvergenceTest::test(const LinearSystem& system) {
  ++iteration_;
  const double value = measure(system);
  norms_.push_back(value);
  const bool fixed = maxIterations_ > 0 && tolerance_ < 0.0;  // FixedNumIter
  const bool converged = fixed ? iteration_ >= maxIterations_ : value <= tolerance_;
  if (printFlag_ == 1)
    std::cerr << name() << ": iteration " << iteration_ << ", norm " << value << " (tol " << tolerance_ << ")\n";
  if (converged) {
    if (printFlag_ == 2) std::cerr << name() << ": converged in " << iteration_ << " iterations, norm " << value << "\n";
    return Result::Converged;
  }
  if (!std::isfinite(value)) {
    failed_ = true;
    return Result::Failed;
  }
  if (iteration_ >= maxIterations_) {
    if (printFlag_ == 5) {
      std::cerr << name() << ": no convergence in " << iteration_ << " iterations (norm " << value
                << "); accepted as converged (printFlag 5)\n";
      return Result::Converged;
    }
    failed_ = true;
    return Result::Failed;
  }
  return Result::Continue;
}

namespace {

class NormUnbalance : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "NormUnbalance"; }
  double measure(const LinearSystem& s) override { return norm(s.b()); }
};

class NormDispIncr : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "NormDispIncr"; }
  double measure(const LinearSystem& s) override { return norm(s.x()); }
};

// Half the work of the last increment against the residual it was solved for.
// OpenSees' energy increment: half the work of the unbalance left after the
// update through the increment just applied, 0.5 |dU . R(U + dU)| (checked
// against OpenSeesPy 3.7.1). Not the textbook dU . R(U), which for a linear
// step would stop after two iterations where OpenSees stops after one.
class EnergyIncr : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "EnergyIncr"; }
  double measure(const LinearSystem& s) override { return 0.5 * std::fabs(s.x().dot(s.b())); }
};

class RelativeNormUnbalance : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "RelativeNormUnbalance"; }
  void start(const LinearSystem& s) override {
    ConvergenceTest::start(s);
    reference_ = norm(s.b());
  }
  double measure(const LinearSystem& s) override {
    const double r = norm(s.b());
    return reference_ > 0.0 ? r / reference_ : r;
  }

 private:
  double reference_ = 0.0;
};

class RelativeNormDispIncr : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "RelativeNormDispIncr"; }
  double measure(const LinearSystem& s) override {
    const double d = norm(s.x());
    if (iteration_ == 1) reference_ = d;
    return reference_ > 0.0 ? d / reference_ : d;
  }

 private:
  double reference_ = 0.0;
};

// Runs exactly numIter iterations; the norm is the unbalance.
class FixedNumIter : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "FixedNumIter"; }
  double measure(const LinearSystem& s) override { return norm(s.b()); }
};

template <class T>
std::unique_ptr<ConvergenceTest> buildTest(CommandArgs& args, Domain&) {
  const double tol = args.nextDouble("tol");
  const int maxIter = args.nextInt("maxIter");
  const int printFlag = args.done() ? 0 : args.nextInt("printFlag");
  const int normType = args.done() ? 2 : args.nextInt("normType");
  args.expectEnd();
  if (tol <= 0.0) args.fail("tol must be positive");
  if (maxIter < 1) args.fail("maxIter must be at least 1");
  return std::make_unique<T>(tol, maxIter, printFlag, normType);
}

std::unique_ptr<ConvergenceTest> buildFixedNumIter(CommandArgs& args, Domain&) {
  const int numIter = args.nextInt("numIter");
  const int printFlag = args.done() ? 0 : args.nextInt("printFlag");
  const int normType = args.done() ? 2 : args.nextInt("normType");
  args.expectEnd();
  if (numIter < 1) args.fail("numIter must be at least 1");
  return std::make_unique<FixedNumIter>(-1.0, numIter, printFlag, normType);
}

void registerTests(Registry& r) {
  r.tests.add("NormUnbalance", &buildTest<NormUnbalance>);
  r.tests.add("NormDispIncr", &buildTest<NormDispIncr>);
  r.tests.add("EnergyIncr", &buildTest<EnergyIncr>);
  r.tests.add("RelativeNormUnbalance", &buildTest<RelativeNormUnbalance>);
  r.tests.add("RelativeNormDispIncr", &buildTest<RelativeNormDispIncr>);
  r.tests.add("FixedNumIter", &buildFixedNumIter);
}

}  // namespace
BEAMSOLID_REGISTER(registerTests);
}  // namespace beamsolid
