// Time series against hand-computed values of the piecewise linear paths.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/PathSeries.h"
#include "core/Registry.h"
#include "core/TimeSeries.h"

using namespace beamsolid;
using V = CommandArgs::Value;

namespace {

// Interpolation of exactly representable data: only rounding in the last bits.
constexpr double kTol = 1e-12;

std::unique_ptr<TimeSeries> build(const std::string& type, std::vector<V> values) {
  Domain domain;
  CommandArgs args("timeSeries", std::move(values));
  return Registry::global().timeSeries.get(type)(args, domain);
}

std::string buildError(const std::string& type, std::vector<V> values) {
  try {
    build(type, std::move(values));
  } catch (const OpenSeesError& e) {
    return e.what();
  }
  return "(no error)";
}

// A per-process scratch directory, removed at exit.
struct ScratchDir {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("beamsolid_ts_" + std::to_string(::getpid()));
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

std::filesystem::path scratchFile(const std::string& name, const std::string& contents) {
  static ScratchDir scratch;
  std::filesystem::create_directories(scratch.path);
  auto path = scratch.path / name;
  std::ofstream(path) << contents;
  return path;
}

V s(const char* text) { return std::string(text); }

}  // namespace

TEST(ConstantSeries, FactorEverywhereAndZeroSlope) {
  auto ts = build("Constant", {1LL, s("-factor"), 2.5});
  EXPECT_EQ(ts->className(), "Constant");
  for (double t : {-3.0, 0.0, 0.7, 1e6}) {
    EXPECT_DOUBLE_EQ(ts->factor(t), 2.5);
    EXPECT_DOUBLE_EQ(ts->slope(t), 0.0);
  }
  EXPECT_DOUBLE_EQ(build("Constant", {2LL})->factor(4.0), 1.0);
}

TEST(LinearSeries, ProportionalToTimeWithSlopeFactor) {
  auto ts = build("Linear", {1LL, s("-factor"), 3.0});
  EXPECT_NEAR(ts->factor(0.5), 1.5, kTol);
  EXPECT_NEAR(ts->factor(-1.0), -3.0, kTol);
  EXPECT_DOUBLE_EQ(ts->slope(10.0), 3.0);
  auto plain = build("Linear", {2LL});
  EXPECT_DOUBLE_EQ(plain->factor(0.25), 0.25);
  EXPECT_DOUBLE_EQ(plain->slope(0.25), 1.0);
}

TEST(LinearSeries, StartTimeGivesZeroBefore) {
  auto ts = build("Linear", {1LL, s("-factor"), 2.0, s("-tStart"), 1.0});
  EXPECT_DOUBLE_EQ(ts->factor(0.5), 0.0);
  EXPECT_DOUBLE_EQ(ts->slope(0.5), 0.0);
  EXPECT_NEAR(ts->factor(1.75), 1.5, kTol);
  EXPECT_DOUBLE_EQ(ts->slope(1.75), 2.0);
}

TEST(LinearSeries, UnknownOptionIsAnError) {
  EXPECT_NE(buildError("Linear", {1LL, s("-fact"), 2.0}).find("timeSeries Linear 1"), std::string::npos);
}

// Path through (0,0), (0.5,1), (1,3), (1.5,2): hand values at midpoints and knots.
TEST(PathSeries, UniformSpacingInterpolatesLinearly) {
  auto ts = build("Path", {3LL, s("-dt"), 0.5, s("-values"), 0.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(ts->className(), "Path");
  EXPECT_NEAR(ts->factor(0.0), 0.0, kTol);
  EXPECT_NEAR(ts->factor(0.25), 0.5, kTol);
  EXPECT_NEAR(ts->factor(0.5), 1.0, kTol);
  EXPECT_NEAR(ts->factor(0.75), 2.0, kTol);
  EXPECT_NEAR(ts->factor(1.0), 3.0, kTol);
  EXPECT_NEAR(ts->factor(1.25), 2.5, kTol);
  EXPECT_NEAR(ts->factor(1.4999), 2.0002, kTol);
  // A uniform path ends before its last point (OpenSees): at and past it 0
  // without -useLast; before the start: 0.
  EXPECT_DOUBLE_EQ(ts->factor(1.5), 0.0);
  EXPECT_DOUBLE_EQ(ts->factor(1.6), 0.0);
  EXPECT_DOUBLE_EQ(ts->factor(-0.1), 0.0);
}

TEST(PathSeries, SlopeIsPiecewiseConstant) {
  auto ts = build("Path", {3LL, s("-dt"), 0.5, s("-values"), 0.0, 1.0, 3.0, 2.0});
  EXPECT_NEAR(ts->slope(0.25), 2.0, kTol);
  EXPECT_NEAR(ts->slope(0.75), 4.0, kTol);
  EXPECT_NEAR(ts->slope(1.25), -2.0, kTol);
  // At an interior knot the segment to the right; the last knot ends the path.
  EXPECT_NEAR(ts->slope(0.5), 4.0, kTol);
  EXPECT_DOUBLE_EQ(ts->slope(1.5), 0.0);
  EXPECT_DOUBLE_EQ(ts->slope(2.0), 0.0);
  EXPECT_DOUBLE_EQ(ts->slope(-1.0), 0.0);
  // The slope agrees with a central difference of factor() inside segments.
  for (double t : {0.1, 0.3, 0.6, 0.9, 1.1, 1.4}) {
    const double h = 1e-6;
    EXPECT_NEAR(ts->slope(t), (ts->factor(t + h) - ts->factor(t - h)) / (2 * h), 1e-6);
  }
}

TEST(PathSeries, UseLastHoldsTheLastValue) {
  auto ts = build("Path", {3LL, s("-dt"), 0.5, s("-values"), 0.0, 1.0, 3.0, 2.0, s("-useLast")});
  EXPECT_NEAR(ts->factor(1.5), 2.0, kTol);
  EXPECT_NEAR(ts->factor(1.6), 2.0, kTol);
  EXPECT_NEAR(ts->factor(100.0), 2.0, kTol);
  EXPECT_DOUBLE_EQ(ts->slope(100.0), 0.0);
}

TEST(PathSeries, FactorScalesValuesAndSlopes) {
  auto ts = build("Path", {3LL, s("-dt"), 0.5, s("-values"), 0.0, 1.0, 3.0, 2.0, s("-factor"), 2.5, s("-useLast")});
  EXPECT_NEAR(ts->factor(0.75), 5.0, kTol);
  EXPECT_NEAR(ts->slope(0.75), 10.0, kTol);
  EXPECT_NEAR(ts->factor(7.0), 5.0, kTol);
}

TEST(PathSeries, PrependZeroShiftsValuesByOneStep) {
  // Points (0,0), (0.5,1), (1,3).
  auto ts = build("Path", {4LL, s("-dt"), 0.5, s("-values"), 1.0, 3.0, s("-prependZero")});
  EXPECT_NEAR(ts->factor(0.0), 0.0, kTol);
  EXPECT_NEAR(ts->factor(0.25), 0.5, kTol);
  EXPECT_NEAR(ts->factor(0.75), 2.0, kTol);
  EXPECT_DOUBLE_EQ(ts->factor(1.0), 0.0);
  EXPECT_NEAR(ts->slope(0.25), 2.0, kTol);
}

TEST(PathSeries, StartTimeShiftsThePath) {
  // Points (2,1), (3,3).
  auto ts = build("Path", {5LL, s("-dt"), 1.0, s("-values"), 1.0, 3.0, s("-startTime"), 2.0});
  EXPECT_DOUBLE_EQ(ts->factor(1.9), 0.0);
  EXPECT_NEAR(ts->factor(2.0), 1.0, kTol);
  EXPECT_NEAR(ts->factor(2.5), 2.0, kTol);
  EXPECT_DOUBLE_EQ(ts->factor(3.0), 0.0);
  EXPECT_DOUBLE_EQ(ts->factor(3.1), 0.0);
}

TEST(PathSeries, UniformEndFollowsTheSegmentIndexOfTime) {
  // Ten steps of 0.1 accumulate to 0.9999999999999999, inside the last
  // segment (value ~10); the last point 1.0 itself ends the path (OpenSees).
  std::vector<V> args{6LL, s("-dt"), 0.1, s("-values")};
  for (int i = 0; i <= 10; ++i) args.push_back(static_cast<double>(i));
  auto ts = build("Path", args);
  double t = 0.0;
  for (int i = 0; i < 10; ++i) t += 0.1;
  EXPECT_NEAR(ts->factor(t), 10.0, 1e-9);
  EXPECT_DOUBLE_EQ(ts->factor(1.0), 0.0);
  EXPECT_DOUBLE_EQ(ts->factor(1.0 + 1e-14), 0.0);
}

TEST(PathSeries, ExplicitTimes) {
  // Points (0,0), (1,2), (3,-2).
  auto ts = build("Path", {7LL, s("-time"), 0.0, 1.0, 3.0, s("-values"), 0.0, 2.0, -2.0});
  EXPECT_NEAR(ts->factor(0.5), 1.0, kTol);
  EXPECT_NEAR(ts->factor(2.0), 0.0, kTol);
  EXPECT_NEAR(ts->factor(2.5), -1.0, kTol);
  EXPECT_NEAR(ts->slope(2.0), -2.0, kTol);
  EXPECT_NEAR(ts->slope(0.5), 2.0, kTol);
  // Explicit times include the last point; after it 0, even with -useLast (OpenSees).
  EXPECT_NEAR(ts->factor(3.0), -2.0, kTol);
  EXPECT_DOUBLE_EQ(ts->factor(3.5), 0.0);
  auto held = build("Path", {7LL, s("-time"), 0.0, 1.0, 3.0, s("-values"), 0.0, 2.0, -2.0, s("-useLast")});
  EXPECT_DOUBLE_EQ(held->factor(3.5), 0.0);
}

TEST(PathSeries, ValuesAndTimesFromFiles) {
  auto values = scratchFile("values.txt", "0 1\n3, 2\n\n");
  auto times = scratchFile("times.txt", "0.0\n0.5\n1.0\n1.5\n");
  auto uniform = build("Path", {8LL, s("-dt"), 0.5, s("-filePath"), values.string()});
  auto timed = build("Path", {9LL, s("-fileTime"), times.string(), s("-filePath"), values.string()});
  for (double t : {0.25, 0.75, 1.25}) {
    const double expected = t < 0.5 ? 2 * t : t < 1.0 ? 1 + 4 * (t - 0.5) : 3 - 2 * (t - 1.0);
    EXPECT_NEAR(uniform->factor(t), expected, kTol) << t;
    EXPECT_NEAR(timed->factor(t), expected, kTol) << t;
  }
}

TEST(PathSeries, ClearErrors) {
  auto contains = [](const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
  };
  std::string m = buildError("Path", {1LL, s("-time"), 0.0, 1.0, 1.0, s("-values"), 0.0, 1.0, 2.0});
  EXPECT_TRUE(contains(m, "timeSeries Path 1") && contains(m, "strictly increase")) << m;
  m = buildError("Path", {1LL, s("-time"), 0.0, 1.0, s("-values"), 0.0, 1.0, 2.0});
  EXPECT_TRUE(contains(m, "2 times but 3 values")) << m;
  m = buildError("Path", {1LL, s("-dt"), 0.1, s("-values"), s("-factor"), 2.0});
  EXPECT_TRUE(contains(m, "values")) << m;
  m = buildError("Path", {1LL, s("-values"), 1.0, 2.0});
  EXPECT_TRUE(contains(m, "'-dt'")) << m;
  m = buildError("Path", {1LL, s("-dt"), 0.1});
  EXPECT_TRUE(contains(m, "values are missing")) << m;
  m = buildError("Path", {1LL, s("-dt"), -0.1, s("-values"), 1.0});
  EXPECT_TRUE(contains(m, "dt must be positive")) << m;
  m = buildError("Path", {1LL, s("-dt"), 0.1, s("-filePath"), s("/nonexistent/dir/motion.txt")});
  EXPECT_TRUE(contains(m, "cannot read file '/nonexistent/dir/motion.txt'")) << m;
  auto bad = scratchFile("bad.txt", "0.1 0.2\n0.3 abc\n");
  m = buildError("Path", {1LL, s("-dt"), 0.1, s("-filePath"), bad.string()});
  EXPECT_TRUE(contains(m, "line 2") && contains(m, "'abc' is not a number")) << m;
  auto empty = scratchFile("empty.txt", "\n \n");
  m = buildError("Path", {1LL, s("-dt"), 0.1, s("-filePath"), empty.string()});
  EXPECT_TRUE(contains(m, "contains no values")) << m;
  m = buildError("Path", {1LL, s("-dt"), 0.1, s("-values"), 1.0, s("-filePath"), bad.string()});
  EXPECT_TRUE(contains(m, "not both")) << m;
  m = buildError("Path", {1LL, s("-time"), 0.0, 1.0, s("-values"), 1.0, 2.0, s("-prependZero")});
  EXPECT_TRUE(contains(m, "'-prependZero' needs '-dt'")) << m;
}

// Periodic series against their closed forms, with the ends included.
TEST(TrigSeries, SineBetweenStartAndEndWithShiftAndZeroShift) {
  const double pi = 3.14159265358979323846;
  auto ts = build("Trig", {11LL, 1.0, 3.0, 2.0, s("-factor"), 2.0, s("-shift"), 0.3});
  EXPECT_EQ(ts->className(), "Trig");
  for (double t : {1.0, 1.3, 2.0, 2.9, 3.0}) {
    EXPECT_NEAR(ts->factor(t), 2.0 * std::sin(pi * (t - 1.0) + 0.3), kTol) << t;
    EXPECT_NEAR(ts->slope(t), 2.0 * pi * std::cos(pi * (t - 1.0) + 0.3), 1e-11) << t;
  }
  EXPECT_DOUBLE_EQ(ts->factor(0.999), 0.0);
  EXPECT_DOUBLE_EQ(ts->factor(3.001), 0.0);
  // The zero shift adds z and moves the phase by period*asin(z/f)/(2 pi).
  auto z = build("Sine", {12LL, 0.0, 10.0, 4.0, s("-zeroShift"), 0.5});
  const double phi = -4.0 * std::asin(0.5) / (2 * pi);
  for (double t : {0.0, 0.7, 3.1})
    EXPECT_NEAR(z->factor(t), std::sin(pi / 2 * t + phi) + 0.5, kTol) << t;
  EXPECT_NE(buildError("Trig", {13LL, 0.0, 1.0, 0.0}).find("period must be positive"), std::string::npos);
  EXPECT_NE(buildError("Trig", {13LL, 0.0, 1.0, 1.0, s("-zeroShift"), 2.0}).find("zeroShift"), std::string::npos);
}

TEST(RectangularSeries, ConstantInsideClosedInterval) {
  auto ts = build("Rectangular", {14LL, 1.0, 3.0, s("-factor"), -2.5});
  EXPECT_DOUBLE_EQ(ts->factor(1.0), -2.5);
  EXPECT_DOUBLE_EQ(ts->factor(2.0), -2.5);
  EXPECT_DOUBLE_EQ(ts->factor(3.0), -2.5);
  EXPECT_DOUBLE_EQ(ts->factor(0.99), 0.0);
  EXPECT_DOUBLE_EQ(ts->factor(3.01), 0.0);
  EXPECT_DOUBLE_EQ(ts->slope(2.0), 0.0);
}

TEST(PulseSeries, OnForTheWidthOfEachPeriod) {
  auto ts = build("Pulse", {15LL, 1.0, 4.0, 1.0});
  EXPECT_DOUBLE_EQ(ts->factor(1.0), 1.0);
  EXPECT_DOUBLE_EQ(ts->factor(1.49), 1.0);
  EXPECT_DOUBLE_EQ(ts->factor(1.5), 0.0);  // the pulse ends at width * period
  EXPECT_DOUBLE_EQ(ts->factor(2.0), 1.0);
  EXPECT_DOUBLE_EQ(ts->factor(4.0), 1.0);
  EXPECT_DOUBLE_EQ(ts->factor(4.2), 0.0);
  auto w = build("Pulse", {16LL, 1.0, 5.0, 1.5, s("-width"), 0.3, s("-shift"), 0.2, s("-factor"), 2.0,
                           s("-zeroShift"), 0.1});
  // On while frac((t - 1 + 0.2) / 1.5) < 0.3, i.e. t in [1, 1.25) and [2.3, 2.75), ...
  EXPECT_NEAR(w->factor(1.2), 2.1, kTol);
  EXPECT_NEAR(w->factor(1.3), 0.1, kTol);
  EXPECT_NEAR(w->factor(2.4), 2.1, kTol);
  EXPECT_NEAR(w->factor(2.8), 0.1, kTol);
  EXPECT_DOUBLE_EQ(w->factor(5.5), 0.0);
  EXPECT_NE(buildError("Pulse", {17LL, 0.0, 1.0, 1.0, s("-width"), 1.5}).find("width"), std::string::npos);
}

TEST(TriangleSeries, UnitTriangleWaveAndZeroShift) {
  auto ts = build("Triangle", {18LL, 1.0, 4.0, 2.0});
  const double t[] = {1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0};
  const double v[] = {0.0, 0.5, 1.0, 0.0, -1.0, 0.0, 1.0, 0.0};
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(ts->factor(t[i]), v[i], kTol) << t[i];
  EXPECT_NEAR(ts->slope(1.2), 2.0, kTol);
  EXPECT_NEAR(ts->slope(2.2), -2.0, kTol);
  EXPECT_DOUBLE_EQ(ts->factor(4.5), 0.0);
  // With a zero shift z the wave still starts from 0: factor = f*tri(p - z/(4f)) + z.
  auto z = build("Triangle", {19LL, 1.0, 4.0, 2.0, s("-zeroShift"), 0.1});
  EXPECT_NEAR(z->factor(1.0), 0.0, kTol);
  EXPECT_NEAR(z->factor(1.5), 1.0, kTol);
  EXPECT_NEAR(z->factor(2.5), -0.8, kTol);
}
