#include "core/GroundMotion.h"

#include <cmath>
#include <vector>

#include "core/OpenSeesError.h"

namespace beamsolid {

GroundMotion::GroundMotion(int tag, std::shared_ptr<TimeSeries> accel, std::shared_ptr<TimeSeries> vel,
                           std::shared_ptr<TimeSeries> disp, double fact, const std::string& context)
    : tag_(tag), accel_(std::move(accel)), vel_(std::move(vel)), disp_(std::move(disp)), fact_(fact) {
  std::size_t points = 0;
  if (!vel_ && accel_) integratedVel_ = integrate(*accel_, fact_, context, points);
  if (!disp_) {
    if (vel_) integratedDisp_ = integrate(*vel_, fact_, context, points);
    else if (integratedVel_) integratedDisp_ = integrate(*integratedVel_, 1.0, context, points);
  }
}

std::unique_ptr<PathSeries> GroundMotion::integrate(const TimeSeries& f, double fact, const std::string& context,
                                                    std::size_t& points) {
  const auto end = f.lastTime();
  if (!end || !(*end > 0.0))
    throw OpenSeesError(context + ": cannot integrate time series " + std::to_string(f.tag()) + " (" +
                        f.className() + "): it has no finite duration; give the velocity/displacement series too");
  const double h = kIntegrationStep;
  // Up to the series' end, and for a '-dt' path one step past its last
  // sample (where it is 0), as OpenSees: there the velocity at the record's
  // last sample takes that sample, and the velocity and displacement reach
  // the extra step (checked with OpenSeesPy 3.7.1 on a 1000-point record; a
  // '-time' path ends at its last time). The displacement keeps the
  // velocity's grid.
  const auto* path = dynamic_cast<const PathSeries*>(&f);
  const std::size_t extra = path && path->isUniform() ? 2 : 1;
  if (points == 0) points = static_cast<std::size_t>(std::floor(*end / h + 0.5)) + extra;
  const std::size_t n = points;
  // A '-dt' path is 0 at its last time itself; the integral takes the sample there.
  const double lastSample = std::nextafter(*end, 0.0);
  auto sample = [&](double t) { return fact * f.factor(std::fabs(t - *end) <= 1e-9 * h ? lastSample : t); };
  std::vector<double> values(n, 0.0);
  double previous = sample(0.0);
  for (std::size_t k = 1; k < n; ++k) {
    const double current = sample(static_cast<double>(k) * h);
    values[k] = values[k - 1] + 0.5 * h * (previous + current);
    previous = current;
  }
  std::vector<double> times(n);
  for (std::size_t k = 0; k < n; ++k) times[k] = static_cast<double>(k) * h;
  return std::make_unique<PathSeries>(-1, std::move(times), std::move(values), 1.0, false, context, true);
}

double GroundMotion::accel(double time) const { return accel_ ? fact_ * accel_->factor(time) : 0.0; }

double GroundMotion::vel(double time) const {
  if (vel_) return fact_ * vel_->factor(time);
  return integratedVel_ ? integratedVel_->factor(time) : 0.0;
}

double GroundMotion::disp(double time) const {
  if (disp_) return fact_ * disp_->factor(time);
  return integratedDisp_ ? integratedDisp_->factor(time) : 0.0;
}

}  // namespace beamsolid
