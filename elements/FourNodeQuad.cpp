#include "elements/FourNodeQuad.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <variant>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/GaussPointResponse.h"

namespace beamsolid {

namespace {

// Natural coordinates of the nodes, counterclockwise.
constexpr double kNodeXi[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
// 2x2 Gauss rule at +-1/sqrt(3), unit weights, numbered as OpenSees reports
// them ('stresses', 'material' k): counterclockwise like the nodes.
constexpr double kGaussXi[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
double gaussCoordinate(int point, int direction) { return kGaussXi[point][direction] / std::sqrt(3.0); }

Eigen::Matrix<double, 4, 2> naturalGradients(double xi, double eta) {
  Eigen::Matrix<double, 4, 2> g;
  for (int a = 0; a < 4; ++a) {
    g(a, 0) = 0.25 * kNodeXi[a][0] * (1.0 + eta * kNodeXi[a][1]);
    g(a, 1) = 0.25 * kNodeXi[a][1] * (1.0 + xi * kNodeXi[a][0]);
  }
  return g;
}

Eigen::Matrix<double, 4, 1> shapeFunctions(double xi, double eta) {
  Eigen::Matrix<double, 4, 1> n;
  for (int a = 0; a < 4; ++a) n(a) = 0.25 * (1.0 + xi * kNodeXi[a][0]) * (1.0 + eta * kNodeXi[a][1]);
  return n;
}

bool parseIndex(const std::string& s, int& out) {
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

}  // namespace

FourNodeQuad::FourNodeQuad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                           const Properties& properties)
    : Element(tag, std::vector<int>(nodeTags.begin(), nodeTags.end())), properties_(properties) {
  if (properties_.type != "PlaneStrain" && properties_.type != "PlaneStress")
    throw OpenSeesError(context() + ": type must be 'PlaneStrain' or 'PlaneStress', got '" + properties_.type + "'");
  for (auto& m : materials_) {
    m = material.clone(properties_.type);
    if (!m)
      throw OpenSeesError(context() + ": nDMaterial " + std::to_string(material.tag()) + " (" +
                          material.className() + ") has no " + properties_.type + " form");
  }
}

void FourNodeQuad::setDomain(Domain&) {
  for (Node* n : nodes())
    if (n->ndf() != 2 || n->ndm() != 2)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has ndm " + std::to_string(n->ndm()) +
                          " and ndf " + std::to_string(n->ndf()) +
                          "; quad needs nodes of a 2D model with ndf 2 (model('basic', '-ndm', 2, '-ndf', 2))");

  Eigen::Matrix<double, kNodes, 2> X;
  for (int a = 0; a < kNodes; ++a) X.row(a) = nodes()[a]->crd().head<2>().transpose();

  const double t = properties_.thickness;
  nodalVolume_.setZero();
  for (int g = 0; g < kGaussPoints; ++g) {
    const double xi = gaussCoordinate(g, 0), eta = gaussCoordinate(g, 1);
    const Eigen::Matrix<double, 4, 2> G = naturalGradients(xi, eta);
    const Eigen::Matrix2d J = X.transpose() * G;  // J_ij = dx_i / dxi_j
    const double detJ = J.determinant();
    if (!(detJ > 0.0)) {
      std::ostringstream os;
      os << context() << ": the Jacobian determinant is " << detJ << " at Gauss point " << g + 1
         << "; give the nodes counterclockwise and check that the quadrilateral is convex and not degenerate";
      throw OpenSeesError(os.str());
    }
    gradients_[g] = G * J.inverse();
    weightedDetJ_[g] = t * detJ;  // unit Gauss weights
    nodalVolume_ += t * detJ * shapeFunctions(xi, eta);
  }

  // Pressure: edge a -> a+1 with chord d takes p (dy, -dx), half per end.
  pressureLoad_.setZero();
  for (int a = 0; a < kNodes; ++a) {
    const int b = (a + 1) % kNodes;
    const Eigen::Vector2d d = X.row(b).transpose() - X.row(a).transpose();
    const Eigen::Vector2d half = 0.5 * properties_.pressure * Eigen::Vector2d(d.y(), -d.x());
    pressureLoad_.segment<2>(2 * a) += half;
    pressureLoad_.segment<2>(2 * b) += half;
  }
  update();
}

double FourNodeQuad::area() const {
  double v = 0.0;
  for (double w : weightedDetJ_) v += w;
  return v / properties_.thickness;
}

double FourNodeQuad::density() const {
  return properties_.rho != 0.0 ? properties_.rho : materials_[0]->density();
}

Eigen::Vector2d FourNodeQuad::gaussPointCoordinates(int g) const {
  const auto n = shapeFunctions(gaussCoordinate(g, 0), gaussCoordinate(g, 1));
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  for (int a = 0; a < kNodes; ++a) x += n(a) * nodes()[a]->crd().head<2>();
  return x;
}

void FourNodeQuad::formStrainDisplacement(int g, Matrix3x8& B) const {
  B.setZero();
  const ShapeGradients& d = gradients_[g];
  for (int a = 0; a < kNodes; ++a) {
    const int c = 2 * a;
    B(0, c) = d(a, 0);
    B(1, c + 1) = d(a, 1);
    B(2, c) = d(a, 1);  // gamma_12
    B(2, c + 1) = d(a, 0);
  }
}

void FourNodeQuad::update() {
  for (int a = 0; a < kNodes; ++a) displacement_.segment<2>(2 * a) = nodes()[a]->trialDisp().head<2>();
  Matrix3x8 B;
  Eigen::Vector3d strain;
  for (int g = 0; g < kGaussPoints; ++g) {
    formStrainDisplacement(g, B);
    strain.noalias() = B * displacement_;
    materials_[g]->setTrialStrain(strain);
  }
}

void FourNodeQuad::formStiffness(bool initial, Matrix8& K) const {
  K.setZero();
  Matrix3x8 B, DB;
  Eigen::Matrix3d D;
  for (int g = 0; g < kGaussPoints; ++g) {
    formStrainDisplacement(g, B);
    D = initial ? materials_[g]->initialTangent() : materials_[g]->tangent();
    DB.noalias() = D * B;
    K.noalias() += weightedDetJ_[g] * (B.transpose() * DB);
  }
}

MatrixView FourNodeQuad::tangentStiff() {
  formStiffness(false, stiffness_);
  return viewOf(stiffness_);
}

MatrixView FourNodeQuad::initialStiff() {
  formStiffness(true, stiffness_);
  return viewOf(stiffness_);
}

FourNodeQuad::Vector8 FourNodeQuad::appliedLoad() const {
  Vector8 p = pressureLoad_;
  const Eigen::Vector2d& perVolume = bodyForceFromLoads_ ? loadedBodyForce_ : properties_.bodyForce;
  for (int a = 0; a < kNodes; ++a) p.segment<2>(2 * a) += nodalVolume_(a) * perVolume;
  return p;
}

VectorView FourNodeQuad::resistingForce() {
  force_.setZero();
  Matrix3x8 B;
  Eigen::Vector3d stress;
  for (int g = 0; g < kGaussPoints; ++g) {
    formStrainDisplacement(g, B);
    stress = materials_[g]->stress();
    force_.noalias() += weightedDetJ_[g] * (B.transpose() * stress);
  }
  force_ -= appliedLoad();
  return viewOf(force_);
}

MatrixView FourNodeQuad::massMatrix() {
  // Lumped: row sums of the consistent mass.
  mass_.setZero();
  const double rho = density();
  for (int a = 0; a < kNodes; ++a)
    for (int i = 0; i < 2; ++i) mass_(2 * a + i, 2 * a + i) = rho * nodalVolume_(a);
  return viewOf(mass_);
}

void FourNodeQuad::commitState() {
  for (auto& m : materials_) m->commitState();
}

void FourNodeQuad::revertToLastCommit() {
  for (auto& m : materials_) m->revertToLastCommit();
}

void FourNodeQuad::revertToStart() {
  for (auto& m : materials_) m->revertToStart();
}

void FourNodeQuad::addLoad(const ElementLoad& load, double factor) {
  if (load.type != ElementLoad::Type::SelfWeight) {
    Element::addLoad(load, factor);
    return;
  }
  // ElementLoad keeps the 3D layout {bx, by, bz}; bz is 0 in 2D.
  if (load.values.size() < 2)
    throw OpenSeesError(context() + ": -selfWeight expects 2 values (factors on b1, b2), got " +
                        std::to_string(load.values.size()));
  bodyForceFromLoads_ = true;
  for (int i = 0; i < 2; ++i) loadedBodyForce_(i) += factor * load.values[i] * properties_.bodyForce(i);
}

void FourNodeQuad::zeroLoad() {
  loadedBodyForce_.setZero();
  bodyForceFromLoads_ = false;
}

Vector FourNodeQuad::stressesAsVector() const {
  Vector out(3 * kGaussPoints);
  for (int g = 0; g < kGaussPoints; ++g) out.segment<3>(3 * g) = materials_[g]->stress();
  return out;
}

Vector FourNodeQuad::strainsAsVector() const {
  Vector out(3 * kGaussPoints);
  for (int g = 0; g < kGaussPoints; ++g) out.segment<3>(3 * g) = materials_[g]->strain();
  return out;
}

Response FourNodeQuad::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  // OpenSees repeats the component names for every Gauss point.
  auto perGaussPoint = [](std::initializer_list<const char*> names) {
    std::vector<std::string> out;
    for (int g = 0; g < kGaussPoints; ++g)
      for (const char* n : names) out.emplace_back(n);
    return out;
  };
  if (what == "stresses" || what == "stress")
    return {perGaussPoint({"sigma11", "sigma22", "sigma12"}), [this] { return stressesAsVector(); }};
  if (what == "strains" || what == "strain")
    return {perGaussPoint({"eta11", "eta22", "eta12"}), [this] { return strainsAsVector(); }};
  if (what == "force" || what == "forces" || what == "globalForce" || what == "globalForces") {
    std::vector<std::string> names;
    for (int a = 1; a <= kNodes; ++a)
      for (const char* c : {"P1_", "P2_"}) names.push_back(c + std::to_string(a));
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

bool FourNodeQuad::setParameter(const std::vector<std::string>& args, double value) {
  bool accepted = false;
  for (auto& m : materials_) accepted = m->setParameter(args, value) || accepted;
  return accepted;
}

void FourNodeQuad::updateMaterialStage(int materialTag, int stage) {
  for (auto& m : materials_)
    if (m->tag() == materialTag) m->updateStage(stage);
}

void FourNodeQuad::initialStateAnalysis(bool on) {
  for (auto& m : materials_) m->initialStateAnalysis(on);
}

void FourNodeQuad::print(std::ostream& os) const {
  const auto& p = properties_;
  os << "Element " << tag() << " type quad nodes";
  for (int t : nodeTags()) os << ' ' << t;
  os << " thick " << p.thickness << ' ' << p.type << " material " << materials_[0]->tag() << " ("
     << materials_[0]->className() << ") pressure " << p.pressure << " rho " << p.rho << " body force "
     << p.bodyForce.transpose() << '\n';
}

namespace {

std::unique_ptr<Element> buildFourNodeQuad(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element quad " + std::to_string(tag));
  if (domain.spaceDim() != 2)
    args.fail("quad is a 2D element; it needs model('basic', '-ndm', 2, '-ndf', 2), this model has -ndm " +
              std::to_string(domain.spaceDim()));
  // The nodes and thick are the numbers before the type string.
  std::size_t numbers = 0;
  while (args.position() + numbers < args.size() &&
         !std::holds_alternative<std::string>(args.at(args.position() + numbers)))
    ++numbers;
  if (numbers != FourNodeQuad::kNodes + 1)
    args.fail("expected 4 node tags and thick before the type ('PlaneStrain' or 'PlaneStress'), got " +
              std::to_string(numbers) + " numbers (quad has exactly 4 nodes)");
  std::array<int, FourNodeQuad::kNodes> nodeTags{};
  for (int a = 0; a < FourNodeQuad::kNodes; ++a) {
    const std::string what = "node" + std::to_string(a + 1);
    nodeTags[a] = args.nextInt(what.c_str());
  }
  FourNodeQuad::Properties p;
  {
    const std::size_t at = args.position();
    p.thickness = args.nextDouble("thick");
    if (!(p.thickness > 0.0)) args.failAt(at, "thick", "a positive thickness");
  }
  {
    const std::size_t at = args.position();
    p.type = args.nextString("type");
    if (p.type != "PlaneStrain" && p.type != "PlaneStress")
      args.failAt(at, "type", "'PlaneStrain' or 'PlaneStress'");
  }
  const int matTag = args.nextInt("matTag");
  const NDMaterial& material = domain.ndMaterials.get(matTag, args.context());
  const std::vector<double> extra = args.nextDoubles("pressure rho b1 b2");
  if (extra.size() > 4)
    args.fail("expected at most 4 optional numbers after matTag (pressure, rho, b1, b2), got " +
              std::to_string(extra.size()));
  args.expectEnd();
  if (extra.size() > 0) p.pressure = extra[0];
  if (extra.size() > 1) p.rho = extra[1];
  if (extra.size() > 2) p.bodyForce.x() = extra[2];
  if (extra.size() > 3) p.bodyForce.y() = extra[3];
  if (!material.clone(p.type))
    args.fail("nDMaterial " + std::to_string(matTag) + " (" + material.className() + ") has no " + p.type +
              " form for a quad");
  return std::make_unique<FourNodeQuad>(tag, nodeTags, material, p);
}

void registerFourNodeQuad(Registry& r) { r.elements.add("quad", &buildFourNodeQuad); }

}  // namespace

BEAMSOLID_REGISTER(registerFourNodeQuad);

}  // namespace beamsolid
