// Aligning: the mode logic by hand, and the real vehicle model (Nomoto yaw,
// 20 s speed lag, the course autopilot) holding the lee goal in currents of
// 0, 0.5 and 1.0 m/s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/identification/aligning.hpp"
#include "deepguide/vehicle/autopilot.hpp"
#include "deepguide/vehicle/vehicle_model.hpp"

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;
const Ellipse kObject{{0.0, 0.0}, 15.0, 8.0, 0.3};

TEST(Aligning, ModesFollowTheShadeAndTheHeading) {
  const AlignParams params;
  const Vec2 current(0.5, 0.0);  // east: the lee is east of the object
  AlignMemory memory;
  // Upstream (west): evasive, heading for the approach point down the axis.
  AlignCommand c = align_command(kObject, params, memory, Vec2(-100, 5), 0.0, current);
  EXPECT_EQ(c.mode, AlignArea::evasive);
  EXPECT_EQ(memory.switches, 0);
  // In the shade but heading downstream, far from the approach point: still evasive.
  c = align_command(kObject, params, memory, Vec2(40, 0), 0.0, current);
  EXPECT_EQ(c.mode, AlignArea::evasive);
  // Facing upstream in the shade: positioning; the bow into the current near the goal.
  c = align_command(kObject, params, memory, Vec2(40, 0), kPi, current);
  EXPECT_EQ(c.mode, AlignArea::positioning);
  EXPECT_EQ(memory.switches, 1);
  // Once positioning, the heading no longer matters inside the shade ...
  c = align_command(kObject, params, memory, Vec2(40, 1), 0.0, current);
  EXPECT_EQ(c.mode, AlignArea::positioning);
  // ... and leaving the shade (across it, beyond the half-width) ends it.
  c = align_command(kObject, params, memory, Vec2(40, 40), kPi, current);
  EXPECT_EQ(c.mode, AlignArea::evasive);
  EXPECT_EQ(memory.switches, 2);
  // The held point: the lee goal on the 10 m safety ellipse plus the 1 m buffer, on the axis.
  EXPECT_NEAR(c.goal.y(), 0.0, 1e-12);
  EXPECT_NEAR(kObject.center.x() + (c.goal - kObject.center).norm(),
              lee_goal_point(security_ellipse(kObject, 10.0), Vec2(1, 0)).x() + 1.0, 1e-12);
}

TEST(Aligning, ACurrentFasterThanTheVehicleIsReportedNotSpun) {
  AlignParams params;
  AlignMemory memory;
  const Vec2 current(0.0, -4.0);  // 4 m/s south, the vehicle makes 3.09 at most
  const AlignCommand c = align_command(kObject, params, memory, Vec2(0, -60), 0.0, current);
  EXPECT_TRUE(c.overpowered);
  EXPECT_NEAR(wrap_pi(c.course - kPi / 2), 0.0, 1e-12);  // into the current
  EXPECT_EQ(c.speed_mps, params.max_speed_mps);
}

TEST(Aligning, BadInputIsRejected) {
  AlignMemory memory;
  AlignParams params;
  params.standoff_m = 0.0;
  EXPECT_THROW(align_command(kObject, params, memory, Vec2(0, 50), 0.0, Vec2(0, 0)), InputError);
  params = AlignParams{};
  params.position_gain_per_s = std::nan("");
  EXPECT_THROW(align_command(kObject, params, memory, Vec2(0, 50), 0.0, Vec2(0, 0)), InputError);
  params = AlignParams{};
  EXPECT_THROW(align_command(kObject, params, memory, Vec2(0, 50), 0.0, Vec2(std::nan(""), 0)), InputError);
}

struct Hold {
  bool positioned = false;
  double distance_rms = 0.0;  ///< |distance to the object - the held point's| over the last 300 s
  double min_clearance = 1e9;
  double heading_error = 0.0;  ///< max |heading - upstream| over the last 100 s (rad)
};

Hold hold(double speed, double direction) {
  const Vec2 current = speed * Vec2(std::cos(direction), std::sin(direction));
  const VehicleParams vp;
  const AlignParams params;
  AlignMemory memory;
  VehicleState state = make_vehicle_state(Vec2(-200, 30), 0.0, 0.0, params.speed_mps, current);
  AutopilotState autopilot;
  Hold h;
  double sum = 0.0, n = 0.0;
  const int steps = 9000;  // 900 s
  for (int k = 0; k < steps; ++k) {
    const AlignCommand c = align_command(kObject, params, memory, state.position, course_over_ground(state), current);
    h.min_clearance = std::min(h.min_clearance, signed_distance(kObject, state.position));
    h.positioned = h.positioned || c.mode == AlignArea::positioning;
    if (k >= steps - 3000) {
      const double e = signed_distance(kObject, state.position) - signed_distance(kObject, c.goal);
      sum += e * e;
      n += 1.0;
    }
    if (k >= steps - 1000 && speed > 0.0) {
      h.heading_error = std::max(h.heading_error, std::abs(wrap_pi(state.heading - math_angle(-current))));
    }
    const AutopilotOutput out = autopilot_step(vp, autopilot, state, {c.course, c.speed_mps, 0.0}, current);
    step_vehicle(vp, state, out.command, current);
  }
  h.distance_rms = std::sqrt(sum / n);
  return h;
}

TEST(Aligning, TheVehicleHoldsTheLeeGoalInCurrentsUpTo1MetrePerSecond) {
  for (double speed : {0.0, 0.5, 1.0}) {
    for (double direction : {0.0, 2.0}) {
      SCOPED_TRACE(testing::Message() << speed << " m/s towards " << direction << " rad");
      const Hold h = hold(speed, direction);
      EXPECT_TRUE(h.positioned);
      EXPECT_LT(h.distance_rms, 1.0);
      EXPECT_GE(h.min_clearance, 10.0);  // never inside the standoff
      if (speed > 0.0) {
        EXPECT_LT(h.heading_error, deg_to_rad(10.0));  // bow into the current
      }
    }
  }
}

}  // namespace
}  // namespace deepguide
