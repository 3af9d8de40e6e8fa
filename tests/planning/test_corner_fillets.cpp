// Corners rounded on a radius (corner_fillets.hpp), against hand-derived
// geometry.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/corner_fillets.hpp"

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CornerFillets, ARightAngleTurnsOnAQuarterCircle) {
  // (0,0) -> (100,0) -> (100,100), R = 10: tangent length R tan(45 deg) = 10,
  // so the arc runs from (90,0) to (100,10) round (90,10).
  const FilletedRoute r = fillet_corners({{0, 0}, {100, 0}, {100, 100}}, 10.0);
  ASSERT_FALSE(r.too_tight);
  ASSERT_EQ(r.legs.size(), 3u);
  const RouteLeg& arc = r.legs[1];
  EXPECT_EQ(arc.kind, RouteLeg::Kind::arc);
  EXPECT_EQ(arc.turn, 1);
  EXPECT_LT((arc.from - Vec2(90, 0)).norm(), 1e-12);
  EXPECT_LT((arc.to - Vec2(100, 10)).norm(), 1e-12);
  EXPECT_LT((arc.core.centre - Vec2(90, 10)).norm(), 1e-12);
  EXPECT_NEAR(arc.length_m, 5 * kPi, 1e-12);
  EXPECT_DOUBLE_EQ(min_turn_radius(arc), 10.0);
  EXPECT_LT((arc_point(arc, arc.phi_from) - arc.from).norm(), 1e-12);
  EXPECT_LT((arc_point(arc, arc.phi_to) - arc.to).norm(), 1e-12);
  // Its middle: R (sqrt 2 - 1) inside the corner.
  const Vec2 mid = arc_point(arc, 0.5 * (arc.phi_from + arc.phi_to));
  EXPECT_NEAR((mid - Vec2(100, 0)).norm(), 10 * (std::sqrt(2.0) - 1), 1e-12);
  EXPECT_NEAR(r.legs[0].length_m + r.legs[2].length_m, 180.0, 1e-12);
}

TEST(CornerFillets, RightTurnsGoClockwiseAndStraightPointsStay) {
  // A 60-degree right turn at (50,0), with a collinear point before it.
  const Vec2 out(std::cos(-kPi / 3), std::sin(-kPi / 3));
  const FilletedRoute r = fillet_corners({{0, 0}, {20, 0}, {50, 0}, Vec2(50, 0) + 40 * out}, 12.0);
  ASSERT_FALSE(r.too_tight);
  ASSERT_EQ(r.legs.size(), 3u) << "the collinear point makes no arc";
  const RouteLeg& arc = r.legs[1];
  EXPECT_EQ(arc.turn, -1);
  const double t = 12.0 * std::tan(kPi / 6);
  EXPECT_LT((arc.from - Vec2(50 - t, 0)).norm(), 1e-12);
  EXPECT_LT((arc.to - (Vec2(50, 0) + t * out)).norm(), 1e-12);
  EXPECT_NEAR(arc.phi_to - arc.phi_from, -kPi / 3, 1e-12);
  EXPECT_NEAR(arc.core.centre.y(), -12.0, 1e-12);
}

TEST(CornerFillets, CornersTooCloseForTheRadiusAreNamed) {
  // Two right angles 10 m apart need 2 x 20 m of leg at R = 20.
  const FilletedRoute r = fillet_corners({{0, 0}, {100, 0}, {100, 10}, {0, 10}}, 20.0);
  EXPECT_TRUE(r.legs.empty());
  ASSERT_TRUE(r.too_tight);
  EXPECT_EQ(*r.too_tight, 1u);
  // A corner too near the end.
  EXPECT_EQ(fillet_corners({{0, 0}, {5, 0}, {5, 100}}, 20.0).too_tight, 1u);
  // Turning back on itself never fits.
  EXPECT_TRUE(fillet_corners({{0, 0}, {100, 0}, {0, 0}}, 1.0).too_tight.has_value());
  // At R = 5 the same two right angles just fit: the arcs meet.
  const FilletedRoute fits = fillet_corners({{0, 0}, {100, 0}, {100, 10}, {0, 10}}, 5.0);
  ASSERT_FALSE(fits.too_tight);
  ASSERT_EQ(fits.legs.size(), 4u);
  EXPECT_LT((fits.legs[1].to - fits.legs[2].from).norm(), 1e-9);
}

TEST(CornerFillets, CloseCornersTurningOneWayJoinWhereTheirLegsMeet) {
  // Two 45-degree left turns 1.41 m apart need 2 x 4.14 m at R = 10: they
  // become one right angle at (101, 0), where y = 0 meets x = 101.
  const std::vector<Vec2> joined = join_tight_corners({{0, 0}, {100, 0}, {101, 1}, {101, 100}}, 10.0);
  ASSERT_EQ(joined.size(), 3u);
  EXPECT_LT((joined[1] - Vec2(101, 0)).norm(), 1e-12);
  const FilletedRoute r = fillet_corners(joined, 10.0);
  ASSERT_FALSE(r.too_tight);
  EXPECT_NEAR(r.legs[1].length_m, 5 * kPi, 1e-12);
  // Where they fit, nothing changes.
  EXPECT_EQ(join_tight_corners({{0, 0}, {100, 0}, {101, 1}, {101, 100}}, 1.0).size(), 4u);
  // An S-bend cannot be joined: it stays, and its fillets do not fit.
  const std::vector<Vec2> s_bend{{0, 0}, {100, 0}, {101, 1}, {200, 1}};
  EXPECT_EQ(join_tight_corners(s_bend, 10.0), s_bend);
  EXPECT_TRUE(fillet_corners(s_bend, 10.0).too_tight.has_value());
  // Nor a pair beside an end.
  EXPECT_EQ(join_tight_corners({{0, 0}, {1, 0}, {2, 1}, {2, 100}}, 10.0).size(), 4u);
}

TEST(CornerFillets, BadInputThrows) {
  EXPECT_THROW(fillet_corners({{0, 0}, {1, 0}}, 0.0), InputError);
  EXPECT_THROW(fillet_corners({{0, 0}, {1, 0}}, std::nan("")), InputError);
  EXPECT_THROW(fillet_corners({{0, 0}, {0, 0}}, 1.0), InputError);
  EXPECT_THROW(fillet_corners({{0, 0}, {std::nan(""), 0}}, 1.0), InputError);
  EXPECT_THROW(join_tight_corners({{0, 0}, {1, 0}}, -1.0), InputError);
  const FilletedRoute line = fillet_corners({{0, 0}, {3, 4}}, 1.0);
  ASSERT_EQ(line.legs.size(), 1u);
  EXPECT_DOUBLE_EQ(line.legs[0].length_m, 5.0);
}

}  // namespace
}  // namespace deepguide
