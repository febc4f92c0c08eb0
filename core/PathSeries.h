#pragma once
#include <string>
#include <vector>

#include "core/TimeSeries.h"

namespace beamsolid {

// Piecewise linear load factor through user points (t_i, v_i), times cFactor.
// Before the first point the factor is 0. The end follows OpenSees (checked
// with OpenSeesPy): a uniform path (-dt) ends just before its last point,
// which, like every later time, gives 0, or the last value with useLast; a
// path with explicit times includes its last point (and times within
// round-off past it) and gives 0 after it, useLast or not. slope() is the slope of the segment holding t (the
// segment to the right at an interior point) and 0 outside the path.
class PathSeries : public TimeSeries {
 public:
  // Throws OpenSeesError prefixed by `context` unless the times strictly
  // increase and match the values in number (at least one point).
  PathSeries(int tag, std::vector<double> times, std::vector<double> values, double cFactor, bool useLast,
             const std::string& context, bool uniform = false);

  std::string className() const override { return "Path"; }
  double factor(double time) const override;
  double slope(double time) const override;
  std::optional<double> lastTime() const override { return times_.back(); }
  void print(std::ostream& os) const override;

  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& values() const { return values_; }
  double startTime() const { return times_.front(); }
  double endTime() const { return times_.back(); }
  // Whether the times are uniform (-dt): the path then ends just before its last point.
  bool isUniform() const { return uniform_; }

  // Whitespace- (or comma-) separated numbers of a file; errors name the
  // file and the offending token.
  static std::vector<double> readNumbers(const std::string& path, const std::string& context);

 private:
  // Index i of the segment [t_i, t_i+1] holding time t, or -1 before the
  // path and -2 past its end.
  long segment(double time) const;

  std::vector<double> times_;
  std::vector<double> values_;
  double cFactor_;
  bool useLast_;
  bool uniform_;
  // Explicit times: times within this distance of the ends count as on the
  // path, so that a time reached by summing increments in floating point
  // still hits the last point (OpenSees gives 0 just past it).
  double tolerance_ = 0.0;
};

}  // namespace beamsolid
