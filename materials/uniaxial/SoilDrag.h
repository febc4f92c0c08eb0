#pragma once

namespace beamsolid {

// The drag spring of the PySimple1 / QzSimple1 gap (Boulanger et al. 1999):
// a nonlinear spring that approaches +-Cd ult in each direction,
//   p = d Cd ult - (d Cd ult - p0) y50 / (y50 + 2 |y - y0|)      (d = +-1)
// from (y0, p0), where the current loading cycle began. A cycle goes on
// across steps while y keeps moving in direction d; a reversal against the
// committed state starts a new one there. (OpenSees' manual writes an
// exponent n on the bracket; the measured response has none: the initial
// stiffness is 2 Cd ult / y50 for both soil types.)
class SoilDrag {
 public:
  struct State {
    double y = 0.0, p = 0.0;
    double y0 = 0.0, p0 = 0.0;  // start of the current cycle
    int direction = 0;          // 0 before any movement
  };
  struct Cycle {
    int direction;
    double y0, p0;
  };

  SoilDrag() = default;
  SoilDrag(double dragUlt, double y50) : dragUlt_(dragUlt), y50_(y50) {}

  void revertToStart() { committed_ = trial_ = State{}; }
  const State& committed() const { return committed_; }
  const State& trial() const { return trial_; }

  // The loading cycle a trial displacement y belongs to.
  Cycle cycle(double y) const;
  double force(double y, const Cycle& c) const;
  double tangent(double y, const Cycle& c) const;
  void setTrial(double y);
  void setTrialToCommitted() { trial_ = committed_; }
  void commit() { committed_ = trial_; }
  void revert() { trial_ = committed_; }

 private:
  double dragUlt_ = 0.0, y50_ = 1.0;
  State committed_, trial_;
};

}  // namespace beamsolid
