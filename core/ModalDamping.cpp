#include "core/ModalDamping.h"

#include <algorithm>
#include <cmath>

#include "core/Domain.h"
#include "core/Node.h"
#include "elements/Element.h"

namespace beamsolid {

std::map<int, Vector> ModalDamping::forces(const Domain& domain) const {
  const std::vector<double>& lambda = domain.eigenvalues();
  const int modes = factors_.size() == 1 ? int(lambda.size()) : std::min<int>(factors_.size(), lambda.size());
  std::map<int, Vector> out;
  if (modes == 0) return out;
  // Per node, M [v, phi_1, ..., phi_n] (columns), summed over nodal and element mass.
  std::map<int, Matrix> mass;
  auto columns = [&](const Node& n) {
    Matrix x(n.ndf(), modes + 1);
    x.col(0) = n.trialVel();
    const Matrix& phi = n.eigenvectors();
    for (int i = 0; i < modes; ++i)
      x.col(i + 1) = i < phi.cols() && phi.rows() == n.ndf() ? Vector(phi.col(i)) : Vector::Zero(n.ndf());
    return x;
  };
  for (const auto& [tag, n] : domain.nodes()) {
    if (n->mass().isZero()) continue;
    mass[tag] = n->mass().asDiagonal() * columns(*n);
  }
  for (const auto& [tag, e] : domain.elements()) {
    MatrixView m = e->massMatrix();
    if (m.isZero()) continue;
    Matrix x(e->numDOF(), modes + 1);
    int offset = 0;
    for (const Node* n : e->nodes()) {
      x.middleRows(offset, n->ndf()) = columns(*n);
      offset += n->ndf();
    }
    const Matrix mx = m * x;
    offset = 0;
    for (const Node* n : e->nodes()) {
      auto [it, fresh] = mass.try_emplace(n->tag(), Matrix::Zero(n->ndf(), modes + 1));
      it->second += mx.middleRows(offset, n->ndf());
      offset += n->ndf();
    }
  }
  // q_i = phi_i^T M v and m_i = phi_i^T M phi_i.
  std::vector<double> q(modes, 0.0), generalized(modes, 0.0);
  for (const auto& [tag, mx] : mass) {
    const Matrix x = columns(*domain.findNode(tag));
    for (int i = 0; i < modes; ++i) {
      q[i] += x.col(i + 1).dot(mx.col(0));
      generalized[i] += x.col(i + 1).dot(mx.col(i + 1));
    }
  }
  for (const auto& [tag, mx] : mass) {
    Vector f = Vector::Zero(mx.rows());
    for (int i = 0; i < modes; ++i) {
      if (generalized[i] <= 0.0 || lambda[i] <= 0.0) continue;
      const double zeta = factors_.size() == 1 ? factors_[0] : factors_[i];
      f += (2.0 * zeta * std::sqrt(lambda[i]) * q[i] / generalized[i]) * mx.col(i + 1);
    }
    out.emplace(tag, std::move(f));
  }
  return out;
}

}  // namespace beamsolid
