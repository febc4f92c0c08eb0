#include "analysis/ModalProperties.h"

#include <Eigen/Sparse>
#include <cmath>
#include <iomanip>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "elements/Element.h"

namespace beamsolid {

namespace {

constexpr double kPi = 3.14159265358979323846;

using SparseMatrix = Eigen::SparseMatrix<double>;

// Fixed-width columns as in OpenSees' report: the first 15 wide, the rest 14.
void header(std::ostream& os, const std::string& first, const std::vector<std::string>& names) {
  os << "#" << std::setw(14) << first;
  for (const auto& n : names) os << std::setw(14) << n;
  os << "\n# -------------";
  for (std::size_t i = 0; i < names.size(); ++i) os << " -------------";
  os << "\n";
}

void row(std::ostream& os, const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) os << std::setw(i == 0 ? 15 : 14) << values[i];
  os << "\n";
}

void modeTable(std::ostream& os, const std::vector<std::string>& names, const std::vector<std::vector<double>>& t) {
  header(os, "MODE", names);
  for (std::size_t m = 0; m < t.size(); ++m) {
    os << std::setw(15) << m + 1;
    for (double v : t[m]) os << std::setw(14) << v;
    os << "\n";
  }
  os << "\n\n";
}

std::vector<std::vector<double>> cumulative(std::vector<std::vector<double>> t) {
  for (std::size_t m = 1; m < t.size(); ++m)
    for (std::size_t d = 0; d < t[m].size(); ++d) t[m][d] += t[m - 1][d];
  return t;
}

std::vector<std::vector<double>> percentOf(std::vector<std::vector<double>> t, const std::vector<double>& total) {
  for (auto& r : t)
    for (std::size_t d = 0; d < r.size(); ++d) r[d] = total[d] != 0.0 ? 100.0 * r[d] / total[d] : 0.0;
  return t;
}

}  // namespace

ModalProperties::ModalProperties(const Domain& domain, const std::vector<double>& eigenvalues, bool unitNormalized)
    : ndm_(domain.ndm() == 0 ? 3 : domain.ndm()), lambda_(eigenvalues) {
  if (eigenvalues.empty()) throw OpenSeesError("modalProperties: no eigenvalues: call eigen first");
  const int numModes = static_cast<int>(eigenvalues.size());
  if (ndm_ == 1) directions_ = {"MX"};
  else if (ndm_ == 2) directions_ = {"MX", "MY", "RMZ"};
  else directions_ = {"MX", "MY", "MZ", "RMX", "RMY", "RMZ"};
  const int numDirections = static_cast<int>(directions_.size());

  // Every node dof gets a row, in node tag order.
  std::map<int, int> offset;
  int size = 0;
  for (const auto& [tag, node] : domain.nodes()) {
    offset[tag] = size;
    size += node->ndf();
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& [tag, node] : domain.nodes())
    for (int i = 0; i < node->mass().size(); ++i)
      if (node->mass()[i] != 0.0) entries.emplace_back(offset[tag] + i, offset[tag] + i, node->mass()[i]);
  for (const auto& [tag, element] : domain.elements()) {
    MatrixView me = element->massMatrix();
    std::vector<int> rows;
    for (int n : element->nodeTags()) {
      const Node* node = domain.findNode(n);
      if (!node) continue;
      for (int i = 0; i < node->ndf(); ++i) rows.push_back(offset[n] + i);
    }
    if (static_cast<int>(rows.size()) != me.rows()) continue;  // multiplier dofs carry no mass
    for (int j = 0; j < me.cols(); ++j)
      for (int i = 0; i < me.rows(); ++i)
        if (me(i, j) != 0.0) entries.emplace_back(rows[i], rows[j], me(i, j));
  }
  SparseMatrix mass(size, size);
  mass.setFromTriplets(entries.begin(), entries.end());

  // Free mass: the rows and columns of constrained (sp/fix) dofs removed.
  Vector freeMask = Vector::Ones(size);
  for (const SPConstraint& sp : domain.sps())
    if (auto it = offset.find(sp.nodeTag); it != offset.end()) freeMask[it->second + sp.dof] = 0.0;
  SparseMatrix freeMass = freeMask.asDiagonal() * mass * freeMask.asDiagonal();

  // Totals and the centre of mass come from masses lumped to the dofs, as
  // OpenSees lumps them: each row of M summed over the columns of the same
  // dof (x with x, rz with rz) at every node. A diagonal M is its own lumping.
  std::vector<int> localDof(size);
  for (const auto& [tag, node] : domain.nodes())
    for (int i = 0; i < node->ndf(); ++i) localDof[offset[tag] + i] = i;
  Vector lumped = Vector::Zero(size);
  for (int j = 0; j < mass.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(mass, j); it; ++it)
      if (localDof[it.row()] == localDof[it.col()]) lumped[it.row()] += it.value();

  // Translations and where they act: the centre of mass of the free mass.
  auto translation = [&](int k) {
    Vector r = Vector::Zero(size);
    for (const auto& [tag, node] : domain.nodes())
      if (k < node->ndf()) r[offset[tag] + k] = 1.0;
    return r;
  };
  centre_.assign(ndm_, 0.0);
  for (int k = 0; k < ndm_; ++k) {
    const Vector r = translation(k);
    Vector at = Vector::Zero(size);
    for (const auto& [tag, node] : domain.nodes())
      if (k < node->ndf()) at[offset[tag] + k] = node->crd()[k];
    const double m = r.dot(freeMask.cwiseProduct(lumped));
    if (m != 0.0) centre_[k] = at.dot(freeMask.cwiseProduct(lumped)) / m;
  }
  // A unit rotation about global axis `axis` through the centre of mass:
  // translations e_axis x (x - c) and the node's own rotation dof, if any.
  auto rotation = [&](int axis) {
    Vector r = Vector::Zero(size);
    Vector3 c = Vector3::Zero();
    for (int k = 0; k < ndm_; ++k) c[k] = centre_[k];
    Vector3 e = Vector3::Zero();
    e[axis] = 1.0;
    const int rotationDof = ndm_ == 2 ? 2 : 3 + axis;
    const int translations = ndm_;
    for (const auto& [tag, node] : domain.nodes()) {
      const Vector3 u = e.cross(node->crd() - c);
      for (int k = 0; k < translations && k < node->ndf(); ++k) r[offset[tag] + k] = u[k];
      if (node->ndf() > rotationDof) r[offset[tag] + rotationDof] = 1.0;
    }
    return r;
  };
  std::vector<Vector> rigid;
  for (int k = 0; k < ndm_; ++k) rigid.push_back(translation(k));
  if (ndm_ == 2) rigid.push_back(rotation(2));
  if (ndm_ == 3)
    for (int axis = 0; axis < 3; ++axis) rigid.push_back(rotation(axis));
  for (const Vector& r : rigid) {
    const Vector r2 = r.cwiseProduct(r);
    totalMass_.push_back(r2.dot(lumped));
    freeMass_.push_back(r2.dot(freeMask.cwiseProduct(lumped)));
  }

  for (int mode = 0; mode < numModes; ++mode) {
    Vector phi = Vector::Zero(size);
    double largest = 0.0;
    for (const auto& [tag, node] : domain.nodes()) {
      const Matrix& v = node->eigenvectors();
      if (v.cols() <= mode || v.rows() != node->ndf())
        throw OpenSeesError("modalProperties: node " + std::to_string(tag) + " has no eigenvector " +
                            std::to_string(mode + 1) + ": call eigen after the model is complete");
      phi.segment(offset[tag], node->ndf()) = v.col(mode);
      for (int k = 0; k < node->ndf(); ++k) largest = std::max(largest, std::abs(v(k, mode)));
    }
    if (unitNormalized && largest > 0.0) phi /= largest;
    // The free dofs' mass only: the coupling of a consistent mass to the
    // supports does not take part (as in OpenSees).
    const Vector mPhi = freeMass * phi;
    const double generalized = phi.dot(mPhi);
    std::vector<double> factor(numDirections), effective(numDirections);
    for (int d = 0; d < numDirections; ++d) {
      const double l = rigid[d].dot(mPhi);
      factor[d] = generalized != 0.0 ? l / generalized : 0.0;
      effective[d] = generalized != 0.0 ? l * l / generalized : 0.0;
    }
    factor_.push_back(factor);
    mass_.push_back(effective);
  }
}

std::map<std::string, std::vector<double>> ModalProperties::toDict() const {
  std::map<std::string, std::vector<double>> d;
  d["domainSize"] = {static_cast<double>(ndm_)};
  for (double l : lambda_) {
    const double omega = std::sqrt(std::abs(l));
    d["eigenLambda"].push_back(l);
    d["eigenOmega"].push_back(omega);
    d["eigenFrequency"].push_back(omega / (2.0 * kPi));
    d["eigenPeriod"].push_back(2.0 * kPi / omega);
  }
  d["totalMass"] = totalMass_;
  d["totalFreeMass"] = freeMass_;
  d["centerOfMass"] = centre_;
  const auto cumu = cumulative(mass_);
  const auto ratios = percentOf(mass_, freeMass_);
  const auto cumuRatios = percentOf(cumu, freeMass_);
  for (std::size_t k = 0; k < directions_.size(); ++k) {
    const std::string& n = directions_[k];
    for (std::size_t m = 0; m < mass_.size(); ++m) {
      d["partiFactor" + n].push_back(factor_[m][k]);
      d["partiMass" + n].push_back(mass_[m][k]);
      d["partiMassesCumu" + n].push_back(cumu[m][k]);
      d["partiMassRatios" + n].push_back(ratios[m][k]);
      d["partiMassRatiosCumu" + n].push_back(cumuRatios[m][k]);
    }
  }
  return d;
}

void ModalProperties::report(std::ostream& os) const {
  const auto d = toDict();
  os << "# MODAL ANALYSIS REPORT\n\n";
  os << "* 1. DOMAIN SIZE:\n"
        "# This is the size of the problem: 1 for 1D problems, 2 for 2D problems, 3 for 3D problems.\n"
     << ndm_ << "\n\n\n";
  os << "* 2. EIGENVALUE ANALYSIS:\n";
  header(os, "MODE", {"LAMBDA", "OMEGA", "FREQUENCY", "PERIOD"});
  for (std::size_t m = 0; m < lambda_.size(); ++m) {
    os << std::setw(15) << m + 1;
    for (const char* key : {"eigenLambda", "eigenOmega", "eigenFrequency", "eigenPeriod"})
      os << std::setw(14) << d.at(key)[m];
    os << "\n";
  }
  os << "\n\n";
  os << "* 3. TOTAL MASS OF THE STRUCTURE:\n"
        "# The total masses (translational and rotational) of the structure\n"
        "# including the masses at fixed DOFs (if any).\n";
  header(os, directions_[0], {directions_.begin() + 1, directions_.end()});
  row(os, totalMass_);
  os << "\n\n";
  os << "* 4. TOTAL FREE MASS OF THE STRUCTURE:\n"
        "# The total masses (translational and rotational) of the structure\n"
        "# including only the masses at free DOFs.\n";
  header(os, directions_[0], {directions_.begin() + 1, directions_.end()});
  row(os, freeMass_);
  os << "\n\n";
  os << "* 5. CENTER OF MASS:\n"
        "# The center of mass of the structure, calculated from free masses.\n";
  const std::vector<std::string> axes = {"X", "Y", "Z"};
  header(os, "X", {axes.begin() + 1, axes.begin() + ndm_});
  row(os, centre_);
  os << "\n\n";
  os << "* 6. MODAL PARTICIPATION FACTORS:\n"
        "# The participation factor for a certain mode 'a' in a certain direction 'i'\n"
        "# indicates how strongly displacement along (or rotation about)\n"
        "# the global axes is represented in the eigenvector of that mode.\n";
  modeTable(os, directions_, factor_);
  os << "* 7. MODAL PARTICIPATION MASSES:\n"
        "# The modal participation masses for each mode.\n";
  modeTable(os, directions_, mass_);
  os << "* 8. MODAL PARTICIPATION MASSES (cumulative):\n"
        "# The cumulative modal participation masses for each mode.\n";
  modeTable(os, directions_, cumulative(mass_));
  os << "* 9. MODAL PARTICIPATION MASS RATIOS (%):\n"
        "# The modal participation mass ratios (%) for each mode.\n";
  modeTable(os, directions_, percentOf(mass_, freeMass_));
  os << "* 10. MODAL PARTICIPATION MASS RATIOS (%) (cumulative):\n"
        "# The cumulative modal participation mass ratios (%) for each mode.\n";
  modeTable(os, directions_, percentOf(cumulative(mass_), freeMass_));
}

}  // namespace beamsolid
