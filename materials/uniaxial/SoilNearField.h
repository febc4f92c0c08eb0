#pragma once

namespace beamsolid {

// The near-field (plastic) component of the PySimple1 / TzSimple1 /
// QzSimple1 springs (Boulanger et al. 1999): a stiff elastic spring inside
// a rigid range lower <= p <= upper, and beyond it plastic loading
//   p = d ult - (d ult - p0) [c y50 / (c y50 + |y - y0|)]^n      (d = +-1)
// from (p0, y0), where the current plastic excursion began. The excursion
// goes on across steps while loading continues in direction d; unloading
// into the rigid range ends it. After plastic loading to p the rigid range
// moves with p (kinematic hardening) by one of three rules:
//   PySimple1: [min(p - 2 Cr ult, -0.25 ult), p] (and mirrored), so at
//              least 0.25 ult of range stays on the other side of zero;
//   QzSimple1: the range keeps its largest width w so far, w grows to
//              |p| + Cr ult and at most 0.7 ult: [p - w, p] (mirrored);
//   TzSimple1: no range (rigid range of zero width): every reversal starts
//              a new plastic excursion at once.
// Displacements are functions of the force p from the committed state, so
// a series of components can be solved for their common force.
class SoilNearField {
 public:
  enum class Range { PySimple1, QzSimple1, TzSimple1 };

  struct State {
    double p = 0.0, y = 0.0;
    double lower = 0.0, upper = 0.0, width = 0.0;
    double p0 = 0.0, y0 = 0.0;  // start of the current plastic excursion
    int direction = 0;          // +1 / -1 during plastic loading that may go on, 0 never yielded
  };

  // The state of a trial force p from the committed state: displacement,
  // excursion start and, when p is plastic, the new direction.
  struct Trial {
    double y;
    bool plastic;
    int direction;
    double p0, y0;
  };

  SoilNearField() = default;
  SoilNearField(double ult, double cY50, double n, double Cr, double elasticStiffness, Range range);

  void revertToStart();
  const State& committed() const { return committed_; }
  const State& trial() const { return trial_; }

  Trial at(double p) const;
  // d y / d p at a trial force (1 / the plastic tangent, or 1 / elastic stiffness).
  double flexibility(double p, const Trial& t) const;
  // Sets the trial state to force p.
  void setTrial(double p);
  void setTrialToCommitted() { trial_ = committed_; }
  // The tangent of the trial state (the plastic tangent while in plastic
  // flow, the elastic stiffness inside the rigid range).
  double tangent() const;
  void commit() { committed_ = trial_; }
  void revert() { trial_ = committed_; }

 private:
  double plasticTangent(double p, double y, double y0, int d) const;

  double ult_ = 1.0, cY50_ = 1.0, n_ = 1.0, Cr_ = 0.0, elasticFlexibility_ = 0.0;
  Range range_ = Range::PySimple1;
  State committed_, trial_;
};

}  // namespace beamsolid
