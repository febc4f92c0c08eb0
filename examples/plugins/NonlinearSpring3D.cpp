// The tutorial plugin (docs/plugins.md): a nonlinear spring between two nodes
// of a 3D model, whose force-deformation law is any uniaxial material.
//
//   ops.loadPlugin('libnonlinear_spring.so')
//   ops.element('NonlinearSpring3D', tag, iNode, jNode, matTag)
//   ops.element('NonlinearSpring3D', tag, iNode, jNode, matTag, '-orient', x, y, z)
//
// The spring acts along the line from iNode to jNode, or along (x, y, z) when
// given (needed when the nodes coincide, as for the p-y springs of a pile).
// Its deformation is the relative translation along that axis, delta = a . (u_j - u_i),
// the material's "strain"; its axial force N is the material's "stress". Nodes
// may have ndf 3 (bricks) or 6 (beams): rotations get no stiffness.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/PluginAbi.h"
#include "core/Registry.h"
#include "elements/Element.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace {

using namespace beamsolid;

class NonlinearSpring3D : public Element {
 public:
  NonlinearSpring3D(int tag, int iNode, int jNode, std::unique_ptr<UniaxialMaterial> material,
                    std::optional<Vector3> orient)
      : Element(tag, {iNode, jNode}), material_(std::move(material)), orient_(orient) {}

  std::string className() const override { return "NonlinearSpring3D"; }

  // Once the nodes are known: the axis, and matrices of the right size
  // (allocated here, once, never on the hot path).
  void setDomain(Domain&) override {
    for (Node* n : nodes())
      if (n->ndf() < 3)
        throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has ndf " +
                            std::to_string(n->ndf()) + "; a 3D spring needs at least 3");
    const Vector3 d = orient_ ? *orient_ : Vector3(nodes()[1]->crd() - nodes()[0]->crd());
    if (d.norm() == 0.0)
      throw OpenSeesError(context() + (orient_ ? ": the -orient vector is zero" :
                                                 ": the nodes coincide; give the axis with -orient x y z"));
    axis_ = d.normalized();
    ndfI_ = nodes()[0]->ndf();
    K_ = Matrix::Zero(numDOF(), numDOF());
    K0_ = Matrix::Zero(numDOF(), numDOF());
    f_ = Vector::Zero(numDOF());
    fill(K0_, material_->initialTangent());
    update();
  }

  void update() override {
    const Vector3 du = nodes()[1]->trialDisp().head<3>() - nodes()[0]->trialDisp().head<3>();
    material_->setTrialStrain(axis_.dot(du));
  }

  MatrixView tangentStiff() override {
    fill(K_, material_->tangent());
    return viewOf(K_);
  }
  MatrixView initialStiff() override { return viewOf(K0_); }

  // The force on iNode is -N a, on jNode +N a.
  VectorView resistingForce() override {
    const double N = material_->stress();
    f_.setZero();
    f_.segment<3>(0) = -N * axis_;
    f_.segment<3>(ndfI_) = N * axis_;
    return viewOf(f_);
  }

  void commitState() override { material_->commitState(); }
  void revertToLastCommit() override { material_->revertToLastCommit(); }
  void revertToStart() override { material_->revertToStart(); }

  // eleResponse / Element recorders: 'force' (global, every dof), 'axialForce',
  // 'deformation', and 'material' followed by what the material answers.
  Response setResponse(const std::vector<std::string>& args) override {
    if (args.empty()) return {};
    if (args[0] == "force" || args[0] == "globalForce")
      return Response::named(Response::numberedNames("P", numDOF()), [this] { return Vector(resistingForce()); });
    if (args[0] == "axialForce") return {{"N"}, [this] { return Vector::Constant(1, material_->stress()); }};
    if (args[0] == "deformation") return {{"delta"}, [this] { return Vector::Constant(1, material_->strain()); }};
    if (args[0] == "material") return material_->setResponse({args.begin() + 1, args.end()});
    return {};
  }

 private:
  // k a a^T in the four translational blocks, +k on the diagonal blocks.
  void fill(Matrix& K, double k) const {
    const Matrix3 kk = k * axis_ * axis_.transpose();
    K.block<3, 3>(0, 0) = kk;
    K.block<3, 3>(ndfI_, ndfI_) = kk;
    K.block<3, 3>(0, ndfI_) = -kk;
    K.block<3, 3>(ndfI_, 0) = -kk;
  }

  std::unique_ptr<UniaxialMaterial> material_;
  std::optional<Vector3> orient_;
  Vector3 axis_ = Vector3::UnitX();
  int ndfI_ = 3;
  Matrix K_, K0_;
  Vector f_;
};

// element('NonlinearSpring3D', tag, iNode, jNode, matTag, <'-orient', x, y, z>)
std::unique_ptr<Element> buildNonlinearSpring3D(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element NonlinearSpring3D " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const int matTag = args.nextInt("matTag");
  std::optional<Vector3> orient;
  if (args.nextFlag("-orient")) {
    // One at a time: the order of a call's arguments is unspecified in C++.
    const double x = args.nextDouble("x"), y = args.nextDouble("y"), z = args.nextDouble("z");
    orient = Vector3(x, y, z);
  }
  args.expectEnd();
  auto material = domain.uniaxialMaterials.get(matTag, args.context()).clone();
  return std::make_unique<NonlinearSpring3D>(tag, iNode, jNode, std::move(material), orient);
}

}  // namespace

BEAMSOLID_PLUGIN_REGISTER(registry) { registry.elements.add("NonlinearSpring3D", &buildNonlinearSpring3D); }
