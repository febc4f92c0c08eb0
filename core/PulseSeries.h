#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// Rectangular pulse train between tStart and tEnd (both included), 0 outside.
// With the phase p = frac((t - tStart + shift) / period):
//   factor(t) = cFactor + zeroShift  for p < width,  zeroShift otherwise.
class PulseSeries : public TimeSeries {
 public:
  PulseSeries(int tag, double tStart, double tEnd, double period, double width, double shift, double cFactor,
              double zeroShift)
      : TimeSeries(tag), tStart_(tStart), tEnd_(tEnd), period_(period), width_(width), shift_(shift),
        cFactor_(cFactor), zeroShift_(zeroShift) {}
  std::string className() const override { return "Pulse"; }
  double factor(double time) const override;
  double slope(double) const override { return 0.0; }
  std::optional<double> lastTime() const override { return tEnd_; }
  void print(std::ostream& os) const override;

 private:
  double tStart_, tEnd_, period_, width_, shift_, cFactor_, zeroShift_;
};

}  // namespace beamsolid
