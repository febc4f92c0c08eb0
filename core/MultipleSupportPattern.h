#pragma once
#include <map>
#include <memory>

#include "core/GroundMotion.h"
#include "core/LoadPattern.h"

namespace beamsolid {

// pattern('MultipleSupport'): supports move with their own ground motions
// (groundMotion), imposed on node dofs by imposedMotion. Each imposed dof
// takes the ground displacement as an imposed value and, as in OpenSees, the
// node's velocity and acceleration at that dof are the ground's.
// Responses are absolute.
class MultipleSupportPattern : public LoadPattern {
 public:
  explicit MultipleSupportPattern(int tag);

  std::string typeName() const override { return "MultipleSupport"; }
  void addGroundMotion(std::unique_ptr<GroundMotion> motion, const std::string& context);
  const GroundMotion& groundMotion(int tag, const std::string& context) const;
  // imposedMotion(node, dof, gmTag); dof 0-based.
  void addImposedMotion(int nodeTag, int dof, int gmTag, const std::string& context);

  double imposedValue(const SPConstraint& sp, double time) const override;
  void applyLoad(Domain& domain, double time) const override;

 private:
  std::map<int, std::unique_ptr<GroundMotion>> motions_;
  // Ground motion of each imposed dof, keyed by (node, dof).
  std::map<std::pair<int, int>, int> motionOf_;
};

}  // namespace beamsolid
