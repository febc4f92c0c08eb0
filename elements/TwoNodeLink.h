#pragma once
#include <array>
#include <memory>
#include <vector>

#include "elements/Element.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// element('twoNodeLink', tag, iNode, jNode, '-mat', *matTags, '-dir', *dirs,
//         <'-orient', *vecx, *vecyp>, <'-pDelta', *ratios>,
//         <'-shearDist', *sDratios>, <'-doRayleigh'>, <'-mass', m>):
// uncoupled uniaxial springs between two nodes that may be apart (OpenSees'
// TwoNodeLink, Schellenberg), in 2D (nodes of ndf 2 or 3) and 3D (ndf 3 or
// 6). Directions: 2D 1, 2 translations along local x, y and 3 the rotation;
// 3D 1-3 translations along local x, y, z and 4-6 rotations about them.
//
// Local axes (as OpenSeesPy 3.7.1, checked): x from node i to node j (global
// X for coincident nodes), or the -orient x vector. 3D: -orient takes 6
// numbers (x, yp) or 3 (yp, with x from the nodes); without yp, yp is
// global Y, or (-x2, x1, 0) when x is along Y; z = x cross yp, y = z cross x.
// 2D: -orient takes 3 or 6 numbers of which the first 3 are x; y = (-x2, x1).
//
// Basic deformations from the local end displacements (u, theta), with L the
// node distance (even when -orient gives x) and sDy, sDz from -shearDist
// (default 0.5; the shear centre at sD L from node i):
//   d1 = u_xj - u_xi
//   d2 = u_yj - u_yi - sDy L theta_zi - (1 - sDy) L theta_zj
//   d3 = u_zj - u_zi + sDz L theta_yi + (1 - sDz) L theta_yj      (3D)
//   d4..d6 = theta_j - theta_i                                    (3D)
// (2D: d3 = theta_j - theta_i.) Spring k of direction dir_k takes d_dir_k
// and its rate; the end forces are the transpose (the shear carries its
// moment L V to the ends).
//
// -pDelta (2D: ri, rj for M_z; 3D: My_i, My_j, Mz_i, Mz_j ratios): with P the
// force of the direction-1 spring and Delta the relative local transverse
// translation u_j - u_i (not the shear deformation), the moment P Delta goes
// r_i to node i, r_j to node j and the rest (1 - r_i - r_j) to a shear
// couple P Delta / L; measured on OpenSeesPy 3.7.1 and reproduced in the
// local end forces. Without -pDelta there is none. The tangent holds both
// P dDelta and Delta dP (consistent; unsymmetric).
//
// -mass m: lumped, m/2 on each translational dof of both nodes. Rayleigh
// damping only with -doRayleigh (a flag, no value). Dashpot materials
// (Viscous) get the deformation rate and add their damping tangent.
class TwoNodeLink : public Element {
 public:
  static constexpr int kMaxDofs = 12;
  using ForceVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDofs, 1>;
  using StiffnessMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDofs, kMaxDofs>;

  struct Options {
    // -orient: 0, 3 or 6 numbers as given.
    std::vector<double> orient;
    std::vector<double> pDelta;            // empty: no P-Delta
    std::array<double, 2> shearDist{0.5, 0.5};
    bool doRayleigh = false;
    double mass = 0.0;
  };

  // `directions` 1-based as in the command.
  TwoNodeLink(int tag, int iNode, int jNode, const std::vector<const UniaxialMaterial*>& materials,
              const std::vector<int>& directions, const Options& options);

  std::string className() const override { return "twoNodeLink"; }
  bool supportsSpace(int ndm) const override { return ndm == 2 || ndm == 3; }
  bool hasConstantTangent() const override;
  bool needsGeneralSolver() const override { return pDeltaActive_; }

  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  bool doesRayleighDamping() const override { return options_.doRayleigh; }
  bool hasDampingTangent() const override { return true; }
  Matrix dampingTangent() override;

  // 'force'/'globalForce' (2 ndf), 'localForce' (2 ndf, local axes),
  // 'basicForce' (one per spring), 'deformation'/'basicDeformation'/
  // 'basicDisplacement' (one per spring), 'localDisplacement' (2 ndf),
  // 'xaxis'/'yaxis'/'zaxis', 'material' k ....
  Response setResponse(const std::vector<std::string>& args) override;
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void print(std::ostream& os) const override;

  const Matrix3& localAxes() const { return axes_; }
  double length() const { return length_; }
  int numSprings() const { return static_cast<int>(springs_.size()); }

 protected:
  void setDomain(Domain& domain) override;

 private:
  struct Spring {
    std::unique_ptr<UniaxialMaterial> material;
    int direction;
    ForceVector gradient;  // deformation = gradient . global element displacements
  };
  void formAxes(int ndm);
  void formStiffness(bool initial);
  // Local end displacements of global ones.
  ForceVector toLocal(const ForceVector& global) const;
  Vector springValues(bool forces) const;

  std::vector<Spring> springs_;
  Options options_;
  Matrix3 axes_ = Matrix3::Identity();
  double length_ = 0.0;
  // Global -> local end displacements (2 ndf square, orthogonal).
  StiffnessMatrix toLocal_;
  // P-Delta: local end forces = P * pDeltaLocal_ * local displacements; in
  // global dofs pDelta_ = T^T pDeltaLocal_ T; axial_ is the direction-1
  // spring (-1: none).
  bool pDeltaActive_ = false;
  StiffnessMatrix pDelta_;
  int axial_ = -1;

  ForceVector displacement_, velocity_, force_;
  StiffnessMatrix stiffness_, mass_;
};

}  // namespace beamsolid
