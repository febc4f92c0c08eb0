#include "elements/StdBrick.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/GaussPointResponse.h"

namespace beamsolid {

namespace {

// Natural coordinates of the nodes: bottom face (zeta = -1) counterclockwise,
// then the top face (zeta = +1).
constexpr double kNodeXi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// 2x2x2 Gauss rule at +-1/sqrt(3), every weight 1. The points are numbered
// as OpenSees numbers them (what 'stresses', 'strains' and 'material' k
// report): xi varies slowest, zeta fastest, (-,-,-), (-,-,+), (-,+,-), ...
constexpr double kGaussXi[8][3] = {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {-1, 1, 1},
                                   {1, -1, -1},  {1, -1, 1},  {1, 1, -1},  {1, 1, 1}};
double gaussCoordinate(int point, int direction) { return kGaussXi[point][direction] / std::sqrt(3.0); }

// dN_a/d(xi, eta, zeta) of the trilinear shape functions at a natural point.
Eigen::Matrix<double, 8, 3> naturalGradients(double xi, double eta, double zeta) {
  Eigen::Matrix<double, 8, 3> g;
  for (int a = 0; a < 8; ++a) {
    const double fx = 1.0 + xi * kNodeXi[a][0];
    const double fy = 1.0 + eta * kNodeXi[a][1];
    const double fz = 1.0 + zeta * kNodeXi[a][2];
    g(a, 0) = 0.125 * kNodeXi[a][0] * fy * fz;
    g(a, 1) = 0.125 * kNodeXi[a][1] * fx * fz;
    g(a, 2) = 0.125 * kNodeXi[a][2] * fx * fy;
  }
  return g;
}

Eigen::Matrix<double, 8, 1> shapeFunctions(double xi, double eta, double zeta) {
  Eigen::Matrix<double, 8, 1> n;
  for (int a = 0; a < 8; ++a)
    n(a) = 0.125 * (1.0 + xi * kNodeXi[a][0]) * (1.0 + eta * kNodeXi[a][1]) * (1.0 + zeta * kNodeXi[a][2]);
  return n;
}

bool parseIndex(const std::string& s, int& out) {
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

const char* const kStressNames[6] = {"sigma11", "sigma22", "sigma33", "sigma12", "sigma23", "sigma13"};
const char* const kStrainNames[6] = {"eps11", "eps22", "eps33", "eps12", "eps23", "eps13"};

}  // namespace

StdBrick::StdBrick(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                   const Vector3& bodyForce)
    : Element(tag, std::vector<int>(nodeTags.begin(), nodeTags.end())), bodyForce_(bodyForce) {
  for (auto& m : materials_) {
    m = material.clone("ThreeDimensional");
    if (!m)
      throw OpenSeesError(context() + ": nDMaterial " + std::to_string(material.tag()) + " (" +
                          material.className() + ") has no ThreeDimensional form for a solid element");
  }
}

void StdBrick::setDomain(Domain&) {
  constantTangentValid_ = false;
  for (Node* n : nodes())
    if (n->ndf() != 3)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs; stdBrick needs nodes with ndf 3 (use model('basic', '-ndm', 3, '-ndf', 3))");

  Eigen::Matrix<double, kNodes, 3> X;
  for (int a = 0; a < kNodes; ++a) X.row(a) = nodes()[a]->crd().transpose();

  nodalVolume_.setZero();
  for (int g = 0; g < kGaussPoints; ++g) {
    const double xi = gaussCoordinate(g, 0), eta = gaussCoordinate(g, 1), zeta = gaussCoordinate(g, 2);
    const Eigen::Matrix<double, 8, 3> G = naturalGradients(xi, eta, zeta);
    const Matrix3 J = X.transpose() * G;  // J_ij = dx_i / dxi_j
    const double detJ = J.determinant();
    if (!(detJ > 0.0)) {
      std::ostringstream os;
      os << context() << ": the Jacobian determinant is " << detJ << " at Gauss point " << g + 1
         << "; check the node order (bottom face 1-4 counterclockwise seen from above, top face 5-8 "
            "above 1-4) and that the element is not degenerate";
      throw OpenSeesError(os.str());
    }
    gradients_[g] = G * J.inverse();
    weightedDetJ_[g] = detJ;  // unit Gauss weights
    nodalVolume_ += detJ * shapeFunctions(xi, eta, zeta);
  }
  // Material state follows the current node displacements (nodes may already be displaced).
  update();
}

double StdBrick::volume() const {
  double v = 0.0;
  for (double w : weightedDetJ_) v += w;
  return v;
}

Vector3 StdBrick::gaussPointCoordinates(int g) const {
  const auto n = shapeFunctions(gaussCoordinate(g, 0), gaussCoordinate(g, 1), gaussCoordinate(g, 2));
  Vector3 x = Vector3::Zero();
  for (int a = 0; a < kNodes; ++a) x += n(a) * nodes()[a]->crd();
  return x;
}

void StdBrick::formStrainDisplacement(int g, Matrix6x24& B) const {
  B.setZero();
  const ShapeGradients& d = gradients_[g];
  for (int a = 0; a < kNodes; ++a) {
    const int c = 3 * a;
    const double dx = d(a, 0), dy = d(a, 1), dz = d(a, 2);
    B(0, c) = dx;
    B(1, c + 1) = dy;
    B(2, c + 2) = dz;
    B(3, c) = dy;  // gamma_xy
    B(3, c + 1) = dx;
    B(4, c + 1) = dz;  // gamma_yz
    B(4, c + 2) = dy;
    B(5, c) = dz;  // gamma_zx
    B(5, c + 2) = dx;
  }
}

void StdBrick::update() {
  for (int a = 0; a < kNodes; ++a) displacement_.segment<3>(3 * a) = nodes()[a]->trialDisp().head<3>();
  Matrix6x24 B;
  Vector6 strain;
  for (int g = 0; g < kGaussPoints; ++g) {
    formStrainDisplacement(g, B);
    strain.noalias() = B * displacement_;
    materials_[g]->setTrialStrain(strain);
  }
}

void StdBrick::formStiffness(bool initial, Matrix24& K) const {
  K.setZero();
  Matrix6x24 B;
  Matrix6x24 DB;
  Matrix6 D;
  for (int g = 0; g < kGaussPoints; ++g) {
    formStrainDisplacement(g, B);
    D = initial ? materials_[g]->initialTangent() : materials_[g]->tangent();
    DB.noalias() = D * B;
    K.noalias() += weightedDetJ_[g] * (B.transpose() * DB);
  }
}

MatrixView StdBrick::tangentStiff() {
  // A linear material's tangent never changes: form it once.
  if (constantTangentValid_) return viewOf(constantTangent_);
  formStiffness(false, stiffness_);
  if (hasConstantTangent()) {
    constantTangent_ = stiffness_;
    constantTangentValid_ = true;
  }
  return viewOf(stiffness_);
}

MatrixView StdBrick::initialStiff() {
  formStiffness(true, stiffness_);
  return viewOf(stiffness_);
}

VectorView StdBrick::resistingForce() {
  force_.setZero();
  Matrix6x24 B;
  Vector6 stress;
  for (int g = 0; g < kGaussPoints; ++g) {
    formStrainDisplacement(g, B);
    stress = materials_[g]->stress();
    force_.noalias() += weightedDetJ_[g] * (B.transpose() * stress);
  }
  // Body force per unit volume: the element's own, or the one of the active
  // -selfWeight loads (see StdBrick.h).
  const Vector3& perVolume = bodyForceFromLoads_ ? loadedBodyForce_ : bodyForce_;
  for (int a = 0; a < kNodes; ++a) force_.segment<3>(3 * a) -= nodalVolume_(a) * perVolume;
  return viewOf(force_);
}

MatrixView StdBrick::massMatrix() {
  // Consistent, rho * integral(N_a N_b dV) on the 2x2x2 rule, as OpenSees'
  // stdBrick (checked against OpenSeesPy's periods).
  mass_.setZero();
  const double rho = materials_[0]->density();
  if (rho == 0.0) return viewOf(mass_);
  for (int g = 0; g < kGaussPoints; ++g) {
    const Eigen::Matrix<double, 8, 1> n =
        shapeFunctions(gaussCoordinate(g, 0), gaussCoordinate(g, 1), gaussCoordinate(g, 2));
    for (int a = 0; a < kNodes; ++a)
      for (int b = 0; b < kNodes; ++b) {
        const double m = rho * weightedDetJ_[g] * n(a) * n(b);
        for (int i = 0; i < 3; ++i) mass_(3 * a + i, 3 * b + i) += m;
      }
  }
  return viewOf(mass_);
}

void StdBrick::commitState() {
  for (auto& m : materials_) m->commitState();
}

void StdBrick::revertToLastCommit() {
  for (auto& m : materials_) m->revertToLastCommit();
}

void StdBrick::revertToStart() {
  for (auto& m : materials_) m->revertToStart();
}

void StdBrick::addLoad(const ElementLoad& load, double factor) {
  if (load.type != ElementLoad::Type::SelfWeight) {
    Element::addLoad(load, factor);
    return;
  }
  if (load.values.size() != 3)
    throw OpenSeesError(context() + ": -selfWeight expects 3 values (factors on b1, b2, b3), got " +
                        std::to_string(load.values.size()));
  bodyForceFromLoads_ = true;
  for (int i = 0; i < 3; ++i) loadedBodyForce_(i) += factor * load.values[i] * bodyForce_(i);
}

void StdBrick::zeroLoad() {
  loadedBodyForce_.setZero();
  bodyForceFromLoads_ = false;
}

Vector StdBrick::stressesAsVector() const {
  Vector out(6 * kGaussPoints);
  for (int g = 0; g < kGaussPoints; ++g) out.segment<6>(6 * g) = materials_[g]->stress();
  return out;
}

Vector StdBrick::strainsAsVector() const {
  Vector out(6 * kGaussPoints);
  for (int g = 0; g < kGaussPoints; ++g) out.segment<6>(6 * g) = materials_[g]->strain();
  return out;
}

Response StdBrick::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  auto perGaussPoint = [](const char* const names[6]) {
    std::vector<std::string> out;
    for (int g = 1; g <= kGaussPoints; ++g)
      for (int i = 0; i < 6; ++i) out.push_back(std::string(names[i]) + "_" + std::to_string(g));
    return out;
  };
  if (what == "stresses" || what == "stress")
    return {perGaussPoint(kStressNames), [this] { return stressesAsVector(); }};
  if (what == "strains" || what == "strain")
    return {perGaussPoint(kStrainNames), [this] { return strainsAsVector(); }};
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    // OpenSees' names for the brick: P<dof>_<node>.
    std::vector<std::string> names;
    for (int a = 1; a <= kNodes; ++a)
      for (const char* c : {"P1_", "P2_", "P3_"}) names.push_back(c + std::to_string(a));
    return {names, [this] { return Vector(resistingForce()); }};
  }
  // Plastic state of every Gauss point (materials that have one: J2Plasticity,
  // DruckerPrager): 6 components (engineering shears) or 1 per point.
  if (what == "plasticStrains" || what == "plasticStrain")
    return gaussPointResponse(materials_, {"plasticStrain"});
  if (what == "equivalentPlasticStrains" || what == "equivalentPlasticStrain")
    return gaussPointResponse(materials_, {"equivalentPlasticStrain"});
  if ((what == "material" || what == "integrPoint") && args.size() >= 2) {
    int point = 0;
    if (!parseIndex(args[1], point) || point < 1 || point > kGaussPoints) return {};
    return materials_[point - 1]->setResponse(std::vector<std::string>(args.begin() + 2, args.end()));
  }
  return {};
}

bool StdBrick::setParameter(const std::vector<std::string>& args, double value) {
  constantTangentValid_ = false;
  bool accepted = false;
  for (auto& m : materials_) accepted = m->setParameter(args, value) || accepted;
  return accepted;
}

void StdBrick::updateMaterialStage(int materialTag, int stage) {
  constantTangentValid_ = false;
  for (auto& m : materials_)
    if (m->tag() == materialTag) m->updateStage(stage);
}

void StdBrick::initialStateAnalysis(bool on) {
  constantTangentValid_ = false;
  for (auto& m : materials_) m->initialStateAnalysis(on);
}

void StdBrick::print(std::ostream& os) const {
  os << "Element " << tag() << " type stdBrick nodes";
  for (int t : nodeTags()) os << ' ' << t;
  os << " material " << materials_[0]->tag() << " (" << materials_[0]->className() << ") body force "
     << bodyForce_.transpose() << '\n';
}

namespace {

std::unique_ptr<Element> buildStdBrick(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element stdBrick " + std::to_string(tag));
  std::array<int, StdBrick::kNodes> nodeTags{};
  for (int a = 0; a < StdBrick::kNodes; ++a) {
    const std::string what = "node" + std::to_string(a + 1);
    nodeTags[a] = args.nextInt(what.c_str());
  }
  const int matTag = args.nextInt("matTag");
  const NDMaterial& material = domain.ndMaterials.get(matTag, args.context());
  const std::vector<double> b = args.nextDoubles("b1 b2 b3");
  if (b.size() != 0 && b.size() != 3)
    args.fail("expected 0 or 3 body force components (b1, b2, b3), got " + std::to_string(b.size()));
  args.expectEnd();
  if (!material.clone("ThreeDimensional"))
    args.fail("nDMaterial " + std::to_string(matTag) + " (" + material.className() +
              ") has no ThreeDimensional form for a solid element");
  const Vector3 bodyForce = b.empty() ? Vector3::Zero() : Vector3(b[0], b[1], b[2]);
  return std::make_unique<StdBrick>(tag, nodeTags, material, bodyForce);
}

void registerStdBrick(Registry& r) { r.elements.add("stdBrick", &buildStdBrick); }

}  // namespace

BEAMSOLID_REGISTER(registerStdBrick);

}  // namespace beamsolid
