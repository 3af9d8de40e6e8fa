// Going around: modes, the line-of-sight sign, laps, and a kinematic vehicle
// (turning at most 5 deg/s) that must complete its laps on the offset path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/identification/going_around.hpp"
#include "deepguide/identification/offset_path.hpp"

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;
const Ellipse kObject{{40.0, -10.0}, 25.0, 12.0, 0.4};

TEST(GoingAround, ModesSwitchAtTheBordersWithHysteresis) {
  AroundParams params;
  params.distance_m = 20.0;
  params.switch_m = 10.0;
  AroundMemory memory;
  // Points on the major axis beyond the path: e = x - (25 + 20) along it.
  auto at = [&](double e) -> Vec2 { return kObject.centre + (45.0 + e) * kObject.major_dir(); };
  EXPECT_EQ(around_command(kObject, params, memory, at(10.1)).mode, AroundMode::steering);
  EXPECT_NEAR(around_command(kObject, params, memory, at(10.1)).cross_track_m, 10.1, 1e-9);
  EXPECT_EQ(around_command(kObject, params, memory, at(9.9)).mode, AroundMode::tracking);
  EXPECT_EQ(around_command(kObject, params, memory, at(19.9)).mode, AroundMode::tracking);  // hysteresis
  EXPECT_EQ(around_command(kObject, params, memory, at(20.1)).mode, AroundMode::steering);
  EXPECT_EQ(around_command(kObject, params, memory, at(-9.9)).mode, AroundMode::tracking);  // inside the path
}

TEST(GoingAround, SteeringHeadsForTheNearestPathPoint) {
  AroundParams params;
  AroundMemory memory;
  const Vec2 p = kObject.centre + 120.0 * kObject.minor_dir();  // on the minor axis: nearest point along it
  const AroundCommand c = around_command(kObject, params, memory, p);
  EXPECT_EQ(c.mode, AroundMode::steering);
  EXPECT_NEAR(wrap_pi(c.course - math_angle(-kObject.minor_dir())), 0.0, 1e-9);
  EXPECT_NEAR(c.cross_track_m, 120.0 - 12.0 - 20.0, 1e-9);
}

TEST(GoingAround, LineOfSightTurnsTowardsThePath) {
  // On the major axis end, anticlockwise the path runs along +minor; outside by 5 m
  // the course turns left of it by atan(5 / lookahead); clockwise it runs along -minor and turns right.
  AroundParams params;
  params.switch_m = 10.0;
  const Vec2 p = kObject.centre + 50.0 * kObject.major_dir();
  const double along = math_angle(kObject.minor_dir());
  for (int direction : {1, -1}) {
    params.direction = direction;
    AroundMemory memory;
    const AroundCommand c = around_command(kObject, params, memory, p);
    ASSERT_EQ(c.mode, AroundMode::tracking);
    const double alpha = direction > 0 ? along : wrap_pi(along + kPi);
    EXPECT_NEAR(wrap_pi(c.course - alpha), direction * std::atan(5.0 / params.lookahead_m), 1e-9) << direction;
  }
}

struct Flight {
  bool done = false;
  double time_s = 0.0;
  double rms_tracking = 0.0;  ///< cross-track RMS after the first quarter lap of tracking
  double min_clearance = 1e9;
  double laps = 0.0;
};

// A kinematic vehicle: speed along its heading, the heading turning towards the
// command at 5 deg/s at most, 10 Hz.
Flight fly(const AroundParams& params, Vec2 p, double heading) {
  AroundMemory memory;
  Flight run;
  const double dt = 0.1, max_rate = deg_to_rad(5.0);
  double sum = 0.0, n = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const AroundCommand c = around_command(kObject, params, memory, p);
    run.min_clearance = std::min(run.min_clearance, signed_distance(kObject, p));
    if (c.mode == AroundMode::done) {
      run.done = true;
      run.time_s = k * dt;
      break;
    }
    if (c.mode == AroundMode::tracking && memory.laps_done() > 0.25) {
      sum += c.cross_track_m * c.cross_track_m;
      n += 1.0;
    }
    heading += std::clamp(wrap_pi(c.course - heading), -max_rate * dt, max_rate * dt);
    p += c.speed_mps * dt * Vec2(std::cos(heading), std::sin(heading));
  }
  run.rms_tracking = n > 0 ? std::sqrt(sum / n) : 1e9;
  run.laps = memory.laps_done();
  return run;
}

TEST(GoingAround, KinematicVehicleCompletesTheLapsOnThePath) {
  AroundParams params;
  params.distance_m = 20.0;
  params.laps = 2.0;
  // The path's tightest turn (12^2 / 25 + 20 = 25.8 m) is wider than the vehicle's (23.6 m).
  check_offset_path_fits(kObject, params.distance_m, params.speed_mps / deg_to_rad(5.0), "test");
  for (int direction : {1, -1}) {
    params.direction = direction;
    const Flight run = fly(params, kObject.centre + Vec2(-150.0, 30.0), 0.0);
    SCOPED_TRACE(direction);
    EXPECT_TRUE(run.done);
    EXPECT_GE(run.laps, 2.0);
    EXPECT_LT(run.rms_tracking, 1.0);
    EXPECT_GT(run.min_clearance, 19.0);  // joins the 20 m path without overshooting into it
  }
}

TEST(GoingAround, BadParametersAreRejected) {
  AroundParams params;
  AroundMemory memory;
  params.direction = 0;
  EXPECT_THROW(around_command(kObject, params, memory, Vec2(0, 0)), InputError);
  params = AroundParams{};
  params.distance_m = -1.0;
  EXPECT_THROW(around_command(kObject, params, memory, Vec2(0, 0)), InputError);
  params = AroundParams{};
  params.laps = std::nan("");
  EXPECT_THROW(around_command(kObject, params, memory, Vec2(0, 0)), InputError);
  params = AroundParams{};
  EXPECT_THROW(around_command(kObject, params, memory, Vec2(std::nan(""), 0)), InputError);
}

}  // namespace
}  // namespace deepguide

namespace deepguide {
namespace {

// The course rate the unit feeds forward is the time derivative of its own
// course along the motion: central differences over +-0.01 s at points
// outside, on and inside the path, both directions, several velocities.
TEST(GoingAround, CourseRateIsTheDerivativeOfTheCourse) {
  const Ellipse object{{5.0, -3.0}, 25.0, 12.0, 0.4};
  AroundParams params;
  params.distance_m = 20.0;
  const double dt = 0.01;
  int checked = 0;
  for (int direction : {1, -1}) {
    params.direction = direction;
    for (double t : {0.0, 0.7, 1.6, 2.9, -2.2}) {
      for (double off : {-6.0, 0.0, 4.0, 15.0}) {
        const Vec2 p = offset_point(object, params.distance_m + off, t);
        for (const Vec2& v : {Vec2(2.0, 0.5), Vec2(-1.0, 2.5), Vec2(0.3, -1.8)}) {
          AroundMemory m0, m1, m2;
          const AroundCommand c = around_command(object, params, m0, p, v);
          ASSERT_EQ(c.mode, AroundMode::tracking);
          const double ahead = around_command(object, params, m1, p + dt * v).course;
          const double behind = around_command(object, params, m2, p - dt * v).course;
          EXPECT_NEAR(c.course_rate, wrap_pi(ahead - behind) / (2.0 * dt), 1e-5)
              << direction << " t " << t << " off " << off;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 120);
  // Steering has no rate to feed forward.
  AroundMemory m;
  EXPECT_EQ(around_command(object, params, m, object.centre + Vec2(300, 0), Vec2(2, 0)).course_rate, 0.0);
}

}  // namespace
}  // namespace deepguide
