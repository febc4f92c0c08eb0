// An element plugin: a shared library exporting one registration function.
// Load it with ops.loadPlugin('/path/to/liblinear_spring_plugin.so'); then
//   ops.element('PluginSpring', tag, iNode, jNode, k)
// is a linear axial spring between two ndf-3 nodes.
#include <memory>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/Element.h"

namespace {

using namespace beamsolid;

class PluginSpring : public Element {
 public:
  PluginSpring(int tag, int i, int j, double k) : Element(tag, {i, j}), k_(k) {}
  std::string className() const override { return "PluginSpring"; }

  void setDomain(Domain&) override {
    for (Node* n : nodes())
      if (n->ndf() != 3) throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " must have ndf 3");
    const Vector3 d = nodes()[1]->crd() - nodes()[0]->crd();
    if (d.norm() == 0.0) throw OpenSeesError(context() + ": the nodes coincide");
    axis_ = d.normalized();
    const Matrix3 kk = k_ * axis_ * axis_.transpose();
    K_ << kk, -kk, -kk, kk;
  }
  void update() override {
    const Vector3 du = nodes()[1]->trialDisp().head<3>() - nodes()[0]->trialDisp().head<3>();
    force_ = k_ * axis_.dot(du);
  }
  MatrixView tangentStiff() override { return viewOf(K_); }
  MatrixView initialStiff() override { return viewOf(K_); }
  VectorView resistingForce() override {
    f_ << -force_ * axis_, force_ * axis_;
    return viewOf(f_);
  }
  Response setResponse(const std::vector<std::string>& args) override {
    if (!args.empty() && args[0] == "axialForce") return {{"N"}, [this] { return Vector::Constant(1, force_); }};
    return {};
  }

 private:
  double k_;
  double force_ = 0.0;
  Vector3 axis_;
  Eigen::Matrix<double, 6, 6> K_;
  Eigen::Matrix<double, 6, 1> f_;
};

std::unique_ptr<Element> buildPluginSpring(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element PluginSpring " + std::to_string(tag));
  const int i = args.nextInt("iNode");
  const int j = args.nextInt("jNode");
  const double k = args.nextDouble("k");
  args.expectEnd();
  if (k <= 0.0) args.fail("k must be positive");
  return std::make_unique<PluginSpring>(tag, i, j, k);
}

}  // namespace

extern "C" void beamsolid_register(beamsolid::Registry& registry) {
  if (!registry.elements.has("PluginSpring")) registry.elements.add("PluginSpring", &buildPluginSpring);
}
