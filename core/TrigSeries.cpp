#include "core/TrigSeries.h"

#include <cmath>
#include <numbers>

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

TrigSeries::TrigSeries(int tag, double tStart, double tEnd, double period, double cFactor, double shift,
                       double zeroShift)
    : TimeSeries(tag), tStart_(tStart), tEnd_(tEnd), period_(period), cFactor_(cFactor), zeroShift_(zeroShift) {
  const double zeroPhase = zeroShift == 0.0 ? 0.0 : std::asin(zeroShift / cFactor);
  phase_ = shift - period * zeroPhase / (2.0 * std::numbers::pi);
}

double TrigSeries::factor(double time) const {
  if (time < tStart_ || time > tEnd_) return 0.0;
  const double omega = 2.0 * std::numbers::pi / period_;
  return cFactor_ * std::sin(omega * (time - tStart_) + phase_) + zeroShift_;
}

double TrigSeries::slope(double time) const {
  if (time < tStart_ || time > tEnd_) return 0.0;
  const double omega = 2.0 * std::numbers::pi / period_;
  return cFactor_ * omega * std::cos(omega * (time - tStart_) + phase_);
}

void TrigSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Trig from t = " << tStart_ << " to t = " << tEnd_ << " period " << period_
     << " factor " << cFactor_ << " phase " << phase_ << " zeroShift " << zeroShift_ << '\n';
}

namespace {

// timeSeries('Trig' | 'Sine', tag, tStart, tEnd, period, <'-factor', f>, <'-shift', phase>, <'-zeroShift', z>)
std::unique_ptr<TimeSeries> buildTrigSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  args.setContext("timeSeries Trig " + std::to_string(tag));
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
  if (zeroShift != 0.0 && !(std::fabs(zeroShift) <= std::fabs(cFactor)))
    args.fail("|zeroShift| must not exceed |factor| (the phase uses asin(zeroShift / factor))");
  return std::make_unique<TrigSeries>(tag, tStart, tEnd, period, cFactor, shift, zeroShift);
}

void registerTrigSeries(Registry& r) {
  r.timeSeries.add("Trig", &buildTrigSeries);
  r.timeSeries.add("Sine", &buildTrigSeries);
}

}  // namespace
BEAMSOLID_REGISTER(registerTrigSeries);

}  // namespace beamsolid
