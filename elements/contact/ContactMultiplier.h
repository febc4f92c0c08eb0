#pragma once
#include <string>

#include "core/Types.h"

namespace beamsolid {

class Domain;
class Element;
class Node;

// The Lagrange multiplier node of a contact element and the contact status
// rule that goes with it (beam_contact_formulation.md, C18 and C20), shared
// by BeamContact3D (shaft) and BeamEndContact3D (pile tip).
//
// The node's first dof is the normal force lambda (positive = compression),
// the other two are inert and get unit stiffness. Out of contact its row is
// F_lambda = lambda with unit stiffness, so lambda returns to zero; in
// contact it is F_lambda = -g (the element adds the coupling to its dofs).
class ContactMultiplier {
 public:
  ContactMultiplier(double gapTolerance, double forceTolerance)
      : gapTolerance_(gapTolerance), forceTolerance_(forceTolerance) {}

  double gapTolerance() const { return gapTolerance_; }
  double forceTolerance() const { return forceTolerance_; }

  // At setDomain: the node has ndf 3, is not fixed, has no imposed
  // displacement or multi-point constraint, and no element but `owner` uses
  // it. Keeps the domain to repeat the check when the model changes.
  // `context` prefixes the messages ("element BeamContact3D 5").
  void attach(const Element& owner, const Node& node, const Domain& domain, std::string context);

  // At every update: repeats the check after a model change, reads lambda
  // and evaluates should_release = lambda <= -forceTol (C20).
  void update();
  double lambda() const { return lambda_; }
  bool shouldRelease() const { return shouldRelease_; }

  // C20: in contact next step iff the gap is below gapTol, lambda did not
  // fall to -forceTol, and the node is eligible (projects inside the segment,
  // lies within the end face). For a node in contact during the step the gap
  // is the converged gap at the step's held geometry (the one lambda drove
  // to zero); for a released node it is the gap re-evaluated at commit.
  bool nextStatus(bool inContact, double convergedGap, double committedGap, bool eligible) const {
    return nextStatus(inContact, convergedGap, committedGap, eligible, shouldRelease_);
  }
  // The same with the release decided by the caller (a filtered lambda).
  bool nextStatus(bool inContact, double convergedGap, double committedGap, bool eligible, bool release) const {
    const double gap = inContact ? convergedGap : committedGap;
    return gap < gapTolerance_ && !release && eligible;
  }

  // The multiplier node's three rows of an element whose last three dofs
  // are [lambda, -, -]: -g in contact, lambda (unit stiffness) out of
  // contact, and the inert dofs. The element sets the in-contact coupling
  // columns and row (K_q,lambda, K_lambda,q) itself.
  template <int N>
  void setRows(Eigen::Matrix<double, N, 1>& force, Eigen::Matrix<double, N, N>& stiffness, bool inContact,
               double gap) const {
    constexpr int at = N - 3;
    if (inContact) {
      force(at) = -gap;
    } else {
      force(at) = lambda_;
      stiffness(at, at) = 1.0;
    }
    force(at + 1) = inert_[0];
    force(at + 2) = inert_[1];
    stiffness(at + 1, at + 1) = 1.0;
    stiffness(at + 2, at + 2) = 1.0;
  }

 private:
  void check() const;

  double gapTolerance_, forceTolerance_;
  // Not owned: the owner element, its multiplier node and domain.
  const Element* owner_ = nullptr;
  const Node* node_ = nullptr;
  const Domain* domain_ = nullptr;
  std::string context_;
  long checkedStamp_ = -1;
  double lambda_ = 0.0;
  double inert_[2] = {0.0, 0.0};
  bool shouldRelease_ = false;
};

}  // namespace beamsolid
