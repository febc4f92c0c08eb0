#pragma once
#include <array>
#include <memory>

#include "elements/Element.h"
#include "sections/PlateSection.h"

namespace beamsolid {

// element('ShellMITC4', tag, n1, n2, n3, n4, secTag): a flat four-node shell
// (6 dofs per node) of a plate section, geometrically linear. In the local
// frame of its mid-plane (e1 along the xi direction, e3 the normal):
//  - membrane: bilinear u, v, with the drilling rotation tied to the
//    in-plane rotation by a penalty (Hughes and Brezzi 1989),
//    gamma_d * integral of (theta_z - (v,x - u,y)/2)^2, gamma_d = the
//    section's initial membrane shear stiffness (G h);
//  - plate: bilinear w and rotations (Reissner-Mindlin), bending from the
//    rotations, transverse shear by the MITC4 assumed strains of Dvorkin and
//    Bathe (1984): covariant shears tied at the edge midpoints, turned into
//    x, y with the xi and eta directions at the centre;
// 2x2 Gauss points, counterclockwise from node 1's corner. Rotations are
// right-handed about the axes: gamma13 = w,x + theta_y, gamma23 = w,y -
// theta_x, kappa11 = theta_y,x, kappa22 = -theta_x,y, kappa12 = theta_y,y -
// theta_x,x. Mass: consistent on the translations (rho h), none on the
// rotations. Checked against OpenSeesPy 3.7.1 (oracle script shells).
class ShellMITC4 : public Element {
 public:
  static constexpr int kNodes = 4;
  static constexpr int kDofs = 24;
  using Matrix24 = Eigen::Matrix<double, kDofs, kDofs>;
  using Vector24 = Eigen::Matrix<double, kDofs, 1>;

  ShellMITC4(int tag, const std::array<int, kNodes>& nodeTags, const PlateSection& section);

  std::string className() const override { return "ShellMITC4"; }
  bool hasConstantTangent() const override;

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 'force'/'forces'/'globalForce'/'globalForces' (24), 'stresses'/'stress'
  // (8 section forces at each of the 4 Gauss points), 'strains'/'strain',
  // 'section'/'material' i ... forwarded to Gauss point i.
  Response setResponse(const std::vector<std::string>& args) override;

 protected:
  void setDomain(Domain& domain) override;

 private:
  using StrainMatrix = Eigen::Matrix<double, PlateSection::kOrder, kDofs>;
  using DrillRow = Eigen::Matrix<double, 1, kDofs>;

  // Local dofs from the global ones (nodal translations and rotations).
  Vector24 localDisplacements() const;
  void form(bool initial);

  std::array<std::unique_ptr<PlateSection>, 4> sections_;
  Eigen::Matrix3d frame_ = Eigen::Matrix3d::Identity();  // rows e1, e2, e3
  std::array<StrainMatrix, 4> B_{};                         // local generalized strains per Gauss point
  std::array<DrillRow, 4> drill_{};                         // theta_z - (v,x - u,y)/2
  std::array<double, 4> weight_{};                          // Gauss weight times det J
  Eigen::Matrix<double, kDofs, kDofs> transform_ = Eigen::Matrix<double, kDofs, kDofs>::Identity();
  double drillStiffness_ = 0.0;
  Matrix24 stiffness_ = Matrix24::Zero();
  Matrix24 mass_ = Matrix24::Zero();
  Vector24 force_ = Vector24::Zero();
};

}  // namespace beamsolid
