// Aligning: the mode logic by hand, the positioning command, bad input. The
// real vehicle holding the lee goal in currents of 0, 0.5 and 1.0 m/s is
// tests/simulation/test_identification_run.cpp (the identification run).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/identification/aligning.hpp"

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
  EXPECT_NEAR(kObject.centre.x() + (c.goal - kObject.centre).norm(),
              lee_goal_point(security_ellipse(kObject, 10.0), Vec2(1, 0)).x() + 1.0, 1e-12);
}

TEST(Aligning, PositioningInACurrentSetsTheHeadingOfTheWaterVelocity) {
  // At the held point the ground velocity asked for is 0: the water velocity
  // is -c, so the bow points into the current at the current's speed.
  const AlignParams params;
  AlignMemory memory;
  const Vec2 current(0.0, 0.8);  // north: the lee is north of the object
  AlignCommand c =
      align_command(kObject, params, memory, Vec2(0, 200), -kPi / 2, current);  // in the shade, facing south
  c = align_command(kObject, params, memory, c.goal, -kPi / 2, current);
  ASSERT_EQ(c.mode, AlignArea::positioning);
  EXPECT_TRUE(c.is_heading);
  EXPECT_NEAR(wrap_pi(c.course + kPi / 2), 0.0, 1e-12);
  EXPECT_NEAR(c.speed_mps, 0.8, 1e-12);
  // 8 m east of it: u = -k (8, 0) = (-0.1, 0), w = u - c = (-0.1, -0.8).
  c = align_command(kObject, params, memory, c.goal + Vec2(8, 0), -kPi / 2, current);
  EXPECT_NEAR(c.course, std::atan2(-0.8, -0.1), 1e-12);
  EXPECT_NEAR(c.speed_mps, std::hypot(0.1, 0.8), 1e-12);
}

TEST(Aligning, AtSlackWaterItWaitsAtTheApproachPoint) {
  const AlignParams params;
  AlignMemory memory;
  // Held in a 0.8 m/s current setting north ...
  AlignCommand c = align_command(kObject, params, memory, Vec2(0, 200), -kPi / 2, Vec2(0.0, 0.8));
  c = align_command(kObject, params, memory, c.goal, -kPi / 2, Vec2(0.0, 0.8));
  ASSERT_EQ(c.mode, AlignArea::positioning);
  EXPECT_FALSE(c.slack);
  // ... the tide slackens to 0.15 m/s (under 0.25 x 0.8): the vehicle heads
  // down the axis, away from the object, for the approach point 50 m on.
  c = align_command(kObject, params, memory, c.goal, -kPi / 2, Vec2(0.0, 0.15));
  EXPECT_TRUE(c.slack);
  EXPECT_NEAR(wrap_pi(c.course - kPi / 2), 0.0, 1e-9);  // north: u = k 50 = 0.625 north, minus c
  EXPECT_NEAR(c.speed_mps, 0.625 - 0.15, 1e-9);
  // Never slack without a current first: still water holds the near point.
  AlignMemory still;
  c = align_command(kObject, params, still, Vec2(0, 100), -kPi / 2, Vec2(0.0, 0.0));
  EXPECT_FALSE(c.slack);
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

}  // namespace
}  // namespace deepguide
