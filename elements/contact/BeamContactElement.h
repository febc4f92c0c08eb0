#pragma once
#include <memory>
#include <vector>

#include "elements/Element.h"
#include "elements/contact/BeamContactGeometry.h"
#include "elements/contact/BeamContactPile.h"
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
//
// Chained form ('-pile', *beamNodeTags): the element belongs to a whole pile
// (BeamContactPile, shared by the pile's contact elements) instead of one
// segment. At commit, when the re-projected xi_c leaves [0, 1] and the pile
// continues there, the element hands its soil node over to the neighbouring
// segment: it re-projects onto it, keeps its material copy (the friction
// state, expressed in the new surface coordinates), its multiplier node and
// lambda and its contact status, and re-connects to the new beam nodes
// (Element::reconnect, so the analysis renumbers before the next step). The
// nodal frames of every segment come from the pile's shared frames, so a
// handed-over element sees exactly the frames the elements already on that
// segment track. A chained element owns its node anywhere along the pile --
// also exactly level with a beam node (closed interval, with a hand-over
// tolerance of 1e-9 in xi so that such a node does not flip between the two
// segments) -- and releases it only beyond the pile's ends.
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
  // Hand-over hysteresis in xi: a chained element moves to the next segment
  // only once xi_c > 1 + tol (or < -tol).
  static constexpr double kHandOverTolerance = 1e-9;
  // How far (in xi of the end segment) a chained element keeps a node that has
  // moved beyond the pile's head or tip. A node level with the end stands for
  // the half soil layer below it; releasing it once it lies any distance beyond
  // (the tilt R*theta of a bent pile's end section does this at the first
  // step) dropped the most loaded contacts of a laterally loaded pile. It is
  // released once less than half its tributary height still faces the pile:
  // a quarter segment beyond the end, for soil levels at the beam nodes.
  static constexpr double kEndAllowance = 0.25;
  // The pile of the chained form (nullptr without '-pile'), the index of the
  // element's current segment in it (-1 without), and how many hand-overs
  // happened since the start.
  const BeamContactPile* pile() const { return pile_.get(); }
  int segment() const { return segment_; }
  int handOverCount() const { return handOvers_; }
  // Whether the element holds its node's projection: 0 < xi_c < 1 without a
  // chain; with a chain anywhere along the pile and up to `endAllowance`
  // beyond its ends (kEndAllowance once the analysis runs; kHandOverTolerance
  // at set-up, so that a node that starts beyond an end is never in contact).
  bool ownsNode(double endAllowance = kEndAllowance) const;
  // The status of the current step (decided at the last commit, C20).
  bool inContact() const { return inContact_; }
  // Normal force t_n of the trial state (lambda or the penalty force); zero
  // out of contact.
  double normalForce() const { return normalForce_; }
  // Status of the last update: separated, sticking or sliding. (After a
  // hand-over the element updates once more, on the new segment with no slip
  // increment; it reports the status its step converged with.)
  Status status() const;
  // The following describe the state of the last update() (also after a
  // commit has re-projected the node), so that recorded values belong together.
  // Contact force acting on the secondary node (global): t_n n - T_alpha g^alpha.
  Vector3 contactForce() const { return normalForce_ * normalAtUpdate_ + frictionForce_; }
  // Its frictional part, -T_alpha g^alpha.
  const Vector3& frictionForce() const { return frictionForce_; }
  // [t_n, friction along g_xi, friction along g_psi] acting on the secondary
  // node (the friction components are -T_alpha / |g_alpha|), in force units.
  const Vector3& forceScalars() const { return forceScalars_; }
  // OpenSees' forcescalar: [t_n, T_xi, T_psi], the friction tractions as
  // covariant components on the unnormalised surface base (T_xi ~ -L times
  // the axial friction force on the secondary node, T_psi ~ -R times the
  // circumferential one).
  Vector3 surfaceForceScalars() const { return Vector3(forceScalars_(0), surfaceTraction_(0), surfaceTraction_(1)); }
  // OpenSees' slip: the last step's slip s^alpha in the surface's parametric
  // coordinates (xi per segment length, psi in radians), kept after commit.
  const Vector2& surfaceSlip() const { return surfaceSlip_; }
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
  // No Rayleigh damping: the multiplier rows are constraints, not stiffness. betaK
  // on them turns a released node's lambda = 0 into lambda + betaK dlambda/dt = 0,
  // so lambda stays negative and the node never closes again (it sinks into the pile).
  bool doesRayleighDamping() const override { return false; }

  // As OpenSees: force (3), frictionforce (3, on the pile), forcescalar (3),
  // masterforce|primaryforce (6), mastermoment|primarymoment (6),
  // masterreaction|primaryreaction (12), slip (2). Ours: soilFrictionForce (3),
  // physicalForceScalar (3: N and the friction along and around the pile on
  // the soil node, in force units), totalSlip (2: metres along and around the
  // pile since the start), gap (1), status (1: 0 separated, 1 sticking, 2 sliding), xi (1),
  // normal (3), segment (2: the current beam node tags), handovers (1).
  // Names are matched case-insensitively.
  Response setResponse(const std::vector<std::string>& args) override;

  void print(std::ostream& os) const override;

 protected:
  // pileNodeTags: the '-pile' chain (empty: a single segment).
  BeamContactElement(int tag, std::vector<int> nodeTags, double radius, std::unique_ptr<CrdTransf> transf,
                     std::unique_ptr<ContactMaterial3D> material, bool initiallyInContact,
                     std::vector<int> pileNodeTags);

  // Checks the beam and secondary nodes, initializes the transformation (or
  // joins the pile and moves to the segment that holds the node's
  // projection) and the geometry, and sets the initial status.
  void setUpGeometry(Domain& domain);
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
  // Chained form: moves the element along the pile while its projection lies
  // beyond the current segment and the next segment holds it; re-connects.
  // base: the covariant base vectors g_alpha in which the material's elastic
  // slip is expressed (those of the step's held projection). Returns the
  // number of segments moved.
  int handOver(Vector3 base[2]);
  // The geometry of the current segment from the pile's frames.
  void initializeOnPile(double xiStart);

  double radius_;
  std::unique_ptr<CrdTransf> transf_;
  bool initiallyInContact_;
  std::vector<int> pileNodeTags_;
  std::shared_ptr<BeamContactPile> pile_;
  int segment_ = -1, initialSegment_ = -1;
  int handOvers_ = 0;
  // The step before this commit's hand-over converged sliding (status()).
  bool slidingAcrossHandOver_ = false;
  Vector2 committedSlip_ = Vector2::Zero();
  // Response state of the last update.
  Vector3 frictionForce_ = Vector3::Zero();
  Vector3 forceScalars_ = Vector3::Zero();
  Vector2 slipIncrement_ = Vector2::Zero();
  Vector2 surfaceTraction_ = Vector2::Zero();
  Vector2 surfaceSlip_ = Vector2::Zero();
  double gapAtUpdate_ = 0.0;
  double xiAtUpdate_ = 0.0;
  Vector3 normalAtUpdate_ = Vector3::Zero();
};

// The element's copy of material matTag: a ContactMaterial3D, or a clear
// error naming the command (context) and what the material is.
std::unique_ptr<ContactMaterial3D> cloneContactMaterial(const NDMaterial& prototype, const std::string& context);

}  // namespace beamsolid
