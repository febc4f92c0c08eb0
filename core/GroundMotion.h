#pragma once
#include <memory>
#include <string>

#include "core/PathSeries.h"
#include "core/TimeSeries.h"

namespace beamsolid {

// groundMotion('Plain'): ground acceleration, velocity and displacement in
// time, each fact times its series. A missing velocity (displacement) is the
// trapezoidal integral of the acceleration (velocity) from t = 0, sampled
// every kIntegrationStep up to the series' last time (a '-dt' path: one
// step past it), as OpenSees does (its default step 0.01, checked with
// OpenSeesPy); the integral is a uniform path, so it is 0 from its end on. A missing acceleration
// is 0: like OpenSees, nothing is differentiated.
class GroundMotion {
 public:
  static constexpr double kIntegrationStep = 0.01;

  // Throws OpenSeesError prefixed by `context` when a series that must be
  // integrated has no last time (Constant, Linear).
  GroundMotion(int tag, std::shared_ptr<TimeSeries> accel, std::shared_ptr<TimeSeries> vel,
               std::shared_ptr<TimeSeries> disp, double fact, const std::string& context);

  int tag() const { return tag_; }
  double accel(double time) const;
  double vel(double time) const;
  double disp(double time) const;

 private:
  // Trapezoidal running integral of f (times fact) on 0, h, 2h, ... up to its last time (a '-dt' path: one step past).
  // `points` (0: from f's last time) is the grid size, set on return.
  static std::unique_ptr<PathSeries> integrate(const TimeSeries& f, double fact, const std::string& context,
                                               std::size_t& points);

  int tag_;
  std::shared_ptr<TimeSeries> accel_, vel_, disp_;
  double fact_;
  std::unique_ptr<PathSeries> integratedVel_, integratedDisp_;
};

}  // namespace beamsolid
