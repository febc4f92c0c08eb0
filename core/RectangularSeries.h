#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// factor(t) = cFactor for tStart <= t <= tEnd, 0 outside.
class RectangularSeries : public TimeSeries {
 public:
  RectangularSeries(int tag, double tStart, double tEnd, double cFactor)
      : TimeSeries(tag), tStart_(tStart), tEnd_(tEnd), cFactor_(cFactor) {}
  std::string className() const override { return "Rectangular"; }
  double factor(double time) const override { return time < tStart_ || time > tEnd_ ? 0.0 : cFactor_; }
  double slope(double) const override { return 0.0; }
  std::optional<double> lastTime() const override { return tEnd_; }
  void print(std::ostream& os) const override;

 private:
  double tStart_, tEnd_, cFactor_;
};

}  // namespace beamsolid
