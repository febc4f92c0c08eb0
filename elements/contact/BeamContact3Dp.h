#pragma once
#include "elements/contact/BeamContactElement.h"

namespace beamsolid {

class Domain;

// Penalty form of BeamContact3D (beam_contact_formulation.md, C19):
//   element('BeamContact3Dp', tag, iNode, jNode, sNode, radius, transfTag,
//           matTag, penalty, <cSwitch=0>, <'-pile', *beamNodeTags>)
// 15 dofs [u_a, th_a, u_b, th_b, u_s]. The normal force is t_n = kappa <-g>
// (positive = compression), so F = t_n B_n + T_alpha B_s^alpha and, while the
// node penetrates, K = kappa B_n B_n^T + B_s C_ss B_s^T + kappa B_s C_sn B_n^T.
// A node with g >= 0 carries no force (and its friction memory is reset).
//
// The Macaulay bracket decides separation and re-contact inside the Newton
// loop; at commit the element only checks that the node still projects
// inside the segment (0 < xi_c < 1). cSwitch 1 (no contact initially)
// leaves the element inactive until the first converged step at which the
// node has penetrated (g < 0), one step late as in C20. '-pile' gives the
// chained form (BeamContactElement): the node is handed over along the pile
// and the commit check becomes "along the pile".
class BeamContact3Dp : public BeamContactElement {
 public:
  using Matrix15 = Eigen::Matrix<double, 15, 15>;

  BeamContact3Dp(int tag, int iNode, int jNode, int sNode, double radius, std::unique_ptr<CrdTransf> transf,
                 std::unique_ptr<ContactMaterial3D> material, double penalty, int cSwitch,
                 std::vector<int> pileNodeTags = {});

  std::string className() const override { return "BeamContact3Dp"; }

  void update() override;
  MatrixView tangentStiff() override { return viewOf(stiffness_); }
  MatrixView initialStiff() override { return viewOf(stiffness_); }
  VectorView resistingForce() override { return viewOf(mechanicalForce_); }

  void revertToStart() override;

  double penalty() const { return penalty_; }
  // False until contact was first seen (cSwitch 1); true from the start with cSwitch 0.
  bool activated() const { return activated_; }

 protected:
  void setDomain(Domain& domain) override;
  bool nextContactStatus(double convergedGap) override;

 private:
  double penalty_;
  bool activated_;
  Matrix15 stiffness_ = Matrix15::Zero();
};

}  // namespace beamsolid
