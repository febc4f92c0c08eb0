#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// Triangular wave of unit amplitude between tStart and tEnd (both included),
// 0 outside. With p = frac((t - tStart + shift) / period - zeroShift / (4 cFactor)):
//   tri(p) = 4p (p < 1/4), 2 - 4p (p < 3/4), 4p - 4 (else);
//   factor(t) = cFactor * tri(p) + zeroShift,
// so that with a zero shift the wave still starts from 0 at tStart (as OpenSees does).
class TriangleSeries : public TimeSeries {
 public:
  TriangleSeries(int tag, double tStart, double tEnd, double period, double cFactor, double shift, double zeroShift)
      : TimeSeries(tag), tStart_(tStart), tEnd_(tEnd), period_(period), cFactor_(cFactor), shift_(shift),
        zeroShift_(zeroShift) {}
  std::string className() const override { return "Triangle"; }
  double factor(double time) const override;
  double slope(double time) const override;
  std::optional<double> lastTime() const override { return tEnd_; }
  void print(std::ostream& os) const override;

 private:
  // Phase in [0, 1) of time t.
  double phase(double time) const;

  double tStart_, tEnd_, period_, cFactor_, shift_, zeroShift_;
};

}  // namespace beamsolid
