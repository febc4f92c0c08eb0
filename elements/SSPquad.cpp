#include "elements/SSPquad.h"

#include "core/Registry.h"

namespace beamsolid {

SSPquad::SSPquad(int tag, const std::array<int, kNodes>& nodeTags, const NDMaterial& material,
                 const std::string& type, double thickness, const Eigen::Vector2d& bodyForce)
    : SinglePointSolid(tag, nodeTags, material, type, thickness, bodyForce) {}

void SSPquad::formStabilization(const StrainMatrix& D0, NodalMatrix& K) const {
  const Cell::NodeCoordinates& X = cell().nodeCoordinates();
  const Cell::ShapeGradients& b = cell().meanGradients();
  // Hourglass vector h and its part orthogonal to the linear fields (gamma . x = gamma . y = 0).
  const Eigen::Vector4d h(1.0, -1.0, 1.0, -1.0);
  const Eigen::Vector4d gamma = 0.25 * (h - (h.dot(X.col(0))) * b.col(0) - (h.dot(X.col(1))) * b.col(1));
  const Eigen::Matrix2d j = cell().centreJacobian().inverse();  // j(k, i) = d xi_k / d x_i
  const Eigen::Vector3d v(1.0, -1.0, 0.0);
  const double modulus = v.dot(D0 * v);
  K.setZero();
  // The xi-linear part of the hourglass strain comes with grad eta, the eta-linear part with grad xi.
  for (int k = 0; k < 2; ++k) {
    NodalVector r = NodalVector::Zero();
    for (int a = 0; a < kNodes; ++a) {
      r(2 * a) = 0.5 * j(k, 0) * gamma(a);
      r(2 * a + 1) = -0.5 * j(k, 1) * gamma(a);
    }
    K.noalias() += r * r.transpose();
  }
  K *= thickness() * cell().volume() / 3.0 * modulus;
}

namespace {

std::unique_ptr<Element> buildSSPquad(CommandArgs& args, Domain& domain) {
  const auto [tag, nodeTags] = solidargs::quadTagAndNodes(args, domain, "SSPquad");
  // matTag comes before type; its form is checked once the type is known.
  const int matTag = args.nextInt("matTag");
  const std::string type = solidargs::planeType(args);
  const NDMaterial& material = solidargs::materialOfTag(args, domain, matTag, type, "SSPquad");
  const double thickness = solidargs::thickness(args);
  const std::vector<double> b = solidargs::bodyForce(args, 2, "b1 b2");
  args.expectEnd();
  const Eigen::Vector2d bodyForce = b.empty() ? Eigen::Vector2d::Zero() : Eigen::Vector2d(b[0], b[1]);
  return std::make_unique<SSPquad>(tag, nodeTags, material, type, thickness, bodyForce);
}

void registerSSPquad(Registry& r) { r.elements.add("SSPquad", &buildSSPquad); }

}  // namespace

BEAMSOLID_REGISTER(registerSSPquad);

}  // namespace beamsolid
