#pragma once
#include "elements/contact/BeamEndContactElement.h"

namespace beamsolid {

// Penalty form of BeamEndContact3D (docs/beam_contact.md, "End bearing", E6):
//   element('BeamEndContact3Dp', tag, iNode, jNode, sNode, radius, penalty,
//           <cFlag=0>)
// 15 dofs [u_i, th_i, u_j, th_j, u_s]. The normal force is t_n = kappa <-g>
// (positive = compression): while the node penetrates F = t_n B and
// K = kappa B B^T - t_n H; a node with g >= 0 carries no force.
//
// The Macaulay bracket decides separation and re-contact inside the Newton
// loop; at commit the element only checks that the node still lies within
// the face (E7). cFlag 1 leaves the element inactive until the first
// converged step at which the node has penetrated the face (g < 0), one
// step late as in C20.
class BeamEndContact3Dp : public BeamEndContactElement {
 public:
  BeamEndContact3Dp(int tag, int iNode, int jNode, int sNode, double radius, double penalty, int cFlag);

  std::string className() const override { return "BeamEndContact3Dp"; }

  void update() override;
  MatrixView tangentStiff() override { return viewOf(stiffness_); }
  MatrixView initialStiff() override { return viewOf(stiffness_); }
  VectorView resistingForce() override { return viewOf(mechanicalForce_); }

  void revertToStart() override;

  double penalty() const { return penalty_; }
  // False until contact was first seen (cFlag 1); true from the start with cFlag 0.
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
