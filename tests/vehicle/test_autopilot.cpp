// The course autopilot closed around the vehicle model: a 90 deg course change
// settles within a derived bound, 179 -> -179 deg turns the short way, course
// over ground is held in a cross-current, and the limits are reported.
#include <gtest/gtest.h>

#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/vehicle/autopilot.hpp"

using namespace deepguide;

namespace {

const VehicleParams kP{};

struct Loop {
  VehicleState vehicle;
  AutopilotState memory;
  AutopilotOutput last;
};

// Nautical degrees in, math radians inside.
AutopilotSetpoint course_deg(double nautical, double speed = kP.cruise_speed_mps, double depth = 20.0) {
  return {heading_deg_to_math_rad(nautical), speed, depth};
}

void step(Loop& r, const AutopilotSetpoint& sp, const Vec2& current) {
  r.last = autopilot_step(kP, r.memory, r.vehicle, sp, current);
  step_vehicle(kP, r.vehicle, r.last.command, current);
}

double cog_error_deg(const VehicleState& s, const AutopilotSetpoint& sp) {
  return rad_to_deg(wrap_pi(course_over_ground(s) - sp.course));
}

}  // namespace

TEST(Autopilot, GainsByPolePlacement) {
  // T = 4, K = 0.25 (m = 16, d = 4), w_n = 0.3, zeta = 1 -> Kp = 1.44, Kd = 5.6, Ki = 0.0432.
  const HeadingGains g = heading_gains(kP);
  EXPECT_NEAR(g.kp, 1.44, 1e-12);
  EXPECT_NEAR(g.kd, 5.6, 1e-12);
  EXPECT_NEAR(g.ki, 0.0432, 1e-12);
}

TEST(Autopilot, NinetyDegreeCourseChangeSettlesWithinBound) {
  // Bound: without limits the critically damped reference is within 1 % (0.9
  // deg) of the step after x / w_r with (1 + x) e^-x = 0.01, x = 6.64: 33.2 s;
  // the rate limit adds at most the ramp 90 deg / 5 deg/s = 18 s; the loop
  // (critically damped at w_n = 0.3) lags by at most its own 1 % time 6.64 / 0.3
  // = 22.1 s. Sum 73.3 s. Below: no vehicle turns 90 deg at 6 deg/s in < 15 s.
  Loop r{make_vehicle_state({0, 0}, 20.0, heading_deg_to_math_rad(0.0), kP.cruise_speed_mps), {}, {}};
  const AutopilotSetpoint sp = course_deg(90.0);
  double settled_at = 0.0, overshoot = 0.0, max_rate_ref = 0.0;
  for (int i = 0; i < 2000; ++i) {
    step(r, sp, Vec2::Zero());
    const double e = cog_error_deg(r.vehicle, sp);
    if (std::abs(e) > 1.0) settled_at = r.vehicle.time_s;
    overshoot = std::max(overshoot, -e);  // see below: past the set-point e < 0
    max_rate_ref = std::max(max_rate_ref, std::abs(r.last.rate_ref));
    ASSERT_LE(std::abs(r.last.rate_ref), kP.autopilot.max_reference_turn_rate + 1e-15);
  }
  EXPECT_LT(settled_at, 73.3);
  EXPECT_GT(settled_at, 15.0);
  // Course 90 (east) is math 0; coming from north (math pi/2) the error is
  // positive on the way, negative past the set-point.
  EXPECT_LT(overshoot, 0.5);
  EXPECT_GT(rad_to_deg(max_rate_ref), 4.0);  // the reference did use its rate
  EXPECT_NEAR(cog_error_deg(r.vehicle, sp), 0.0, 0.01);
  EXPECT_LT(r.vehicle.yaw_rate, 1e-4);
  EXPECT_NEAR(r.vehicle.speed_mps, kP.cruise_speed_mps, 1e-9);
}

TEST(Autopilot, TurnsTheShortWayAcross180) {
  // 179 -> -179 (= 181) deg: 2 deg to starboard, not 358 to port.
  Loop r{make_vehicle_state({0, 0}, 20.0, heading_deg_to_math_rad(179.0), kP.cruise_speed_mps), {}, {}};
  const AutopilotSetpoint sp = course_deg(-179.0);
  for (int i = 0; i < 600; ++i) {
    step(r, sp, Vec2::Zero());
    const double h = math_rad_to_heading_deg(r.vehicle.heading);
    ASSERT_GT(h, 178.9) << "t = " << r.vehicle.time_s;
    ASSERT_LT(h, 181.2) << "t = " << r.vehicle.time_s;
    ASSERT_LE(r.vehicle.yaw_rate, 1e-6);  // clockwise only (math r <= 0), small overshoot aside
  }
  EXPECT_NEAR(math_rad_to_heading_deg(r.vehicle.heading), 181.0, 0.05);
  // And the other way round: 181 -> 179 turns to port.
  Loop q{make_vehicle_state({0, 0}, 20.0, heading_deg_to_math_rad(181.0), kP.cruise_speed_mps), {}, {}};
  for (int i = 0; i < 600; ++i) step(q, course_deg(179.0), Vec2::Zero());
  EXPECT_NEAR(math_rad_to_heading_deg(q.vehicle.heading), 179.0, 0.05);
}

TEST(Autopilot, HoldsCourseOverGroundInCrossCurrent) {
  // Course north, 0.5 m/s current to the east: the vehicle crabs into it with
  // heading -asin(0.5 / 2.0578) = -14.06 deg, and its ground track runs north.
  const Vec2 current(0.5, 0.0);
  Loop r{make_vehicle_state({0, 0}, 20.0, heading_deg_to_math_rad(0.0), kP.cruise_speed_mps, current), {}, {}};
  const AutopilotSetpoint sp = course_deg(0.0);
  for (int i = 0; i < 900; ++i) step(r, sp, current);
  const double crab = rad_to_deg(std::asin(0.5 / kP.cruise_speed_mps));
  EXPECT_NEAR(crab, 14.06, 0.01);
  EXPECT_NEAR(cog_error_deg(r.vehicle, sp), 0.0, 0.05);
  EXPECT_NEAR(math_rad_to_heading_deg(r.vehicle.heading), 360.0 - crab, 0.05);
  EXPECT_FALSE(r.last.course_unreachable);
  // Over the next 100 s the track drifts less than 5 cm east of its line.
  const double x0 = r.vehicle.position.x();
  for (int i = 0; i < 1000; ++i) step(r, sp, current);
  EXPECT_NEAR(r.vehicle.position.x(), x0, 0.05);
  EXPECT_GT(r.vehicle.position.y(), 190.0);  // made good ~ sqrt(2.0578^2 - 0.25) x 100 = 199.6 m
}

TEST(Autopilot, CrabHeadingMakesGoodTheCourse) {
  bool ok = false;
  const Vec2 c(0.3, -0.4);
  for (double course_deg : {0.0, 45.0, 135.0, 200.0, 300.0}) {
    const double chi = heading_deg_to_math_rad(course_deg);
    const double h = crab_heading(chi, 2.0, c, ok);
    ASSERT_TRUE(ok);
    const Vec2 g = 2.0 * unit_vector(h) + c;
    const Vec2 d = unit_vector(chi);
    EXPECT_NEAR(d.x() * g.y() - d.y() * g.x(), 0.0, 1e-12) << course_deg;  // no cross-track motion
    EXPECT_GT(d.dot(g), 0.0) << course_deg;
  }
  // Cross-current stronger than the vehicle: reported, and the heading pushes against it.
  const double h = crab_heading(heading_deg_to_math_rad(0.0), 1.0, Vec2(1.5, 0.0), ok);
  EXPECT_FALSE(ok);
  EXPECT_NEAR(math_rad_to_heading_deg(h), 270.0, 1e-9);
  // Head current stronger than the vehicle: reported, facing the course.
  crab_heading(heading_deg_to_math_rad(0.0), 1.0, Vec2(0.0, -1.5), ok);
  EXPECT_FALSE(ok);
}

TEST(Autopilot, ReportsWhatItCannotDo) {
  Loop r{make_vehicle_state({0, 0}, 20.0, 0.0, 1.0), {}, {}};
  step(r, AutopilotSetpoint{0.0, 9.0, -5.0}, Vec2(0.0, 3.0));
  EXPECT_TRUE(r.last.speed_limited);
  EXPECT_EQ(r.last.command.speed_mps, kP.max_speed_mps);
  EXPECT_TRUE(r.last.depth_limited);
  EXPECT_EQ(r.last.command.depth_m, 0.0);
  EXPECT_TRUE(r.last.course_unreachable);  // 3 m/s cross-current, 1 m/s through water
  AutopilotState m;
  EXPECT_THROW(autopilot_step(kP, m, r.vehicle, AutopilotSetpoint{std::nan(""), 1.0, 0.0}, Vec2::Zero()), InputError);
  EXPECT_THROW(autopilot_step(kP, m, r.vehicle, AutopilotSetpoint{0.0, 1.0, 0.0}, Vec2(INFINITY, 0.0)), InputError);
}

TEST(Autopilot, ClosedLoopIsBitIdentical) {
  auto simulate = [](double drift) {
    Loop r{make_vehicle_state({0, 0}, 0.0, 0.0, 0.0), {}, {}};
    const Vec2 current(0.2, drift);
    for (int i = 0; i < 6000; ++i) {
      const double course = 90.0 * std::floor(i / 1000.0) + 10.0 * std::sin(0.01 * i);
      step(r, course_deg(course, 1.0 + (i % 3000) * 0.0005, 0.01 * i), current);
    }
    return r;
  };
  const Loop a = simulate(0.1), b = simulate(0.1), c = simulate(0.1 + 1e-13);
  EXPECT_EQ(a.vehicle, b.vehicle);
  EXPECT_EQ(a.memory, b.memory);
  EXPECT_FALSE(a.vehicle == c.vehicle);
}

// A course set-point that turns at a steady rate: without its rate the
// reference lags by 2 r / w_r (a critically damped second-order reference); with it
// fed forward the lag goes (autopilot.hpp).
TEST(Autopilot, CourseRateFeedForwardRemovesTheRampLag) {
  const double rate = deg_to_rad(3.0);
  auto lag_after_a_minute = [&](bool feed_forward, const Vec2& current) {
    Loop r{make_vehicle_state({0, 0}, 20.0, 0.0, kP.cruise_speed_mps, current), {}, {}};
    const int steps = 1200;  // 120 s: 60 s to settle, then the ramp's steady state
    double lag = 0.0;
    for (int k = 0; k < steps; ++k) {
      const double t = k * kP.step_s;
      AutopilotSetpoint sp{rate * t, kP.cruise_speed_mps, 20.0};
      if (feed_forward) sp.course_rate = rate;
      step(r, sp, current);
      lag = std::abs(rad_to_deg(wrap_pi(sp.course - course_over_ground(r.vehicle))));
    }
    return lag;
  };
  const double w_r = kP.autopilot.reference_natural_frequency_rad_s;
  const double expected_lag = rad_to_deg(2.0 * rate / w_r);  // 30 deg
  EXPECT_NEAR(lag_after_a_minute(false, {0, 0}), expected_lag, 2.0);
  EXPECT_LT(lag_after_a_minute(true, {0, 0}), 1.0);
  // In a current the heading turns faster or slower than the course (the crab
  // changes): fed forward through d psi / d chi, the course is still held.
  EXPECT_LT(lag_after_a_minute(true, {0.0, 0.8}), 2.0);
}

TEST(Autopilot, HeadingModeHoldsTheBowNotTheCourse) {
  const Vec2 current(0.0, 1.0);  // north, across an east heading
  Loop r{make_vehicle_state({0, 0}, 20.0, 0.0, kP.cruise_speed_mps, current), {}, {}};
  AutopilotSetpoint sp{deg_to_rad(10.0), kP.cruise_speed_mps, 20.0};
  sp.heading_mode = true;
  for (int k = 0; k < 3000; ++k) step(r, sp, current);  // 300 s: the integral's slow tail too
  EXPECT_NEAR(rad_to_deg(wrap_pi(r.vehicle.heading - sp.course)), 0.0, 0.05);
  // The course over ground is the heading's plus the current's: well off it
  // (atan2(2.06 sin 10 + 1, 2.06 cos 10) = 33.8 deg).
  EXPECT_NEAR(rad_to_deg(wrap_pi(course_over_ground(r.vehicle) - sp.course)), 23.8, 0.3);
  // Back to course mode: the reference restarts at the course over ground,
  // so the first step's heading set-point is the crab for that course, the
  // heading the vehicle has: no jump by the crab angle.
  AutopilotSetpoint course = sp;
  course.heading_mode = false;
  course.course = course_over_ground(r.vehicle);
  const AutopilotOutput first = autopilot_step(kP, r.memory, r.vehicle, course, current);
  EXPECT_NEAR(rad_to_deg(wrap_pi(first.heading_setpoint - r.vehicle.heading)), 0.0, 0.1);
  EXPECT_FALSE(r.last.course_unreachable);
}
