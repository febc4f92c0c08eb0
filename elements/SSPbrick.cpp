#include "elements/SSPbrick.h"

#include "core/Registry.h"

namespace beamsolid {

namespace {

constexpr int kHourglass = 4;  // eta zeta, zeta xi, xi eta, xi eta zeta
constexpr int kEnhanced = 12;
using HourglassMatrix = Eigen::Matrix<double, 3 * kHourglass, 3 * kHourglass>;
using HourglassStrain = Eigen::Matrix<double, 6, 3 * kHourglass>;

// Value of hourglass function k at the natural point xi.
double hourglass(int k, const Vector3& xi) {
  switch (k) {
    case 0: return xi(1) * xi(2);
    case 1: return xi(2) * xi(0);
    case 2: return xi(0) * xi(1);
    default: return xi(0) * xi(1) * xi(2);
  }
}

// d h_k / d xi_m at xi.
Vector3 hourglassNaturalGradient(int k, const Vector3& xi) {
  switch (k) {
    case 0: return {0.0, xi(2), xi(1)};
    case 1: return {xi(2), 0.0, xi(0)};
    case 2: return {xi(1), xi(0), 0.0};
    default: return {xi(1) * xi(2), xi(0) * xi(2), xi(0) * xi(1)};
  }
}

// Engineering Voigt vector of f sym(g (x) h): normal parts g_i h_i, shears g_i h_j + g_j h_i.
Eigen::Matrix<double, 6, 1> symmetricProduct(const Vector3& g, const Vector3& h, double f) {
  Eigen::Matrix<double, 6, 1> e;
  e << g(0) * h(0), g(1) * h(1), g(2) * h(2), g(0) * h(1) + g(1) * h(0), g(1) * h(2) + g(2) * h(1),
      g(2) * h(0) + g(0) * h(2);
  return f * e;
}

// The twelve enhanced strain modes at xi, columns of G; g.row(m) = grad xi_m.
Eigen::Matrix<double, 6, kEnhanced> enhancedModes(const Matrix3& g, const Vector3& xi) {
  Eigen::Matrix<double, 6, kEnhanced> G;
  int c = 0;
  for (int m = 0; m < 3; ++m) G.col(c++) = symmetricProduct(g.row(m).transpose(), g.row(m).transpose(), xi(m));
  static constexpr int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (const auto& p : pairs)
    for (int k : {p[0], p[1]}) G.col(c++) = symmetricProduct(g.row(p[0]).transpose(), g.row(p[1]).transpose(), xi(k));
  for (int m = 0; m < 3; ++m) {
    const int n1 = (m + 1) % 3, n2 = (m + 2) % 3;
    G.col(c++) = symmetricProduct(g.row(m).transpose(), g.row(m).transpose(), xi(n1) * xi(n2));
  }
  return G;
}

}  // namespace

void SSPbrick::formStabilization(const StrainMatrix& D0, NodalMatrix& K) const {
  const Cell::NodeCoordinates& X = cell().nodeCoordinates();
  const Cell::ShapeGradients& b = cell().meanGradients();
  const Matrix3 J0 = cell().centreJacobian();
  const Matrix3 g = J0.inverse();  // g(m, i) = d xi_m / d x_i
  const double detJ0 = J0.determinant();

  // gamma_k: hourglass vector k made orthogonal to the linear fields.
  Eigen::Matrix<double, kNodes, kHourglass> gamma;
  for (int k = 0; k < kHourglass; ++k) {
    Eigen::Matrix<double, kNodes, 1> h;
    for (int a = 0; a < kNodes; ++a) h(a) = hourglass(k, Cell::nodeNatural(a));
    gamma.col(k) = (h - b * (X.transpose() * h)) / 8.0;
  }

  // Hourglass strain and enhanced modes, condensed on the 2x2x2 rule (exact for these polynomials).
  HourglassMatrix Kqq = HourglassMatrix::Zero();
  Eigen::Matrix<double, 3 * kHourglass, kEnhanced> Kqa = Eigen::Matrix<double, 3 * kHourglass, kEnhanced>::Zero();
  Eigen::Matrix<double, kEnhanced, kEnhanced> Kaa = Eigen::Matrix<double, kEnhanced, kEnhanced>::Zero();
  for (int p = 0; p < Cell::kGaussPoints; ++p) {
    const Vector3 xi = Cell::gaussPoint(p);
    Eigen::Matrix<double, kHourglass, 3> gradients;  // spatial gradient of each hourglass function
    for (int k = 0; k < kHourglass; ++k) gradients.row(k) = (g.transpose() * hourglassNaturalGradient(k, xi)).transpose();
    HourglassStrain Bq;
    smallstrain::strainDisplacement(gradients, Bq);
    const Eigen::Matrix<double, 6, kEnhanced> G = enhancedModes(g, xi);
    const HourglassStrain DBq = D0 * Bq;
    Kqq.noalias() += detJ0 * Bq.transpose() * DBq;
    Kqa.noalias() += detJ0 * DBq.transpose() * G;
    Kaa.noalias() += detJ0 * G.transpose() * (D0 * G);
  }
  const HourglassMatrix S = Kqq - Kqa * Kaa.ldlt().solve(Kqa.transpose());

  // q_kd = gamma_k . u_d.
  Eigen::Matrix<double, kDofs, 3 * kHourglass> Gamma = Eigen::Matrix<double, kDofs, 3 * kHourglass>::Zero();
  for (int a = 0; a < kNodes; ++a)
    for (int k = 0; k < kHourglass; ++k)
      for (int d = 0; d < 3; ++d) Gamma(3 * a + d, 3 * k + d) = gamma(a, k);
  K.noalias() = Gamma * S * Gamma.transpose();
}

namespace {
void registerSSPbrick(Registry& r) {
  r.elements.add("SSPbrick", [](CommandArgs& a, Domain& d) { return solidargs::brick<SSPbrick>(a, d, "SSPbrick"); });
}
}  // namespace

BEAMSOLID_REGISTER(registerSSPbrick);

}  // namespace beamsolid
