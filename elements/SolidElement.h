#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "elements/Element.h"
#include "elements/MultilinearCell.h"
#include "elements/SimplexCell.h"
#include "materials/nd/NDMaterial.h"

namespace beamsolid {

// What OpenSees' low-order continuum elements share, in 2D (4-node quads:
// quad, bbarQuad, SSPquad) and 3D (8-node bricks: stdBrick, bbarBrick,
// SSPbrick): the nodes and their reference geometry (MultilinearCell), one
// copy of the nD material per material point, body forces and eleLoad
// '-selfWeight', mass, the responses (stresses, strains, forces, material k
// ...), and the forwarding of setParameter, updateMaterialStage and
// InitialStateAnalysis to the material copies. A formulation supplies the
// strains it gives its materials and the stiffness and internal force that
// follow (Gauss-point elements through GaussPointSolid, the stabilized
// single-point ones directly).
//
// Body forces b are force per unit volume (not multiplied by the density),
// acting in full at every step independent of load patterns:
// resistingForce = internal force - integral(N^T b dV) (- other element
// loads). While eleLoad '-selfWeight' (fx, fy, <fz>) loads are active the
// body force is sum over them of factor * (fx b1, fy b2, fz b3), replacing b
// (OpenSees' behaviour, checked against OpenSeesPy 3.7.1).
//
// `CellType` is the reference geometry: MultilinearCell (quadrilaterals and
// hexahedra) or SimplexCell (tri31, FourNodeTetrahedron).
template <int Dim, class CellType = MultilinearCell<Dim>>
class SolidElement : public Element {
 public:
  using Cell = CellType;
  static constexpr int kNodes = Cell::kNodes;
  static constexpr int kDofs = Dim * kNodes;
  using NodalVector = Eigen::Matrix<double, kDofs, 1>;
  using NodalMatrix = Eigen::Matrix<double, kDofs, kDofs>;
  using BodyForce = Eigen::Matrix<double, Dim, 1>;

  // How massMatrix() distributes rho * V: consistent rho integral(N_a N_b dV);
  // row sums of it, rho integral(N_a dV) on the diagonal; or rho V / nodes
  // on every node.
  enum class MassKind { Consistent, RowSum, Uniform };

  // `kind` is the material form ("ThreeDimensional", "PlaneStrain",
  // "PlaneStress"); `points` the number of material points.
  SolidElement(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material, const std::string& kind,
               int points, double thickness, const BodyForce& bodyForce);

  bool supportsSpace(int ndm) const override { return ndm == Dim; }
  // True when every material point is linear: the solver may then condense
  // the element's dofs once (the tangent is cached for the same reason).
  bool hasConstantTangent() const override;

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void zeroLoad() override;
  void addLoad(const ElementLoad& load, double factor) override;
  bool acceptsLoad(ElementLoad::Type type) const override { return type == ElementLoad::Type::SelfWeight; }

  // 'stresses'/'stress' and 'strains'/'strain' (every material point's
  // vector, in point order), 'force'/'forces'/'globalForce'/'globalForces'
  // (P<dof>_<node>), 'material'/'integrPoint' k ... (k = 1..points),
  // 'plasticStrains' (points x 6, the 3D plastic strain) and
  // 'equivalentPlasticStrains' (points) when the material has a plastic
  // state (ours).
  Response setResponse(const std::vector<std::string>& args) override;
  // Forwarded to every material point; true when any accepted it.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void updateMaterialStage(int materialTag, int stage) override;
  void initialStateAnalysis(bool on) override;

  void print(std::ostream& os) const override;

  int materialPoints() const { return static_cast<int>(materials_.size()); }
  const NDMaterial& material(int point) const {
    refreshMaterials();
    return *materials_[point];
  }
  const BodyForce& bodyForce() const { return bodyForce_; }
  double thickness() const { return thickness_; }
  // Volume (area in 2D, without the thickness) of the element.
  double volume() const { return cell_.volume(); }
  // Mass density in use: the material's unless a formulation says otherwise.
  virtual double density() const { return materials_[0]->density(); }
  // The nodal forces of the element's own loads (body force, and what a
  // formulation adds), which resistingForce() subtracts.
  virtual NodalVector appliedLoad() const;

 protected:
  // Checks the nodes (ndm, ndf), builds the reference geometry, calls
  // prepare() and update().
  void setDomain(Domain& domain) override;
  // Formulation data that depend on the geometry (and on the initial tangent).
  virtual void prepare() {}
  // Gives every material point its trial strain from the nodal displacements.
  virtual void setMaterialStrains(const NodalVector& u) = 0;
  // Stiffness from the materials' current (or initial) tangents.
  virtual void formStiffness(bool initial, NodalMatrix& K) const = 0;
  virtual void formInternalForce(NodalVector& f) const = 0;
  virtual MassKind massKind() const { return MassKind::Consistent; }
  // A material may have changed its moduli: drop what was built from them.
  virtual void materialsChanged();
  // Brings the material points to the current displacements if update() left them behind.
  void refreshMaterials() const;
  // Component names of one material point's stress or strain vector.
  std::vector<std::string> pointComponentNames(bool stress) const;

  const Cell& cell() const { return cell_; }
  std::vector<std::unique_ptr<NDMaterial>> materials_;
  NodalVector displacement_ = NodalVector::Zero();

 private:
  Vector pointVectors(bool stress) const;

  std::string kind_;
  double thickness_;
  BodyForce bodyForce_;
  // Body force from the active -selfWeight loads (see above).
  BodyForce loadedBodyForce_ = BodyForce::Zero();
  bool bodyForceFromLoads_ = false;

  Cell cell_;
  // The element matrices are allocated on first use (4.6 KB each for a brick):
  // a model of linear bricks needs only the constant tangent, a static one no mass.
  static NodalMatrix& buffer(std::unique_ptr<NodalMatrix>& m);
  std::unique_ptr<NodalMatrix> stiffness_;
  // The tangent of linear materials, kept until something may change it.
  std::unique_ptr<NodalMatrix> constantTangent_;
  bool constantTangentValid_ = false;
  // With a constant tangent the internal force is affine in the displacements:
  // f = f_ref + K (u - u_ref) from the state the tangent was formed at, a
  // product instead of a pass over the material points (the linear soil's
  // share of every Newton iteration).
  NodalVector referenceForce_ = NodalVector::Zero(), referenceDisplacement_ = NodalVector::Zero();
  // ... and the material points need their strains only when something reads
  // them (commit, revert, responses, a tangent formed afresh): update() then
  // leaves them behind the displacements and refreshMaterials() catches up.
  mutable bool materialsStale_ = false;
  std::unique_ptr<NodalMatrix> mass_;
  NodalVector force_ = NodalVector::Zero();
};

// The arguments every solid command reads the same way.
namespace solidargs {
// n node tags, named node1 ... noden.
template <std::size_t N>
std::array<int, N> nodeTags(CommandArgs& args);
// Body force components: none or exactly `count`, as what the command says.
std::vector<double> bodyForce(CommandArgs& args, std::size_t count, const char* names);
// A positive thickness named thick.
double thickness(CommandArgs& args);
// 'PlaneStrain' or 'PlaneStress', named type.
std::string planeType(CommandArgs& args);
// Refuses a model whose -ndm is not `ndm` (quads are 2D, bricks 3D).
void requireSpace(CommandArgs& args, const Domain& domain, int ndm, const std::string& type);
// element(type, tag, *4 nodes, ...) of a quad: the tag (which names the
// messages from here on), a 2D model, the nodes.
std::pair<int, std::array<int, 4>> quadTagAndNodes(CommandArgs& args, const Domain& domain, const std::string& type);
// The nDMaterial of matTag, checked to have form `kind`.
const NDMaterial& material(CommandArgs& args, Domain& domain, const std::string& kind, const std::string& forWhat);
// The same for a matTag already read.
const NDMaterial& materialOfTag(CommandArgs& args, Domain& domain, int matTag, const std::string& kind,
                                const std::string& forWhat);

// element(type, tag, *N nodes, matTag, <b1, b2, b3>): what every 3D solid
// reads (the bricks, FourNodeTetrahedron).
template <class Solid, std::size_t N>
std::unique_ptr<Element> solid(CommandArgs& args, Domain& domain, const std::string& type) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element " + type + " " + std::to_string(tag));
  // Up to N + 1 numbers: the missing node or matTag is named when read.
  const std::size_t numbers = args.remaining();
  if (numbers > N + 1 && numbers != N + 4)
    args.fail("expected " + std::to_string(N) + " node tags, matTag and 0 or 3 body force components (b1 b2 b3), got " +
              std::to_string(numbers) + " arguments (" + type + " has exactly " + std::to_string(N) + " nodes)");
  const auto tags = nodeTags<N>(args);
  const NDMaterial& m = material(args, domain, "ThreeDimensional", "a solid element");
  const std::vector<double> b = bodyForce(args, 3, "b1 b2 b3");
  args.expectEnd();
  const Vector3 force = b.empty() ? Vector3::Zero() : Vector3(b[0], b[1], b[2]);
  return std::make_unique<Solid>(tag, tags, m, force);
}

template <class Brick>
std::unique_ptr<Element> brick(CommandArgs& args, Domain& domain, const std::string& type) {
  return solid<Brick, 8>(args, domain, type);
}
}  // namespace solidargs

}  // namespace beamsolid
