#pragma once
#include "materials/uniaxial/SoilDrag.h"
#include "materials/uniaxial/SoilNearField.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('QzSimple1', tag, qzType, qult, Z50, suction=0, c=0):
// the q-z (pile tip) spring of Boulanger et al. (1999) as OpenSees
// implements it (docs/pile_springs.md). Compression (bearing) is negative.
// Three components in series, z = ze + zp + zg:
//  - far field: elastic, Kf = Ce qult / z50;
//  - near field (SoilNearField): 1e4 qult / z50 inside the rigid range
//    (initially +-Cr qult; it follows plastic loading and widens to
//    |q| + Cr qult, at most 0.7 qult), plastic beyond it,
//    q = -qult - (-qult - q0) [c z50 / (c z50 + |zp - zp0|)]^n in bearing;
//    (c, n, Cr, Ce) = (0.35, 1.2, 0.2, 0.525) for qzType 1 (Reese & O'Neill
//    1987, drilled shafts in clay) and (12.3, 5.5, 0.3, 1.39) for qzType 2
//    (Vijayvergiya 1977, piles in sand);
//  - gap: a bilinear closure spring (1000 qult / z50 closed, zg < 0, and
//    1.000002e-6 qult / z50 open) in parallel with a drag spring (SoilDrag)
//    of capacity suction * qult that gives the uplift resistance.
// The tangent keeps the near-field tangent above 1e-4 qult / z50; at rest it
// is OpenSees' initial tangent (closure 100 qult / z50). The dashpot and the
// stress bound are those of PySimple1.
class QzSimple1 : public UniaxialMaterial {
 public:
  QzSimple1(int tag, int qzType, double qult, double z50, double suction, double c);

  std::string className() const override { return "QzSimple1"; }
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

  double springForce() const { return trial_.q; }
  double nearFieldDisplacement() const { return nearField_.trial().y; }
  double gapDisplacement() const { return trial_.gap; }
  double farFieldStiffness() const { return farStiffness_; }

 private:
  // The far field's share of a displacement increment, which the dashpot
  // sees (see the class comment).
  double farFieldShare() const;
  struct State {
    double z = 0.0, rate = 0.0, q = 0.0, tangent = 0.0, gap = 0.0;
  };
  std::pair<double, double> gapForce(double gap) const;
  double gapAt(double q, double guess) const;
  double seriesTangent(double nearTangent, double gap) const;

  int qzType_;
  double qult_, z50_, suction_, dashpot_;
  double farStiffness_, closedStiffness_, openStiffness_, initialTangent_;
  SoilNearField nearField_;
  SoilDrag drag_;
  State trial_, committed_;
};

}  // namespace beamsolid
