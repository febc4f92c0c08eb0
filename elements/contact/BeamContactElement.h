#pragma once
#include <memory>

#include "elements/Element.h"
#include "elements/contact/BeamContactGeometry.h"
#include "elements/transforms/CrdTransf.h"
#include "materials/nd/ContactMaterial3D.h"

namespace beamsolid {

// What BeamContact3D (Lagrange multiplier) and BeamContact3Dp (penalty) share:
// the beam segment a-b with its geometric transformation, the secondary node
// s, the surface geometry and kinematics (BeamContactGeometry), the element's
// own ContactMaterial3D copy, the contact status, friction stage forwarding
// and the recorder responses. The derived classes supply the normal force
// (multiplier or penalty) and the element matrices.
//
// Sign conventions: positive normal force is compression (the pile pushes
// the soil outward along n). "force" is the contact force acting on the
// secondary node; the primary* responses are the contact forces and moments
// acting on the beam nodes (equivalent nodal actions of the reaction on the
// pile); together they are in equilibrium.
class BeamContactElement : public Element {
 public:
  using Vector2 = Eigen::Vector2d;
  using Matrix2 = Eigen::Matrix2d;
  using Vector15 = BeamContactGeometry::Vector15;

  enum class Status { Separated = 0, Sticking = 1, Sliding = 2 };

  // --- read access (for tests, recorders and Python helpers) ---------------------
  const BeamContactGeometry& geometry() const { return geometry_; }
  const ContactMaterial3D& material() const { return *material_; }
  double radius() const { return radius_; }
  // The status of the current step (decided at the last commit, C20).
  bool inContact() const { return inContact_; }
  // Normal force t_n of the trial state (lambda or the penalty force); zero
  // out of contact.
  double normalForce() const { return normalForce_; }
  // Status of the last update: separated, sticking or sliding.
  Status status() const;
  // The following describe the state of the last update() (also after a
  // commit has re-projected the node), so that recorded values belong together.
  // Contact force acting on the secondary node (global): t_n n - T_alpha g^alpha.
  Vector3 contactForce() const { return normalForce_ * normalAtUpdate_ + frictionForce_; }
  // Its frictional part, -T_alpha g^alpha.
  const Vector3& frictionForce() const { return frictionForce_; }
  // [t_n, friction along g_xi, friction along g_psi] acting on the secondary
  // node (the friction components are -T_alpha / |g_alpha|).
  const Vector3& forceScalars() const { return forceScalars_; }
  // Relative slip of the secondary node over the pile surface while in
  // contact, accumulated since the start: [along g_xi, along g_psi] as
  // arc lengths (s^xi |g_xi|, s^psi |g_psi| summed over steps).
  Vector2 totalSlip() const { return committedSlip_ + slipIncrement_; }
  // Gap, xi_c and normal n used by the last update.
  double gap() const { return gapAtUpdate_; }
  double xi() const { return xiAtUpdate_; }
  const Vector3& normal() const { return normalAtUpdate_; }
  // Resisting force on the 15 mechanical dofs [u_a, th_a, u_b, th_b, u_s].
  const Vector15& mechanicalForce() const { return mechanicalForce_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // 'friction' (0 frictionless, 1 frictional) and the material's parameters
  // ('mu', 'G', 'c', 't'), forwarded to this element's material copy.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  void updateMaterialStage(int materialTag, int stage) override;
  // Multipliers (zero diagonal) and sliding friction (unsymmetric tangent).
  bool needsGeneralSolver() const override { return true; }

  // force (3), frictionforce (3), forcescalar (3), masterforce|primaryforce (6),
  // mastermoment|primarymoment (6), masterreaction|primaryreaction (12),
  // slip (2), gap (1), status (1: 0 separated, 1 sticking, 2 sliding), xi (1),
  // normal (3). Names are matched case-insensitively.
  Response setResponse(const std::vector<std::string>& args) override;

  void print(std::ostream& os) const override;

 protected:
  BeamContactElement(int tag, std::vector<int> nodeTags, double radius, std::unique_ptr<CrdTransf> transf,
                     std::unique_ptr<ContactMaterial3D> material, bool initiallyInContact);

  // Checks the beam and secondary nodes, initializes the transformation and
  // the geometry, and sets the initial status.
  void setUpGeometry();
  // Geometry from the nodes' trial state (allocation-free).
  void updateGeometry();
  // Keeps what the responses report from this update (allocation-free);
  // derived classes call it at the end of update().
  void storeResponseState();
  // The status for the next step from the converged state (C20); called
  // by commitState() after the geometry was re-projected. convergedGap is
  // the step's gap at the held projection (C10), before re-projection.
  virtual bool nextContactStatus(double convergedGap) = 0;
  // Whether the status at the start is "in contact" (cSwitch == 0).
  bool initiallyInContact() const { return initiallyInContact_; }

  const Node& nodeA() const { return *nodes()[0]; }
  const Node& nodeB() const { return *nodes()[1]; }
  const Node& nodeS() const { return *nodes()[2]; }

  BeamContactGeometry geometry_;
  std::unique_ptr<ContactMaterial3D> material_;
  bool inContact_ = false;
  // Whether the last update() applied contact forces (its status).
  bool activeInUpdate_ = false;
  double normalForce_ = 0.0;
  Vector15 mechanicalForce_ = Vector15::Zero();

 private:
  double radius_;
  std::unique_ptr<CrdTransf> transf_;
  bool initiallyInContact_;
  Vector2 committedSlip_ = Vector2::Zero();
  // Response state of the last update.
  Vector3 frictionForce_ = Vector3::Zero();
  Vector3 forceScalars_ = Vector3::Zero();
  Vector2 slipIncrement_ = Vector2::Zero();
  double gapAtUpdate_ = 0.0;
  double xiAtUpdate_ = 0.0;
  Vector3 normalAtUpdate_ = Vector3::Zero();
};

// The element's copy of material matTag: a ContactMaterial3D, or a clear
// error naming the command (context) and what the material is.
std::unique_ptr<ContactMaterial3D> cloneContactMaterial(const NDMaterial& prototype, const std::string& context);

}  // namespace beamsolid
