#include "core/LinearSeries.h"

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

void LinearSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Linear factor " << cFactor_;
  if (hasStart_) os << " tStart " << tStart_;
  os << '\n';
}

namespace {

// timeSeries('Linear', tag, <'-factor', f>, <'-tStart', t0>)
std::unique_ptr<TimeSeries> buildLinearSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  args.setContext("timeSeries Linear " + std::to_string(tag));
  double cFactor = 1.0;
  double tStart = 0.0;
  bool hasStart = false;
  while (!args.done()) {
    if (args.nextFlag("-factor")) {
      cFactor = args.nextDouble("factor");
    } else if (args.nextFlag("-tStart") || args.nextFlag("-startTime")) {
      tStart = args.nextDouble("tStart");
      hasStart = true;
    } else {
      args.failAt(args.position(), "option", "'-factor' or '-tStart'");
    }
  }
  if (hasStart) return std::make_unique<LinearSeries>(tag, cFactor, tStart);
  return std::make_unique<LinearSeries>(tag, cFactor);
}

void registerLinearSeries(Registry& r) { r.timeSeries.add("Linear", &buildLinearSeries); }

}  // namespace
BEAMSOLID_REGISTER(registerLinearSeries);

}  // namespace beamsolid
