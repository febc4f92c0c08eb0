#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// factor(t) = cFactor * (t - tStart) for t >= tStart, 0 before.
class LinearSeries : public TimeSeries {
 public:
  LinearSeries(int tag, double cFactor = 1.0, double tStart = 0.0)
      : TimeSeries(tag), cFactor_(cFactor), tStart_(tStart) {}
  std::string className() const override { return "Linear"; }
  double factor(double time) const override { return time < tStart_ ? 0.0 : cFactor_ * (time - tStart_); }
  double slope(double time) const override { return time < tStart_ ? 0.0 : cFactor_; }
  void print(std::ostream& os) const override;

 private:
  double cFactor_;
  double tStart_;
};

}  // namespace beamsolid
