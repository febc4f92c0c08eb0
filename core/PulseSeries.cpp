#include "core/PulseSeries.h"

#include <cmath>

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

double PulseSeries::factor(double time) const {
  if (time < tStart_ || time > tEnd_) return 0.0;
  const double cycles = (time - tStart_ + shift_) / period_;
  const double phase = cycles - std::floor(cycles);
  return (phase < width_ ? cFactor_ : 0.0) + zeroShift_;
}

void PulseSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Pulse from t = " << tStart_ << " to t = " << tEnd_ << " period " << period_
     << " width " << width_ << " shift " << shift_ << " factor " << cFactor_ << " zeroShift " << zeroShift_ << '\n';
}

namespace {

// timeSeries('Pulse', tag, tStart, tEnd, period, <'-width', w>, <'-shift', s>, <'-factor', f>, <'-zeroShift', z>)
std::unique_ptr<TimeSeries> buildPulseSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  args.setContext("timeSeries Pulse " + std::to_string(tag));
  const double tStart = args.nextDouble("tStart");
  const double tEnd = args.nextDouble("tEnd");
  const double period = args.nextDouble("period");
  if (!(period > 0.0)) args.fail("period must be positive, got " + std::to_string(period));
  double width = 0.5, shift = 0.0, cFactor = 1.0, zeroShift = 0.0;
  while (!args.done()) {
    if (args.nextFlag("-width")) width = args.nextDouble("width");
    else if (args.nextFlag("-shift")) shift = args.nextDouble("shift");
    else if (args.nextFlag("-factor")) cFactor = args.nextDouble("factor");
    else if (args.nextFlag("-zeroShift")) zeroShift = args.nextDouble("zeroShift");
    else args.failAt(args.position(), "option", "one of '-width', '-shift', '-factor', '-zeroShift'");
  }
  if (!(width > 0.0 && width < 1.0)) args.fail("width must lie in (0, 1) (a fraction of the period), got " + std::to_string(width));
  return std::make_unique<PulseSeries>(tag, tStart, tEnd, period, width, shift, cFactor, zeroShift);
}

void registerPulseSeries(Registry& r) { r.timeSeries.add("Pulse", &buildPulseSeries); }

}  // namespace
BEAMSOLID_REGISTER(registerPulseSeries);

}  // namespace beamsolid
