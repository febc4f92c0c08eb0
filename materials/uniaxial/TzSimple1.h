#pragma once
#include "materials/uniaxial/SoilNearField.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('TzSimple1', tag, tzType, tult, z50, c=0): the t-z
// (shaft friction) spring of Boulanger et al. (1999) as OpenSees implements
// it (docs/pile_springs.md). An elastic far field z^e = t / Kf,
// Kf = Ce tult / z50, in series with a plastic near field without rigid range
//   t = tult - (tult - t0) [c z50 / (c z50 + |zp - zp0|)]^n
// that restarts at every reversal (Masing-like). (c, n, Ce) = (0.5, 1.5,
// 0.70791) for tzType 1 (Reese & O'Neill 1987, drilled shafts) and
// (0.6, 0.85, 2.0504) for tzType 2 (Mosher 1984, piles in sand): with these
// t = tult / 2 at z = z50. The tangent keeps the near-field tangent above
// 1e-4 tult / z50 (as OpenSees reports it); the dashpot c acts on the
// far-field share of the velocity (stress = t + c v tangent / Kf, bounded
// by 0.999999999999 tult).
class TzSimple1 : public UniaxialMaterial {
 public:
  TzSimple1(int tag, int tzType, double tult, double z50, double c);

  std::string className() const override { return "TzSimple1"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.z; }
  double stress() const override;
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return initialTangent_; }
  double dampingTangent() const override { return dashpot_ * farFieldShare(); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  void print(std::ostream& os) const override;

  double springForce() const { return trial_.t; }
  double plasticDisplacement() const { return nearField_.trial().y; }
  double farFieldStiffness() const { return farStiffness_; }

 private:
  // The far field's share of a displacement increment, which the dashpot
  // sees (see the class comment).
  double farFieldShare() const;
  struct State {
    double z = 0.0, rate = 0.0, t = 0.0, tangent = 0.0;
  };
  double seriesTangent(double nearTangent) const;

  int tzType_;
  double tult_, z50_, dashpot_;
  double farStiffness_, initialTangent_;
  SoilNearField nearField_;
  State trial_, committed_;
};

}  // namespace beamsolid
