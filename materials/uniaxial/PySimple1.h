#pragma once
#include "materials/uniaxial/SoilDrag.h"
#include "materials/uniaxial/SoilNearField.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// uniaxialMaterial('PySimple1', tag, soilType, pult, Y50, Cd, c=0): the p-y
// spring of Boulanger, Curras, Kutter, Wilson & Abghari (1999), J. Geotech.
// Geoenviron. Eng. 125(9), 750-759, as OpenSees implements it (docs/pile_springs.md).
// Three components in series carry the same force p, y = ye + yp + yg:
//  - far field: elastic, ye = p / Kf, Kf = Ce pult / y50 with Ce = 1/0.98
//    (soilType 1, Matlock soft clay) or 0.542 (soilType 2, API sand);
//  - near field (SoilNearField): stiff elastic (50 pult / y50) inside the
//    rigid range, initially +-Cr pult, then plastic
//    p = pult - (pult - p0) [c y50 / (c y50 + |yp - yp0|)]^n with
//    (c, n, Cr) = (10, 5, 0.35) for clay and (0.5, 2, 0.2) for sand;
//  - gap: a closure spring in parallel with a drag spring (SoilDrag, Cd pult):
//      pc = 1.8 pult [y50 / (y50 + 50 (y0+ - yg)) - y50 / (y50 - 50 (y0- - yg))]
//    with memory terms y0+ = max(y50/100, -(min past (yp + yg) + 1.5 y50)) and
//    y0- = min(-y50/100, -(max past (yp + yg) - 1.5 y50)): the gap behind
//    the pile that plastic deformation on one side leaves on the other.
//    Beyond y0+ (or below y0-) the gap force continues linearly with the
//    stiffness it has there, which keeps the closure finite.
// Each trial solves the series for p exactly (nested safeguarded Newton).
// The tangent is the series tangent with the near-field, closure and drag
// tangents each kept above 0.01 pult / y50 (as OpenSees reports it). A dashpot c acts on the
// far-field share of the velocity: stress = p + c v t / Kf, t the tangent,
// and the stress is bounded by 0.999999999999 pult in magnitude; the damping
// tangent is c t / Kf.
class PySimple1 : public UniaxialMaterial {
 public:
  PySimple1(int tag, int soilType, double pult, double y50, double Cd, double c);

  std::string className() const override { return "PySimple1"; }
  std::unique_ptr<UniaxialMaterial> clone() const override;

  void setTrialStrain(double strain, double strainRate = 0.0) override;
  double strain() const override { return trial_.y; }
  double stress() const override;
  double tangent() const override { return trial_.tangent; }
  double initialTangent() const override { return initialTangent_; }
  double dampingTangent() const override { return dashpot_ * farFieldShare(); }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  void print(std::ostream& os) const override;

  // The force in the springs (without the dashpot) and the components'
  // displacements, for tests and recorders.
  double springForce() const { return trial_.p; }
  double farFieldDisplacement() const { return trial_.p / farStiffness_; }
  double nearFieldDisplacement() const { return nearField_.trial().y; }
  double gapDisplacement() const { return trial_.gap; }
  double gapRight() const { return trial_.closeRight; }
  double gapLeft() const { return trial_.closeLeft; }
  double farFieldStiffness() const { return farStiffness_; }

 private:
  // The far field's share of a displacement increment, which the dashpot
  // sees (see the class comment).
  double farFieldShare() const;
  struct State {
    double y = 0.0, rate = 0.0, p = 0.0, tangent = 0.0;
    double gap = 0.0, closeRight = 0.0, closeLeft = 0.0;  // yg, y0+, y0-
  };
  struct GapForce {
    double force, slope, closureTangent, dragTangent, clipped, closeRight, closeLeft;
    SoilDrag::Cycle cycle;
  };
  GapForce gapForce(double gap, double nearDisplacement) const;
  double closure(double b, double right, double left) const;
  double closureTangent(double b, double right, double left) const;
  double gapAt(double p, double nearDisplacement, double guess) const;
  double seriesTangent(double nearTangent, const GapForce& gap) const;

  int soilType_;
  double pult_, y50_, Cd_, dashpot_;
  double farStiffness_, initialTangent_;
  SoilNearField nearField_;
  SoilDrag drag_;
  State trial_, committed_;
};

}  // namespace beamsolid
