#include "core/RectangularSeries.h"

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

void RectangularSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Rectangular from t = " << tStart_ << " to t = " << tEnd_ << " factor "
     << cFactor_ << '\n';
}

namespace {

// timeSeries('Rectangular', tag, tStart, tEnd, <'-factor', f>)
std::unique_ptr<TimeSeries> buildRectangularSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  args.setContext("timeSeries Rectangular " + std::to_string(tag));
  const double tStart = args.nextDouble("tStart");
  const double tEnd = args.nextDouble("tEnd");
  double cFactor = 1.0;
  while (!args.done()) {
    if (args.nextFlag("-factor")) cFactor = args.nextDouble("factor");
    else args.failAt(args.position(), "option", "'-factor'");
  }
  return std::make_unique<RectangularSeries>(tag, tStart, tEnd, cFactor);
}

void registerRectangularSeries(Registry& r) { r.timeSeries.add("Rectangular", &buildRectangularSeries); }

}  // namespace
BEAMSOLID_REGISTER(registerRectangularSeries);

}  // namespace beamsolid
