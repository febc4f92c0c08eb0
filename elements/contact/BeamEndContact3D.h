#pragma once
#include "elements/contact/BeamEndContactElement.h"
#include "elements/contact/ContactMultiplier.h"

namespace beamsolid {

// End bearing of a pile tip on a solid node with a Lagrange multiplier for
// the normal force (docs/beam_contact.md, "End bearing"):
//   element('BeamEndContact3D', tag, iNode, jNode, sNode, lNode, radius,
//           gapTol, forceTol, <cFlag=0>)
// iNode: the beam end node (ndf 6), jNode: the other node of the end element
// (ndf 6; gives the axis, n points from j to i); sNode: solid node (ndf 3);
// lNode: this element's own multiplier node (ndf 3, free, used by no other
// element): its first dof is the normal force lambda (positive = compression),
// the other two are inert. 18 dofs [u_i, th_i, u_j, th_j, u_s, lambda, -, -].
//
// From dW = lambda dg + dlambda g (E5): in contact F = lambda B, F_lambda = -g,
// K_qq = -lambda H (the face turns with the tip), K_q,lambda = B,
// K_lambda,q = B^T; out of contact no force on the mechanical dofs and
// F_lambda = lambda with unit stiffness so lambda returns to zero.
//
// Status (C20), decided at commit: in contact next step iff g < gapTol
// (the converged gap for a node in contact, the gap with the committed
// normal for a released one), lambda > -forceTol at the last update, and
// the node within the face (E7). Opening and closing are seen one step late.
class BeamEndContact3D : public BeamEndContactElement {
 public:
  using Vector18 = Eigen::Matrix<double, 18, 1>;
  using Matrix18 = Eigen::Matrix<double, 18, 18>;

  BeamEndContact3D(int tag, int iNode, int jNode, int sNode, int lNode, double radius, double gapTolerance,
                   double forceTolerance, int cFlag);

  std::string className() const override { return "BeamEndContact3D"; }

  void update() override;
  MatrixView tangentStiff() override { return viewOf(stiffness_); }
  // The current tangent (contact has no meaningful initial stiffness).
  MatrixView initialStiff() override { return viewOf(stiffness_); }
  VectorView resistingForce() override { return viewOf(force_); }
  // Zero multiplier diagonal.
  bool needsGeneralSolver() const override { return true; }

  double lambda() const { return multiplier_.lambda(); }
  bool shouldRelease() const { return multiplier_.shouldRelease(); }
  double gapTolerance() const { return multiplier_.gapTolerance(); }
  double forceTolerance() const { return multiplier_.forceTolerance(); }
  // The last node carries lambda.
  std::vector<int> multiplierNodes() const override { return {nodeTags().back()}; }
  // The multiplier node's two inert dofs (unit stiffness, ContactMultiplier::setRows).
  bool hasConstantUncoupledDof(int i) const override { return i >= numDOF() - 2; }

 protected:
  void setDomain(Domain& domain) override;
  bool nextContactStatus(double convergedGap) override;

 private:
  ContactMultiplier multiplier_;
  Vector18 force_ = Vector18::Zero();
  Matrix18 stiffness_ = Matrix18::Zero();
};

}  // namespace beamsolid
