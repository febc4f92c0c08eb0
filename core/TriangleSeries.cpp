#include "core/TriangleSeries.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

double TriangleSeries::phase(double time) const {
  const double offset = zeroShift_ == 0.0 ? 0.0 : zeroShift_ / (4.0 * cFactor_);
  const double cycles = (time - tStart_ + shift_) / period_ - offset;
  return cycles - std::floor(cycles);
}

double TriangleSeries::factor(double time) const {
  if (time < tStart_ || time > tEnd_) return 0.0;
  const double p = phase(time);
  const double unit = p < 0.25 ? 4.0 * p : (p < 0.75 ? 2.0 - 4.0 * p : 4.0 * p - 4.0);
  return cFactor_ * unit + zeroShift_;
}

double TriangleSeries::slope(double time) const {
  if (time < tStart_ || time > tEnd_) return 0.0;
  const double p = phase(time);
  const double rate = 4.0 * cFactor_ / period_;
  return p < 0.25 || p >= 0.75 ? rate : -rate;
}

void TriangleSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Triangle from t = " << tStart_ << " to t = " << tEnd_ << " period "
     << period_ << " factor " << cFactor_ << " shift " << shift_ << " zeroShift " << zeroShift_ << '\n';
}

namespace {

// timeSeries('Triangle', tag, tStart, tEnd, period, <'-factor', f>, <'-shift', s>, <'-zeroShift', z>)
std::unique_ptr<TimeSeries> buildTriangleSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  args.setContext("timeSeries Triangle " + std::to_string(tag));
  const double tStart = args.nextDouble("tStart");
  const double tEnd = args.nextDouble("tEnd");
  const double period = args.nextDouble("period");
  if (!(period > 0.0)) args.fail("period must be positive, got " + std::to_string(period));
  double cFactor = 1.0, shift = 0.0, zeroShift = 0.0;
  while (!args.done()) {
    if (args.nextFlag("-factor")) cFactor = args.nextDouble("factor");
    else if (args.nextFlag("-shift")) shift = args.nextDouble("shift");
    else if (args.nextFlag("-zeroShift")) zeroShift = args.nextDouble("zeroShift");
    else args.failAt(args.position(), "option", "one of '-factor', '-shift', '-zeroShift'");
  }
  if (zeroShift != 0.0 && cFactor == 0.0) args.fail("a zero shift needs a nonzero factor");
  return std::make_unique<TriangleSeries>(tag, tStart, tEnd, period, cFactor, shift, zeroShift);
}

void registerTriangleSeries(Registry& r) { r.timeSeries.add("Triangle", &buildTriangleSeries); }

}  // namespace
BEAMSOLID_REGISTER(registerTriangleSeries);

}  // namespace beamsolid
