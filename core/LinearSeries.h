#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// factor(t) = cFactor * t. With a start time (-tStart): cFactor * (t - tStart)
// for t >= tStart and 0 before. Without one the line continues to negative
// times, since an arc-length analysis can drive the load factor below zero.
class LinearSeries : public TimeSeries {
 public:
  explicit LinearSeries(int tag, double cFactor = 1.0) : TimeSeries(tag), cFactor_(cFactor) {}
  LinearSeries(int tag, double cFactor, double tStart)
      : TimeSeries(tag), cFactor_(cFactor), tStart_(tStart), hasStart_(true) {}
  std::string className() const override { return "Linear"; }
  double factor(double time) const override {
    return hasStart_ && time < tStart_ ? 0.0 : cFactor_ * (time - tStart_);
  }
  double slope(double time) const override { return hasStart_ && time < tStart_ ? 0.0 : cFactor_; }
  void print(std::ostream& os) const override;

 private:
  double cFactor_;
  double tStart_ = 0.0;
  bool hasStart_ = false;
};

}  // namespace beamsolid
