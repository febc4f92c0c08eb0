#pragma once
#include "core/TimeSeries.h"

namespace beamsolid {

// factor(t) = cFactor for every t.
class ConstantSeries : public TimeSeries {
 public:
  ConstantSeries(int tag, double cFactor = 1.0) : TimeSeries(tag), cFactor_(cFactor) {}
  std::string className() const override { return "Constant"; }
  double factor(double) const override { return cFactor_; }
  double slope(double) const override { return 0.0; }
  void print(std::ostream& os) const override;

 private:
  double cFactor_;
};

}  // namespace beamsolid
