#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// Sine wave between tStart and tEnd (both included), 0 outside:
//   factor(t) = cFactor * sin(2 pi (t - tStart) / period + phi) + zeroShift,
//   phi = shift - period * asin(zeroShift / cFactor) / (2 pi).
// The zero-shift correction to the phase is what OpenSees applies (measured
// with OpenSeesPy: it is a time offset used as a phase), kept so that scripts
// with '-zeroShift' give OpenSees' numbers.
class TrigSeries : public TimeSeries {
 public:
  TrigSeries(int tag, double tStart, double tEnd, double period, double cFactor, double shift, double zeroShift);
  std::string className() const override { return "Trig"; }
  double factor(double time) const override;
  double slope(double time) const override;
  std::optional<double> lastTime() const override { return tEnd_; }
  void print(std::ostream& os) const override;

 private:
  double tStart_, tEnd_, period_, cFactor_, zeroShift_;
  double phase_;
};

}  // namespace beamsolid
