#pragma once
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('ElasticPPGap', tag, E, Fy, gap, <eta=0>, <'damage'>):
// an elastic-plastic gap. With Fy > 0 it carries tension once the strain
// passes the contact strain (initially `gap`); with Fy < 0 it is the mirror
// image in compression. Past the elastic range the stress follows a fixed line
// in strain, Fy + eta*E*(strain - gap - Fy/E) (eta < 0 softens): the stress is
// the lower of that line and the elastic line from the contact strain. Unloading
// is elastic; a plastic excursion moves the contact strain to where the stress
// would reach zero, so the gap grows.
// Re-centering (OpenSees' default 'noDamage'), found by running OpenSees: a
// committed strain strictly between the initial gap and the current contact
// strain moves the contact strain back to it (the plastic line stays). This
// depends on the path: one step from the yielded state straight past the
// initial gap leaves the grown gap as it is, while walking back through the
// open range closes it to the last committed point inside that range. With
// 'damage' the gap never closes.
class ElasticPPGap : public UniaxialMaterial {
 public:
  ElasticPPGap(int tag, double E, double Fy, double gap, double eta, bool damage);

  std::string className() const override { return "ElasticPPGap"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trialStrain_; }
  double stress() const override { return sign_ * trialStress_; }
  double tangent() const override { return trialTangent_; }
  double initialTangent() const override { return E_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  void print(std::ostream& os) const override;

 private:
  // The gap is worked in its own frame: strains and stresses times sign_
  // (+1 tension gap, -1 compression gap), so that the gap opens below it.
  double E_, Fy_, gap_, eta_;
  bool damage_;
  double sign_;
  double trialStrain_ = 0.0, trialStress_ = 0.0, trialTangent_ = 0.0;  // stress in the gap's frame
  double committedStrain_ = 0.0;
  double contactStrain_;  // the stress is zero below it (gap's frame)
  // Past it the stress is on the plastic line: where the elastic line from the
  // contact strain meets it (gap's frame).
  double plasticStrain_;
};

}  // namespace beamsolid
