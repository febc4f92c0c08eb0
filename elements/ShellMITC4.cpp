#include "elements/ShellMITC4.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

namespace {

// Natural coordinates of the nodes and of the 2x2 Gauss points (both
// counterclockwise from node 1's corner).
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};

struct Shape {
  Eigen::Vector4d N, dXi, dEta;
};

Shape shapeAt(double xi, double eta) {
  Shape s;
  for (int a = 0; a < 4; ++a) {
    s.N[a] = 0.25 * (1.0 + xi * kXi[a]) * (1.0 + eta * kEta[a]);
    s.dXi[a] = 0.25 * kXi[a] * (1.0 + eta * kEta[a]);
    s.dEta[a] = 0.25 * kEta[a] * (1.0 + xi * kXi[a]);
  }
  return s;
}

using Row24 = Eigen::Matrix<double, 1, ShellMITC4::kDofs>;

// The covariant transverse shear along xi (alongXi) or eta at a point:
// w,xi + x,xi theta_y - y,xi theta_x (beta_x = theta_y, beta_y = -theta_x).
Row24 covariantShear(const Eigen::Matrix<double, 4, 2>& x, double xi, double eta, bool alongXi) {
  const Shape s = shapeAt(xi, eta);
  const Eigen::Vector4d& d = alongXi ? s.dXi : s.dEta;
  const double dx = d.dot(x.col(0));
  const double dy = d.dot(x.col(1));
  Row24 row = Row24::Zero();
  for (int a = 0; a < 4; ++a) {
    row(6 * a + 2) = d[a];
    row(6 * a + 3) = -dy * s.N[a];
    row(6 * a + 4) = dx * s.N[a];
  }
  return row;
}

}  // namespace

ShellMITC4::ShellMITC4(int tag, const std::array<int, kNodes>& nodeTags, const PlateSection& section)
    : Element(tag, std::vector<int>(nodeTags.begin(), nodeTags.end())) {
  for (auto& s : sections_) s = section.clone();
}

bool ShellMITC4::hasConstantTangent() const {
  // Geometrically linear; constant as long as its section is elastic.
  return sections_[0]->className() == "ElasticMembranePlateSection";
}

void ShellMITC4::setDomain(Domain&) {
  for (const Node* n : nodes())
    if (n->ndf() != 6)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs, a shell needs 6 (model('basic', '-ndm', 3, '-ndf', 6))");
  std::array<Vector3, 4> X;
  for (int a = 0; a < 4; ++a) X[a] = nodes()[a]->crd();
  // The mid-plane frame: e1 along xi, e3 normal to the xi and eta directions.
  const Vector3 v1 = 0.5 * (X[1] + X[2] - X[0] - X[3]);
  const Vector3 v2 = 0.5 * (X[2] + X[3] - X[0] - X[1]);
  const Vector3 normal = v1.cross(v2);
  if (!(v1.norm() > 0.0) || !(normal.norm() > 1e-14 * v1.squaredNorm()))
    throw OpenSeesError(context() + ": the nodes do not span a quadrilateral (coincident or collinear nodes)");
  const Vector3 e1 = v1.normalized();
  const Vector3 e3 = normal.normalized();
  const Vector3 e2 = e3.cross(e1);
  frame_.row(0) = e1.transpose();
  frame_.row(1) = e2.transpose();
  frame_.row(2) = e3.transpose();
  transform_.setZero();
  for (int k = 0; k < 8; ++k) transform_.block<3, 3>(3 * k, 3 * k) = frame_;

  const Vector3 centre = 0.25 * (X[0] + X[1] + X[2] + X[3]);
  Eigen::Matrix<double, 4, 2> x;
  for (int a = 0; a < 4; ++a) {
    x(a, 0) = e1.dot(X[a] - centre);
    x(a, 1) = e2.dot(X[a] - centre);
  }

  // MITC4 tying points: xi-shear at (0, -1) and (0, 1), eta-shear at (-1, 0) and (1, 0).
  const Row24 shearA = covariantShear(x, 0.0, -1.0, true), shearC = covariantShear(x, 0.0, 1.0, true);
  const Row24 shearD = covariantShear(x, -1.0, 0.0, false), shearB = covariantShear(x, 1.0, 0.0, false);

  // Unit directions of the xi and eta axes at the centre.
  const Shape centreShape = shapeAt(0.0, 0.0);
  const Eigen::Vector2d axisXi =
      Eigen::Vector2d(centreShape.dXi.dot(x.col(0)), centreShape.dXi.dot(x.col(1))).normalized();
  const Eigen::Vector2d axisEta =
      Eigen::Vector2d(centreShape.dEta.dot(x.col(0)), centreShape.dEta.dot(x.col(1))).normalized();

  const double g = 1.0 / std::sqrt(3.0);
  mass_.setZero();
  const double rhoH = sections_[0]->areaDensity();
  for (int p = 0; p < 4; ++p) {
    const double xi = g * kXi[p], eta = g * kEta[p];
    const Shape s = shapeAt(xi, eta);
    Eigen::Matrix2d J;
    J << s.dXi.dot(x.col(0)), s.dXi.dot(x.col(1)), s.dEta.dot(x.col(0)), s.dEta.dot(x.col(1));
    const double detJ = J.determinant();
    if (!(detJ > 0.0))
      throw OpenSeesError(context() + ": the element is inverted or degenerate at a Gauss point (det J = " +
                          std::to_string(detJ) + "); give the nodes counterclockwise");
    const Eigen::Matrix2d Jinv = J.inverse();
    Eigen::Matrix<double, 2, 4> dN;
    dN.row(0) = s.dXi.transpose();
    dN.row(1) = s.dEta.transpose();
    const Eigen::Matrix<double, 2, 4> dNdx = Jinv * dN;

    StrainMatrix& B = B_[p];
    B.setZero();
    DrillRow& d = drill_[p];
    d.setZero();
    for (int a = 0; a < 4; ++a) {
      const double Nx = dNdx(0, a), Ny = dNdx(1, a);
      const int o = 6 * a;
      B(0, o) = Nx;          // eps11 = u,x
      B(1, o + 1) = Ny;      // eps22 = v,y
      B(2, o) = Ny;          // gamma12 = u,y + v,x
      B(2, o + 1) = Nx;
      B(3, o + 4) = Nx;      // kappa11 = theta_y,x
      B(4, o + 3) = -Ny;     // kappa22 = -theta_x,y
      B(5, o + 4) = Ny;      // kappa12 = theta_y,y - theta_x,x
      B(5, o + 3) = -Nx;
      d(o + 5) = s.N[a];     // theta_z - (v,x - u,y) / 2
      d(o) = 0.5 * Ny;
      d(o + 1) = -0.5 * Nx;
    }
    // Assumed covariant shears, as physical shears along the xi and eta
    // lines (scaled by the other tangent's length over det J), then turned
    // into x, y with the directions of the xi and eta axes at the centre
    // (Dvorkin and Bathe's formula; OpenSees does the same, which differs
    // from J^-1 at the point on distorted elements).
    const Row24 gXi = 0.5 * (1.0 - eta) * shearA + 0.5 * (1.0 + eta) * shearC;
    const Row24 gEta = 0.5 * (1.0 - xi) * shearD + 0.5 * (1.0 + xi) * shearB;
    const Row24 gammaR = J.row(1).norm() / detJ * gXi;
    const Row24 gammaS = J.row(0).norm() / detJ * gEta;
    B.row(6) = axisEta.y() * gammaR - axisXi.y() * gammaS;
    B.row(7) = -axisEta.x() * gammaR + axisXi.x() * gammaS;
    weight_[p] = detJ;

    // Consistent mass on the translations.
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int k = 0; k < 3; ++k) mass_(6 * a + k, 6 * b + k) += rhoH * s.N[a] * s.N[b] * detJ;
  }
  drillStiffness_ = sections_[0]->initialTangent()(2, 2);
  update();
}

ShellMITC4::Vector24 ShellMITC4::localDisplacements() const {
  Vector24 u;
  for (int a = 0; a < 4; ++a) u.segment<6>(6 * a) = nodes()[a]->trialDisp();
  return transform_ * u;
}

void ShellMITC4::update() {
  const Vector24 u = localDisplacements();
  for (int p = 0; p < 4; ++p) sections_[p]->setTrialDeformation(B_[p] * u);
  Vector24 f = Vector24::Zero();
  for (int p = 0; p < 4; ++p)
    f += weight_[p] * (B_[p].transpose() * sections_[p]->force() +
                       drillStiffness_ * drill_[p].transpose() * drill_[p].dot(u));
  force_ = transform_.transpose() * f;
}

void ShellMITC4::form(bool initial) {
  Matrix24 k = Matrix24::Zero();
  for (int p = 0; p < 4; ++p) {
    const auto& C = initial ? sections_[p]->initialTangent() : sections_[p]->tangent();
    k += weight_[p] * (B_[p].transpose() * C * B_[p] + drillStiffness_ * drill_[p].transpose() * drill_[p]);
  }
  stiffness_ = transform_.transpose() * k * transform_;
}

MatrixView ShellMITC4::tangentStiff() {
  form(false);
  return viewOf(stiffness_);
}

MatrixView ShellMITC4::initialStiff() {
  form(true);
  return viewOf(stiffness_);
}

VectorView ShellMITC4::resistingForce() { return viewOf(force_); }

MatrixView ShellMITC4::massMatrix() { return viewOf(mass_); }

void ShellMITC4::commitState() {
  for (auto& s : sections_) s->commitState();
}

void ShellMITC4::revertToLastCommit() {
  for (auto& s : sections_) s->revertToLastCommit();
  update();
}

void ShellMITC4::revertToStart() {
  for (auto& s : sections_) s->revertToStart();
  update();
}

Response ShellMITC4::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& name = args[0];
  if (args.size() == 1 && (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")) {
    std::vector<std::string> names;
    for (int a = 1; a <= 4; ++a)
      for (const char* c : {"Px", "Py", "Pz", "Mx", "My", "Mz"}) names.push_back(std::string(c) + "_" + std::to_string(a));
    return Response::named(std::move(names), [this]() -> Vector { return Vector(force_); });
  }
  const bool stresses = name == "stresses" || name == "stress";
  if (args.size() == 1 && (stresses || name == "strains" || name == "strain")) {
    std::vector<std::string> names;
    const char* const* labels = stresses ? PlateSection::forceNames() : PlateSection::deformationNames();
    for (int p = 1; p <= 4; ++p)
      for (int k = 0; k < PlateSection::kOrder; ++k) names.push_back(std::string(labels[k]) + "_" + std::to_string(p));
    return Response::named(std::move(names), [this, stresses]() -> Vector {
      Vector out(4 * PlateSection::kOrder);
      for (int p = 0; p < 4; ++p)
        out.segment<PlateSection::kOrder>(PlateSection::kOrder * p) =
            stresses ? sections_[p]->force() : sections_[p]->reportedDeformation();
      return out;
    });
  }
  if ((name == "section" || name == "material") && args.size() >= 3) {
    int point = 0;
    try {
      point = std::stoi(args[1]);
    } catch (const std::exception&) {
      return {};
    }
    if (point < 1 || point > 4) return {};
    return sections_[point - 1]->setResponse(std::vector<std::string>(args.begin() + 2, args.end()));
  }
  return {};
}

namespace {

std::unique_ptr<Element> buildShellMITC4(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element ShellMITC4 " + std::to_string(tag));
  if (domain.spaceDim() != 3) args.fail("a shell needs a 3D model (-ndm 3, -ndf 6)");
  std::array<int, 4> nodes{};
  for (int a = 0; a < 4; ++a) nodes[a] = args.nextInt(a == 0 ? "node1" : a == 1 ? "node2" : a == 2 ? "node3" : "node4");
  const int secTag = args.nextInt("secTag");
  // OpenSees' options of ShellMITC4 that change nothing for a linear shell.
  while (!args.done()) {
    const std::string option = args.nextString("option");
    if (option != "-updateBasis") args.fail("unknown option '" + option + "' (expected -updateBasis)");
    args.fail("-updateBasis (a frame that follows large rotations) is not supported; this shell is geometrically linear");
  }
  const PlateSection& section = PlateSection::of(domain.sections.get(secTag, args.context()), args.context());
  return std::make_unique<ShellMITC4>(tag, nodes, section);
}

void registerShellMITC4(Registry& r) {
  // OpenSees' other names for the same element (OpenSeesPy's PlanarShearWall test meshes 'shell').
  for (const char* name : {"ShellMITC4", "shellMITC4", "Shell", "shell"}) r.elements.add(name, &buildShellMITC4);
}

}  // namespace

BEAMSOLID_REGISTER(registerShellMITC4);

}  // namespace beamsolid
