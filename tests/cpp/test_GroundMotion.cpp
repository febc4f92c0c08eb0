// GroundMotion against closed forms of the trapezoidal rule at step h = 0.01.
#include <gtest/gtest.h>

#include <memory>

#include "core/ConstantSeries.h"
#include "core/GroundMotion.h"
#include "core/LinearSeries.h"
#include "core/OpenSeesError.h"
#include "core/PathSeries.h"

using namespace beamsolid;

namespace {
std::shared_ptr<TimeSeries> path(std::vector<double> t, std::vector<double> v) {
  return std::make_shared<PathSeries>(1, std::move(t), std::move(v), 1.0, false, "test");
}
}  // namespace

TEST(GroundMotion, LinearAccelerationIntegratesToTheTrapezoidalClosedForms) {
  // a = c t: the trapezoidal velocity is exact, c t^2 / 2; the displacement
  // carries the rule's error for a quadratic, c t^3 / 6 + c h^2 t / 12.
  const double c = 3.0, h = GroundMotion::kIntegrationStep, fact = 2.0;
  GroundMotion gm(1, path({0.0, 4.0}, {0.0, 4.0 * c}), nullptr, nullptr, fact, "groundMotion 1");
  for (int k : {1, 7, 100, 250, 399}) {
    const double t = k * h;
    EXPECT_NEAR(gm.accel(t), fact * c * t, 1e-12);
    EXPECT_NEAR(gm.vel(t), fact * c * t * t / 2, 1e-12) << t;
    EXPECT_NEAR(gm.disp(t), fact * (c * t * t * t / 6 + c * h * h * t / 12), 1e-12) << t;
  }
  // Between samples the integrals are interpolated linearly.
  const double t = 0.125;
  const double v0 = c * 0.12 * 0.12 / 2, v1 = c * 0.13 * 0.13 / 2;
  EXPECT_NEAR(gm.vel(t), fact * (v0 + 0.5 * (v1 - v0)), 1e-12);
  // The integrals end with the record (a uniform path): 0 from its last time on.
  EXPECT_EQ(gm.vel(4.0), 0.0);
  EXPECT_EQ(gm.disp(5.0), 0.0);
}

TEST(GroundMotion, GivenSeriesAreUsedAndNothingIsDifferentiated) {
  auto disp = path({0.0, 2.0}, {0.0, 1.0});
  GroundMotion onlyDisp(2, nullptr, nullptr, disp, 3.0, "groundMotion 2");
  EXPECT_NEAR(onlyDisp.disp(1.0), 1.5, 1e-14);
  EXPECT_EQ(onlyDisp.vel(1.0), 0.0);
  EXPECT_EQ(onlyDisp.accel(1.0), 0.0);
  // Velocity given: the displacement is its integral (exact for a linear velocity).
  GroundMotion onlyVel(3, nullptr, path({0.0, 2.0}, {0.0, 2.0}), nullptr, 1.0, "groundMotion 3");
  EXPECT_NEAR(onlyVel.disp(1.5), 1.5 * 1.5 / 2, 1e-12);
  EXPECT_EQ(onlyVel.accel(1.5), 0.0);
}

TEST(GroundMotion, SeriesWithoutAnEndCannotBeIntegrated) {
  try {
    GroundMotion gm(4, std::make_shared<LinearSeries>(5), nullptr, nullptr, 1.0, "groundMotion 4");
    FAIL() << "no error";
  } catch (const OpenSeesError& e) {
    EXPECT_NE(std::string(e.what()).find("groundMotion 4: cannot integrate time series 5"), std::string::npos)
        << e.what();
  }
  // A given displacement needs no integration: no error.
  GroundMotion fine(5, nullptr, nullptr, std::make_shared<ConstantSeries>(6, 1.0), 1.0, "groundMotion 5");
  EXPECT_EQ(fine.disp(10.0), 1.0);
}
