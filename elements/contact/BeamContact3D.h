#pragma once
#include "elements/contact/BeamContactElement.h"
#include "elements/contact/ContactMultiplier.h"

namespace beamsolid {

class Domain;

// Frictional beam-solid contact with a Lagrange multiplier for the normal
// force (Arduino, Petek & Mackenzie-Helnwein 2007; beam_contact_formulation.md):
//   element('BeamContact3D', tag, iNode, jNode, sNode, lNode, radius, transfTag,
//           matTag, gapTol, forceTol, <cSwitch=0>, <'-pile', *beamNodeTags>)
// iNode, jNode: beam nodes (ndf 6); sNode: solid node (ndf 3); lNode: this
// element's own multiplier node (ndf 3, free, used by no other element): its
// first dof is the normal force lambda (positive = compression), the other
// two are inert. 18 dofs [u_a, th_a, u_b, th_b, u_s, lambda, -, -].
//
// In contact (C17, C18): F = lambda B_n + T_alpha B_s^alpha, F_lambda = -g;
// out of contact: no force on the mechanical dofs and F_lambda = lambda with
// unit stiffness so lambda returns to zero.
//
// Contact status (C20) is decided at commit, not inside the Newton loop:
// in contact next step iff g < gapTol, lambda > -forceTol at the last update,
// and 0 < xi_c < 1 after re-projection. For a node in contact during the step
// g is the converged gap at the held projection (the one lambda drove to
// zero); for a released node it is the re-projected distance. (The
// re-projected distance of a node in contact exceeds the radius by the
// tangent-plane drift ~ slip^2 / 2R of a step's circumferential sliding,
// which would release sliding nodes for any small gapTol.) A change of
// status is seen one step late; the error this lag makes shrinks with the
// step size. cSwitch 0 starts in contact, 1 out of contact.
//
// '-pile', *beamNodeTags: the ordered beam nodes of the whole pile (iNode,
// jNode consecutive in it): the chained form of BeamContactElement, which
// hands the soil node over to the neighbouring segment instead of releasing
// it, so "inside the segment" above becomes "along the pile".
class BeamContact3D : public BeamContactElement {
 public:
  using Vector18 = Eigen::Matrix<double, 18, 1>;
  using Matrix18 = Eigen::Matrix<double, 18, 18>;

  BeamContact3D(int tag, int iNode, int jNode, int sNode, int lNode, double radius, std::unique_ptr<CrdTransf> transf,
                std::unique_ptr<ContactMaterial3D> material, double gapTolerance, double forceTolerance,
                int cSwitch, std::vector<int> pileNodeTags = {});

  std::string className() const override { return "BeamContact3D"; }

  void update() override;
  MatrixView tangentStiff() override { return viewOf(stiffness_); }
  // The current tangent (contact has no meaningful initial stiffness).
  MatrixView initialStiff() override { return viewOf(stiffness_); }
  VectorView resistingForce() override { return viewOf(force_); }

  // Lambda (dof 1 of the multiplier node) at the last update.
  double lambda() const { return multiplier_.lambda(); }
  // lambda <= -forceTol at the last update: contact is released at commit.
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
  // In a transient analysis the contact holds a target gap g_n + 3/4 dt
  // gdot_n + dt^2/8 gddot_n over a step instead of g = 0: an inelastic
  // impact spread over two steps of the trapezoidal rule, instead of the
  // node being thrown out of a penetration it reached while open (which
  // pumps energy into every closing). Formed once per step; 0 in statics.
  double gapTarget();

  ContactMultiplier multiplier_;
  const Domain* domain_ = nullptr;
  double targetTime_ = 0.0;
  double target_ = 0.0;
  bool targetValid_ = false;
  Vector18 force_ = Vector18::Zero();
  Matrix18 stiffness_ = Matrix18::Zero();
};

}  // namespace beamsolid
