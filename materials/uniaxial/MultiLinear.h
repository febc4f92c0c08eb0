#pragma once
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('MultiLinear', tag, e1, s1, e2, s2, ...): a symmetric
// multilinear backbone through (e_i, s_i), strains increasing, the last slope
// continued beyond the last point, with Masing unloading and reloading.
// It is built as an Iwan (parallel-series) model: one elastic-perfectly
// plastic spring per corner, of stiffness slope_i - slope_(i+1) and yield
// strain e_i, in parallel with an elastic spring of the last slope. On a
// reversal every segment is therefore twice as long as on the backbone, and
// inner loops remember the springs they did not reach, as OpenSees'
// MultiLinear does (checked point by point against OpenSeesPy).
class MultiLinear : public UniaxialMaterial {
 public:
  MultiLinear(int tag, const std::vector<double>& strains, const std::vector<double>& stresses);

  std::string className() const override { return "MultiLinear"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override { return trialStress_; }
  double tangent() const override { return trialTangent_; }
  double initialTangent() const override { return initialTangent_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  std::vector<double> strains_, stresses_;
  std::vector<double> stiffness_;  // of the yielding springs, one per corner
  double elasticStiffness_ = 0.0;  // the last slope, never yields
  double initialTangent_ = 0.0;
  std::vector<double> trialSlip_, committedSlip_;  // plastic strain of each yielding spring
  double trialStrain_ = 0.0, trialStress_ = 0.0, trialTangent_ = 0.0;
  // Stored, not recomputed: on a corner the committed slips alone cannot
  // tell a yielding spring (tangent without it) from an elastic one.
  double committedStrain_ = 0.0, committedStress_ = 0.0, committedTangent_ = 0.0;
};

}  // namespace beamsolid
