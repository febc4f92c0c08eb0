#include "analysis/ConvergenceTest.h"

#include <algorithm>
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
  const bool converged = fixed ? iteration_ >= maxIterations_ : passes(value);
  if (printFlag_ == 1)
    std::cerr << name() << ": iteration " << iteration_ << ", norm " << value << " (tol " << tolerance_ << ")\n";
  if (converged) {
    if (printFlag_ == 2) std::cerr << name() << ": converged in " << iteration_ << " iterations, norm " << value << "\n";
    return Result::Converged;
  }
  if (!std::isfinite(value) || diverged()) {
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

std::vector<double> ConvergenceTest::reportedNorms(int cap) const {
  std::vector<double> out = norms_;
  const int length = std::min(maxIterations_, cap);
  if (static_cast<int>(out.size()) < length) out.resize(length, 0.0);
  return out;
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

// The energy increment (as EnergyIncr) of each iteration against that of the
// step's first iteration; testNorm holds the energies themselves (as OpenSeesPy 3.7.1).
class RelativeEnergyIncr : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "RelativeEnergyIncr"; }
  double measure(const LinearSystem& s) override {
    const double e = 0.5 * std::fabs(s.x().dot(s.b()));
    if (iteration_ == 1) reference_ = e;
    return e;
  }
  bool passes(double value) const override { return reference_ > 0.0 ? value / reference_ <= tolerance_ : value <= tolerance_; }

 private:
  double reference_ = 0.0;
};

// The displacement-increment norm of each iteration against the sum of the
// step's norms so far; testNorm holds the norms themselves (as OpenSeesPy 3.7.1).
class RelativeTotalNormDispIncr : public ConvergenceTest {
 public:
  using ConvergenceTest::ConvergenceTest;
  std::string name() const override { return "RelativeTotalNormDispIncr"; }
  double measure(const LinearSystem& s) override {
    const double d = norm(s.x());
    total_ = iteration_ == 1 ? d : total_ + d;
    return d;
  }
  bool passes(double value) const override { return total_ > 0.0 ? value / total_ <= tolerance_ : value <= tolerance_; }

 private:
  double total_ = 0.0;
};

// test('NormDispAndUnbalance' | 'NormDispOrUnbalance', tolIncr, tolR, iter, <pFlag, nType, maxIncr>):
// both (or either) of the increment norm <= tolIncr and the unbalance norm
// <= tolR. With maxIncr >= 0 the step fails once the norms have grown from
// one iteration to the next more than maxIncr times (either norm growing
// counts). testNorm gives the increment norms padded to iter entries, then
// the unbalance norms padded likewise (as OpenSeesPy 3.7.1).
class NormDispAndOrUnbalance : public ConvergenceTest {
 public:
  NormDispAndOrUnbalance(bool both, double tolIncr, double tolR, int maxIter, int printFlag, int normType,
                         int maxIncr)
      : ConvergenceTest(tolIncr, maxIter, printFlag, normType), both_(both), tolR_(tolR), maxIncr_(maxIncr) {}
  std::string name() const override { return both_ ? "NormDispAndUnbalance" : "NormDispOrUnbalance"; }
  void start(const LinearSystem& s) override {
    ConvergenceTest::start(s);
    unbalanceNorms_.clear();
    increases_ = 0;
  }
  double measure(const LinearSystem& s) override {
    const double d = norm(s.x());
    const double r = norm(s.b());
    if (!norms_.empty() && (d > norms_.back() || r > unbalanceNorms_.back())) ++increases_;
    unbalanceNorms_.push_back(r);
    lastUnbalance_ = r;
    // A non-finite norm fails the step (ConvergenceTest::test checks the value returned).
    return std::isfinite(r) ? d : r;
  }
  bool passes(double d) const override {
    if (maxIncr_ >= 0 && increases_ > maxIncr_) return false;
    const bool dispOk = d <= tolerance_;
    const bool unbalanceOk = lastUnbalance_ <= tolR_;
    return both_ ? dispOk && unbalanceOk : dispOk || unbalanceOk;
  }
  bool diverged() const override { return maxIncr_ >= 0 && increases_ > maxIncr_; }
  std::vector<double> reportedNorms(int cap) const override {
    const int length = std::min(maxIterations_, cap);
    std::vector<double> disp = norms_, unbalance = unbalanceNorms_;
    if (static_cast<int>(disp.size()) < length) disp.resize(length, 0.0);
    if (static_cast<int>(unbalance.size()) < length) unbalance.resize(length, 0.0);
    disp.insert(disp.end(), unbalance.begin(), unbalance.end());
    return disp;
  }

 private:
  bool both_;
  double tolR_;
  int maxIncr_;
  int increases_ = 0;
  double lastUnbalance_ = 0.0;
  std::vector<double> unbalanceNorms_;
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

template <bool Both>
std::unique_ptr<ConvergenceTest> buildDispAndOrUnbalance(CommandArgs& args, Domain&) {
  const double tolIncr = args.nextDouble("tolIncr");
  const double tolR = args.nextDouble("tolR");
  const int maxIter = args.nextInt("iter");
  const int printFlag = args.done() ? 0 : args.nextInt("pFlag");
  const int normType = args.done() ? 2 : args.nextInt("nType");
  const int maxIncr = args.done() ? -1 : args.nextInt("maxIncr");
  args.expectEnd();
  if (tolIncr <= 0.0) args.fail("tolIncr must be positive");
  if (tolR <= 0.0) args.fail("tolR must be positive");
  if (maxIter < 1) args.fail("iter must be at least 1");
  if (normType < 0) args.fail("nType must be 0 (max norm), 1, 2 or higher");
  return std::make_unique<NormDispAndOrUnbalance>(Both, tolIncr, tolR, maxIter, printFlag, normType, maxIncr);
}

void registerTests(Registry& r) {
  r.tests.add("NormDispAndUnbalance", &buildDispAndOrUnbalance<true>);
  r.tests.add("NormDispOrUnbalance", &buildDispAndOrUnbalance<false>);
  r.tests.add("RelativeEnergyIncr", &buildTest<RelativeEnergyIncr>);
  r.tests.add("RelativeTotalNormDispIncr", &buildTest<RelativeTotalNormDispIncr>);
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
