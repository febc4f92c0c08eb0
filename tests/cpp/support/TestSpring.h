#pragma once
// A test-only two-node axial spring (ndf 3 nodes) with a chosen force law
// N(e) of the elongation e, small-displacement kinematics along the initial
// axis. Registered as element type "testSpring" for the tests:
//   element('testSpring', tag, i, j, k, <cubic>)  with N = k e + cubic e^3.
#include <cmath>
#include <memory>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/Element.h"

namespace beamsolid::testing {

class TestSpring : public Element {
 public:
  TestSpring(int tag, int i, int j, double k, double cubic) : Element(tag, {i, j}), k_(k), cubic_(cubic) {}
  std::string className() const override { return "testSpring"; }
  void setDomain(Domain&) override {
    for (Node* n : nodes())
      if (n->ndf() != 3) throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " needs ndf 3");
    Vector3 d = nodes()[1]->crd() - nodes()[0]->crd();
    if (d.norm() == 0) throw OpenSeesError(context() + ": zero length");
    axis_ = d.normalized();
    update();
  }
  void update() override {
    const Vector3 ui = nodes()[0]->trialDisp().head<3>(), uj = nodes()[1]->trialDisp().head<3>();
    elongation_ = axis_.dot(uj - ui);
  }
  double force() const { return k_ * elongation_ + cubic_ * std::pow(elongation_, 3); }
  double stiffness() const { return k_ + 3 * cubic_ * elongation_ * elongation_; }
  MatrixView tangentStiff() override { return fill(stiffness()); }
  MatrixView initialStiff() override { return fill(k_); }
  VectorView resistingForce() override {
    f_.head<3>() = -force() * axis_;
    f_.tail<3>() = force() * axis_;
    return viewOf(f_);
  }
  Response setResponse(const std::vector<std::string>& args) override {
    if (!args.empty() && args[0] == "axialForce") return {{"N"}, [this] { return Vector::Constant(1, force()); }};
    return {};
  }

 private:
  MatrixView fill(double k) {
    const Matrix3 kk = k * axis_ * axis_.transpose();
    K_ << kk, -kk, -kk, kk;
    return viewOf(K_);
  }
  double k_, cubic_;
  Vector3 axis_ = Vector3::UnitX();
  double elongation_ = 0.0;
  Eigen::Matrix<double, 6, 6> K_;
  Eigen::Matrix<double, 6, 1> f_;
};

inline void registerTestSpring(Registry& r) {
  if (r.elements.has("testSpring")) return;
  r.elements.add("testSpring", [](CommandArgs& a, Domain&) -> std::unique_ptr<Element> {
    const int tag = a.nextInt("tag");
    a.setContext("element testSpring " + std::to_string(tag));
    const int i = a.nextInt("iNode"), j = a.nextInt("jNode");
    const double k = a.nextDouble("k");
    const double cubic = a.done() ? 0.0 : a.nextDouble("cubic");
    a.expectEnd();
    return std::make_unique<TestSpring>(tag, i, j, k, cubic);
  });
}

}  // namespace beamsolid::testing

namespace beamsolid::testing {

// Test-only linear time series ("testLinear", tag): factor = t.
class TestLinearSeries : public TimeSeries {
 public:
  explicit TestLinearSeries(int tag) : TimeSeries(tag) {}
  std::string className() const override { return "testLinear"; }
  double factor(double t) const override { return t; }
  double slope(double) const override { return 1.0; }
};

inline void registerTestTypes() {
  Registry& r = Registry::global();
  registerTestSpring(r);
  if (!r.timeSeries.has("testLinear"))
    r.timeSeries.add("testLinear", [](CommandArgs& a, Domain&) -> std::unique_ptr<TimeSeries> {
      const int tag = a.nextInt("tag");
      a.expectEnd();
      return std::make_unique<TestLinearSeries>(tag);
    });
}

}  // namespace beamsolid::testing
