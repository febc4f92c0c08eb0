#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Types.h"

namespace beamsolid {

class CrdTransf;
class Domain;
class Node;

// The pile behind chained beam contact elements ('-pile' option of
// BeamContact3D / BeamContact3Dp): its ordered beam nodes, the reference
// section frames of its segments and the committed nodal frames of all its
// nodes. One object per (pile, geomTransf), shared by every contact element
// of that pile through Domain::sharedObject(), so that an element handing its
// soil node over to the next segment finds that segment's nodal frames
// exactly as the elements already on it track them.
//
// Nodal frames (C1): segment s sees pile node k (k = s or s + 1) with the
// frame P_k Q0_s, where Q0_s holds the local axes of the geomTransf on
// segment s (columns x, y, z) and P_k is the node's accumulated rotation,
// advanced by exp(skew(theta_k - theta_k,ref)) whenever the node's rotation
// theta_k differs from the one of the last advance. Every element of the pile
// calls synchronize() at its commit; the first call of a commit advances the
// frames, the others find nothing to do, so the frames advance exactly once
// per converged step, in every element's view alike. For a single segment this
// is the same sequence of exponential maps the unchained element applies to
// its own frames, so chained and unchained elements agree to round-off.
class BeamContactPile {
 public:
  // Checks the node list (at least two distinct existing nodes of ndf 6) and
  // computes Q0 of every segment from a copy of `transf`. Errors name
  // `context` (the element being built).
  BeamContactPile(const Domain& domain, std::vector<int> nodeTags, const CrdTransf& transf,
                  const std::string& context);

  // Key under which the elements of one pile share this object.
  static std::string key(int transfTag, const std::vector<int>& nodeTags);

  const std::vector<int>& nodeTags() const { return tags_; }
  int numNodes() const { return static_cast<int>(tags_.size()); }
  int numSegments() const { return numNodes() - 1; }
  // Index s of the segment from node iNode to node jNode (consecutive in
  // this order), or -1.
  int segmentOf(int iNode, int jNode) const;
  // Reference length |X_{s+1} - X_s| of segment s.
  double segmentLength(int segment) const { return lengths_[segment]; }
  const Node& node(int k) const;

  // Advances every nodal frame to its node's current rotation (C1);
  // idempotent between changes of the nodes' rotations.
  void synchronize();
  // Frame of pile node k (columns: axis, section axes) as segment `segment`
  // sees it, at the rotations of the last synchronize().
  Matrix3 frame(int k, int segment) const { return rotations_[k] * referenceAxes_[segment]; }
  // Back to the reference frames (all rotations zero); idempotent.
  void revertToStart();

 private:
  void resolveNodes() const;

  const Domain& domain_;
  std::string context_;
  std::vector<int> tags_;
  std::vector<double> lengths_;
  std::vector<Matrix3> referenceAxes_;  // Q0 per segment
  std::vector<Matrix3> rotations_;      // P_k per node
  std::vector<Vector3> thetas_;         // rotation of node k at the last advance
  // Node pointers, re-resolved when the model changes.
  mutable std::vector<const Node*> nodes_;
  mutable long resolvedStamp_ = -1;
};

}  // namespace beamsolid
