#include "core/ConstantSeries.h"

#include "core/CommandArgs.h"
#include "core/Registry.h"

namespace beamsolid {

void ConstantSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Constant factor " << cFactor_ << '\n';
}

namespace {

// timeSeries('Constant', tag, <'-factor', f>)
std::unique_ptr<TimeSeries> buildConstantSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  args.setContext("timeSeries Constant " + std::to_string(tag));
  double cFactor = 1.0;
  while (!args.done()) {
    if (args.nextFlag("-factor")) cFactor = args.nextDouble("factor");
    else args.failAt(args.position(), "option", "'-factor'");
  }
  return std::make_unique<ConstantSeries>(tag, cFactor);
}

void registerConstantSeries(Registry& r) { r.timeSeries.add("Constant", &buildConstantSeries); }

}  // namespace
BEAMSOLID_REGISTER(registerConstantSeries);

}  // namespace beamsolid
