#include "core/PathSeries.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/CommandArgs.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace beamsolid {

PathSeries::PathSeries(int tag, std::vector<double> times, std::vector<double> values, double cFactor,
                       bool useLast, const std::string& context, bool uniform)
    : TimeSeries(tag), times_(std::move(times)), values_(std::move(values)), cFactor_(cFactor), useLast_(useLast),
      uniform_(uniform) {
  if (values_.empty()) throw OpenSeesError(context + ": the path has no values");
  if (times_.size() != values_.size())
    throw OpenSeesError(context + ": " + std::to_string(times_.size()) + " times but " +
                        std::to_string(values_.size()) + " values; expected one time per value");
  for (std::size_t i = 1; i < times_.size(); ++i)
    if (!(times_[i] > times_[i - 1])) {
      std::ostringstream os;
      os << context << ": times must strictly increase, but time " << i + 1 << " (" << times_[i]
         << ") follows time " << i << " (" << times_[i - 1] << ")";
      throw OpenSeesError(os.str());
    }
  const double span = times_.back() - times_.front();
  tolerance_ = span > 0.0 ? 1e-10 * span : 1e-12 * std::max(1.0, std::fabs(times_.front()));
}

long PathSeries::segment(double time) const {
  const long n = static_cast<long>(times_.size());
  if (uniform_) {
    if (time < times_.front()) return -1;
    if (n < 2) return -2;
    const double dt = times_[1] - times_[0];
    const long i = static_cast<long>(std::floor((time - times_.front()) / dt));
    return i >= n - 1 ? -2 : i;
  }
  if (time < times_.front() - tolerance_) return -1;
  if (time > times_.back() + tolerance_) return -2;
  if (n < 2) return 0;
  // First point strictly after t, minus one: right-continuous at interior points.
  const long i = static_cast<long>(std::upper_bound(times_.begin(), times_.end(), time) - times_.begin()) - 1;
  return std::clamp(i, 0L, n - 2);
}

double PathSeries::factor(double time) const {
  const long i = segment(time);
  if (i == -1) return 0.0;
  if (i == -2) return uniform_ && useLast_ ? cFactor_ * values_.back() : 0.0;
  if (times_.size() == 1) return cFactor_ * values_.front();
  const double t = uniform_ ? time : std::clamp(time, times_.front(), times_.back());
  const double xi = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return cFactor_ * (values_[i] + xi * (values_[i + 1] - values_[i]));
}

double PathSeries::slope(double time) const {
  const long i = segment(time);
  if (i < 0 || times_.size() == 1) return 0.0;
  return cFactor_ * (values_[i + 1] - values_[i]) / (times_[i + 1] - times_[i]);
}

void PathSeries::print(std::ostream& os) const {
  os << "TimeSeries " << tag() << " type Path points " << times_.size() << " from t = " << times_.front()
     << " to t = " << times_.back() << " factor " << cFactor_ << (useLast_ ? " useLast" : "") << '\n';
}

std::vector<double> PathSeries::readNumbers(const std::string& path, const std::string& context) {
  std::ifstream in(path);
  if (!in) throw OpenSeesError(context + ": cannot read file '" + path + "'");
  std::vector<double> out;
  std::string line;
  std::size_t lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream tokens(line);
    std::string token;
    while (tokens >> token) {
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size() || !std::isfinite(v))
        throw OpenSeesError(context + ": file '" + path + "' line " + std::to_string(lineNo) + ": '" + token +
                            "' is not a number");
      out.push_back(v);
    }
  }
  if (in.bad()) throw OpenSeesError(context + ": error while reading file '" + path + "'");
  if (out.empty()) throw OpenSeesError(context + ": file '" + path + "' contains no values");
  return out;
}

namespace {

// timeSeries('Path', tag, '-dt', dt, '-values', *v | '-filePath', f,
//            <'-factor', c>, <'-useLast'>, <'-prependZero'>, <'-startTime', t0>)
// timeSeries('Path', tag, '-time', *t | '-fileTime', ft, '-values', *v | '-filePath', f,
//            <'-factor', c>, <'-useLast'>)
std::unique_ptr<TimeSeries> buildPathSeries(CommandArgs& args, Domain&) {
  const int tag = args.nextInt("tag");
  const std::string context = "timeSeries Path " + std::to_string(tag);
  args.setContext(context);

  double dt = 0.0;
  bool haveDt = false, haveValues = false, haveTimes = false;
  std::vector<double> values, times;
  std::string valuesFile, timesFile;
  double cFactor = 1.0, startTime = 0.0;
  bool useLast = false, prependZero = false, haveStartTime = false;

  while (!args.done()) {
    if (args.nextFlag("-dt") || args.nextFlag("-dT")) {
      dt = args.nextDouble("dt");
      haveDt = true;
    } else if (args.nextFlag("-values")) {
      values = args.nextDoubles("values", 1);
      haveValues = true;
    } else if (args.nextFlag("-time")) {
      times = args.nextDoubles("time", 1);
      haveTimes = true;
    } else if (args.nextFlag("-filePath")) {
      valuesFile = args.nextString("filePath");
    } else if (args.nextFlag("-fileTime")) {
      timesFile = args.nextString("fileTime");
    } else if (args.nextFlag("-factor")) {
      cFactor = args.nextDouble("factor");
    } else if (args.nextFlag("-useLast")) {
      useLast = true;
    } else if (args.nextFlag("-prependZero")) {
      prependZero = true;
    } else if (args.nextFlag("-startTime") || args.nextFlag("-tStart")) {
      startTime = args.nextDouble("startTime");
      haveStartTime = true;
    } else {
      args.failAt(args.position(), "option",
                  "one of '-dt', '-values', '-time', '-filePath', '-fileTime', '-factor', '-useLast', "
                  "'-prependZero', '-startTime'");
    }
  }

  if (haveValues == !valuesFile.empty())
    args.fail(haveValues ? "give the values either with '-values' or with '-filePath', not both"
                         : "the values are missing: expected '-values', *values or '-filePath', file");
  if (!haveValues) values = PathSeries::readNumbers(valuesFile, context);

  const bool explicitTimes = haveTimes || !timesFile.empty();
  if (haveTimes && !timesFile.empty()) args.fail("give the times either with '-time' or with '-fileTime', not both");
  if (explicitTimes && haveDt) args.fail("give either '-dt' or explicit times ('-time' / '-fileTime'), not both");
  if (!explicitTimes && !haveDt)
    args.fail("the time spacing is missing: expected '-dt', dt or '-time', *times or '-fileTime', file");

  if (explicitTimes) {
    if (prependZero) args.fail("'-prependZero' needs '-dt' (uniform spacing); with explicit times add the point yourself");
    if (haveStartTime) args.fail("'-startTime' needs '-dt' (uniform spacing); with explicit times shift the times");
    if (!timesFile.empty()) times = PathSeries::readNumbers(timesFile, context);
  } else {
    if (!(dt > 0.0)) args.fail("dt must be positive, got " + std::to_string(dt));
    if (prependZero) values.insert(values.begin(), 0.0);
    times.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) times[i] = startTime + static_cast<double>(i) * dt;
  }
  return std::make_unique<PathSeries>(tag, std::move(times), std::move(values), cFactor, useLast, context,
                                      !explicitTimes);
}

void registerPathSeries(Registry& r) { r.timeSeries.add("Path", &buildPathSeries); }

}  // namespace
BEAMSOLID_REGISTER(registerPathSeries);

}  // namespace beamsolid
