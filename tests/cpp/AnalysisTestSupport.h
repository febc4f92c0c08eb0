#pragma once
// Test-only building blocks for the analysis tests: a 2-node axial spring
// with a force law chosen by the test, a linear time series, and a small
// fixture that builds the analysis objects through the Registry exactly as
// the interpreter does.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "analysis/StaticAnalysis.h"
#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/Registry.h"
#include "core/TimeSeries.h"
#include "elements/Element.h"

namespace beamsolid::analysistest {

// force and tangent of a spring as functions of its elongation d
struct SpringLaw {
  std::function<double(double)> force;
  std::function<double(double)> stiffness;
};

inline SpringLaw linearLaw(double k) {
  return {[k](double d) { return k * d; }, [k](double) { return k; }};
}

// An axial spring along x between two ndf-3 nodes (dofs x, y, rz): only the
// x dofs carry force. Optional consistent bar mass m/6 [[2,1],[1,2]] on x.
// Not named TestSpring: support/TestSpring.h defines that class in the same
// namespace, and two inline definitions of one name break the ODR.
class LawSpring : public Element {
 public:
  LawSpring(int tag, int nodeI, int nodeJ, SpringLaw law, double mass = 0.0)
      : Element(tag, {nodeI, nodeJ}), law_(std::move(law)), mass_(mass) {}
  std::string className() const override { return "TestSpring"; }

  void update() override {
    const double d = nodes()[1]->trialDisp()[0] - nodes()[0]->trialDisp()[0];
    fill(law_.force(d), law_.stiffness(d));
  }
  MatrixView tangentStiff() override { return viewOf(stiffness_); }
  MatrixView initialStiff() override {
    initial_.setZero();
    setAxial(initial_, law_.stiffness(0.0));
    return viewOf(initial_);
  }
  VectorView resistingForce() override { return viewOf(force_); }
  MatrixView massMatrix() override {
    massMatrix_.setZero();
    setAxial(massMatrix_, -mass_ / 6.0);
    massMatrix_(0, 0) = massMatrix_(3, 3) = mass_ / 3.0;
    return viewOf(massMatrix_);
  }

 protected:
  void setDomain(Domain&) override {
    for (const Node* n : nodes())
      if (n->ndf() != 3) throw OpenSeesError(context() + ": needs ndf 3 nodes");
    update();
  }

 private:
  static void setAxial(Eigen::Matrix<double, 6, 6>& m, double k) {
    m(0, 0) = m(3, 3) = k;
    m(0, 3) = m(3, 0) = -k;
  }
  void fill(double f, double k) {
    force_.setZero();
    force_[0] = -f;
    force_[3] = f;
    stiffness_.setZero();
    setAxial(stiffness_, k);
  }

  SpringLaw law_;
  double mass_;
  Eigen::Matrix<double, 6, 6> stiffness_, initial_, massMatrix_;
  Eigen::Matrix<double, 6, 1> force_;
};

// factor(t) = t: the load factor lambda is the time.
class LinearSeries : public TimeSeries {
 public:
  explicit LinearSeries(int tag) : TimeSeries(tag) {}
  std::string className() const override { return "TestLinear"; }
  double factor(double t) const override { return t; }
  double slope(double) const override { return 1.0; }
};

using Args = std::vector<CommandArgs::Value>;

template <class Product, class Table>
std::unique_ptr<Product> build(const Table& table, Domain& domain, const std::string& type, Args args = {}) {
  CommandArgs a(type, std::move(args));
  return table.get(type)(a, domain);
}

// A 1D model along x: nodes with ndf 3, y and rz fixed everywhere.
struct Model {
  Domain domain;
  AnalysisComponents components;
  std::unique_ptr<StaticAnalysis> analysis;

  void addNode(int tag, double x, double mass = 0.0) {
    auto n = std::make_unique<Node>(tag, 3, Vector3(x, 0.0, 0.0));
    if (mass != 0.0) n->setMass(Vector3(mass, 0.0, 0.0));
    domain.addNode(std::move(n), "test");
    domain.addSP({tag, 1, 0.0}, "test");
    domain.addSP({tag, 2, 0.0}, "test");
  }
  void fixX(int tag) { domain.addSP({tag, 0, 0.0}, "test"); }
  void addSpring(int tag, int i, int j, SpringLaw law, double mass = 0.0) {
    domain.addElement(std::make_unique<LawSpring>(tag, i, j, std::move(law), mass), "test");
  }
  // Pattern 1 with a Linear series: reference load P in x at `node`.
  void addLoad(int node, double P) {
    auto pattern = std::make_unique<LoadPattern>(1, std::make_shared<LinearSeries>(1));
    pattern->addNodalLoad(node, Vector3(P, 0.0, 0.0));
    domain.addPattern(std::move(pattern), "test");
  }
  double disp(int node) const { return domain.node(node, "test").trialDisp()[0]; }

  // The interpreter's path: every object from its registered factory.
  void analyzeWith(const std::string& algorithm, Args algorithmArgs, const std::string& integrator,
                   Args integratorArgs, double tol = 1e-10, int maxIter = 50) {
    Registry& r = Registry::global();
    components.handler = build<ConstraintHandler>(r.constraintHandlers, domain, "Transformation");
    components.numberer = build<Numberer>(r.numberers, domain, "Plain");
    components.solver = build<LinearSolver>(r.systems, domain, "UmfPack");
    setTest(tol, maxIter);
    components.algorithm = build<Algorithm>(r.algorithms, domain, algorithm, std::move(algorithmArgs));
    components.integrator = build<Integrator>(r.integrators, domain, integrator, std::move(integratorArgs));
    analysis = std::make_unique<StaticAnalysis>(domain, components);
  }
  void setTest(double tol, int maxIter) {
    components.test = build<ConvergenceTest>(Registry::global().tests, domain, "NormUnbalance",
                                             {tol, static_cast<long long>(maxIter)});
  }
  int analyze(int steps) { return analysis->analyze(steps); }
};

}  // namespace beamsolid::analysistest
