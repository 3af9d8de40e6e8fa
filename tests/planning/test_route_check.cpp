// Independent route checker (planning/route_check.hpp).
//
// Scenes are built so every clearance is hand-derivable (margin 5 m):
//   safe route (0, 15.5) -> (100, 15.5) -> (100, 100) -> (0, 100), circle 'c1'
//   r = 10 at (50, 0), square 'p1' [120, 140] x [40, 60]. Segment 0 passes the
//   circle at 15.5 - 10 = 5.5 = margin + 0.5, at (50, 15.5); segment 1 is 20 from
//   the square's edge x = 120, segment 2 farther from both. So min 5.5, segment 0.
//   unsafe route (0, 20) -> (100, 20) -> (100, 80) -> (300, 80) -> (300, 200) with
//   circle 'c5' r = 4 at (200, 74.73): segment 2 (y = 80) passes 80 - 74.73 - 4 =
//   1.27 m from it at (200, 80); the other obstacles are >= 10 m from every segment
//   (c1: 10 from segment 0; c2 ellipse a = 20, b = 5 at (150, 40): 30 from segment
//   1 at (130, 40); c3 square [250, 270] x [120, 140]: 30 from segment 3;
//   c4 ellipse a = 10, b = 3 along north at (350, 150): 47 from segment 3).
//   square [0, 10]^2: a horizontal route at y = 15 - e is exactly 5 - e from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/geometry/algorithms/correct.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/world/obstacle_field.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMargin = 5.0;

BgPolygon rectangle(double x0, double y0, double x1, double y1) {
  BgPolygon p;
  for (const auto& [x, y] : {std::pair{x0, y0}, std::pair{x1, y0}, std::pair{x1, y1}, std::pair{x0, y1}}) {
    p.outer().emplace_back(x, y);
  }
  boost::geometry::correct(p);
  return p;
}

void add_ellipse(ObstacleSet& set, const std::string& id, const Ellipse& e) {
  set.ellipses.push_back({id, e, std::nullopt, std::nullopt});
}

void add_polygon(ObstacleSet& set, const std::string& id, const BgPolygon& p) {
  set.polygons.push_back({id, p, std::nullopt, std::nullopt});
}

ObstacleField safe_scene() {
  ObstacleSet set;
  add_ellipse(set, "c1", Ellipse{Vec2(50.0, 0.0), 10.0, 10.0, 0.0});
  add_polygon(set, "p1", rectangle(120.0, 40.0, 140.0, 60.0));
  return ObstacleField(set, kMargin);
}

ObstacleField unsafe_scene() {
  ObstacleSet set;
  add_ellipse(set, "c1", Ellipse{Vec2(50.0, 0.0), 10.0, 10.0, 0.0});
  add_ellipse(set, "c2", Ellipse{Vec2(150.0, 40.0), 20.0, 5.0, 0.0});
  add_ellipse(set, "c4", Ellipse{Vec2(350.0, 150.0), 10.0, 3.0, kPi / 2.0});
  add_ellipse(set, "c5", Ellipse{Vec2(200.0, 74.73), 4.0, 4.0, 0.0});
  add_polygon(set, "c3", rectangle(250.0, 120.0, 270.0, 140.0));
  add_polygon(set, "", rectangle(-500.0, -500.0, -400.0, -400.0));
  return ObstacleField(set, kMargin);
}

const std::vector<Vec2> kUnsafeRoute{{0.0, 20.0}, {100.0, 20.0}, {100.0, 80.0}, {300.0, 80.0}, {300.0, 200.0}};

}  // namespace

TEST(RouteCheck, SafeRoutePassingAtMarginPlusHalf) {
  const ObstacleField field = safe_scene();
  const RouteCheck c = check_route({{0.0, 15.5}, {100.0, 15.5}, {100.0, 100.0}, {0.0, 100.0}}, field);
  EXPECT_TRUE(c.safe);
  EXPECT_NEAR(c.min_clearance_m, 5.5, 1e-9);
  EXPECT_EQ(c.worst_segment, 0u);
  EXPECT_EQ(c.worst_obstacle, "c1");
  EXPECT_NEAR(c.worst_point.x(), 50.0, 1e-5);
  EXPECT_DOUBLE_EQ(c.worst_point.y(), 15.5);
  EXPECT_EQ(c.segments, 3u);
  EXPECT_EQ(c.describe(), "segment 0 passes 5.50 m from obstacle 'c1' at (50.00, 15.50) (margin 5 m)");
}

TEST(RouteCheck, UnsafeRouteNamesSegmentAndObstacle) {
  const ObstacleField field = unsafe_scene();
  const RouteCheck c = check_route(kUnsafeRoute, field);
  EXPECT_FALSE(c.safe);
  EXPECT_NEAR(c.min_clearance_m, 1.27, 1e-9);
  EXPECT_EQ(c.worst_segment, 2u);
  EXPECT_EQ(c.worst_obstacle, "c5");
  EXPECT_NEAR(c.worst_point.x(), 200.0, 1e-5);
  EXPECT_DOUBLE_EQ(c.worst_point.y(), 80.0);
  const std::string line = c.describe();
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_NE(line.find("segment 2 passes 1.27 m from obstacle 'c5'"), std::string::npos) << line;
  EXPECT_NE(line.find("(margin 5 m)"), std::string::npos) << line;

  // Dropping the offending leg leaves c1 at 10 m (segment 0) the nearest.
  const RouteCheck first_two = check_route({kUnsafeRoute[0], kUnsafeRoute[1], kUnsafeRoute[2]}, field);
  EXPECT_TRUE(first_two.safe);
  EXPECT_NEAR(first_two.min_clearance_m, 10.0, 1e-9);
  EXPECT_EQ(first_two.worst_obstacle, "c1");
}

TEST(RouteCheck, RouteEnteringAnObstacle) {
  const ObstacleField field = unsafe_scene();
  // Through the centre of c1 (r = 10): 10 m deep.
  const RouteCheck c = check_route({{100.0, 100.0}, {30.0, 0.0}, {70.0, 0.0}}, field);
  EXPECT_FALSE(c.safe);
  EXPECT_NEAR(c.min_clearance_m, -10.0, 1e-9);
  EXPECT_EQ(c.worst_segment, 1u);
  EXPECT_EQ(c.worst_obstacle, "c1");
  EXPECT_NE(c.describe().find("segment 1 enters obstacle 'c1' (10.00 m deep)"), std::string::npos) << c.describe();
}

TEST(RouteCheck, UnnamedObstacleAndTies) {
  ObstacleSet set;
  add_polygon(set, "", rectangle(0.0, 0.0, 10.0, 10.0));
  const ObstacleField field(set, kMargin);
  // Both legs are exactly 5 m from the top edge: the first one is reported.
  const RouteCheck c = check_route({{-5.0, 15.0}, {5.0, 15.0}, {15.0, 15.0}}, field);
  EXPECT_TRUE(c.safe);
  EXPECT_EQ(c.min_clearance_m, 5.0);
  EXPECT_EQ(c.worst_segment, 0u);
  EXPECT_EQ(c.worst_obstacle, "polygon #0");
}

TEST(RouteCheck, ToleranceAbsorbsRoundingOnly) {
  ObstacleSet set;
  add_polygon(set, "sq", rectangle(0.0, 0.0, 10.0, 10.0));
  const ObstacleField field(set, kMargin);
  const auto route_at = [](double y) { return std::vector<Vec2>{{-20.0, y}, {30.0, y}}; };
  EXPECT_TRUE(check_route(route_at(15.0), field, 0.0).safe);
  EXPECT_TRUE(check_route(route_at(15.0 - 1e-7), field).safe);
  EXPECT_FALSE(check_route(route_at(15.0 - 1e-7), field, 0.0).safe);
  const RouteCheck short_by = check_route(route_at(15.0 - 1e-4), field);
  EXPECT_FALSE(short_by.safe);
  // Printed with enough digits not to read as the margin itself.
  EXPECT_NE(short_by.describe().find("4.9999 m"), std::string::npos) << short_by.describe();
  EXPECT_THROW(check_route(route_at(15.0), field, -1.0), std::invalid_argument);
  EXPECT_THROW(check_route(route_at(15.0), field, std::nan("")), std::invalid_argument);
}

TEST(RouteCheck, SinglePointRoute) {
  const ObstacleField field = safe_scene();
  const RouteCheck inside = check_route({{50.0, 5.0}}, field);
  EXPECT_FALSE(inside.safe);
  EXPECT_EQ(inside.segments, 0u);
  EXPECT_EQ(inside.worst_segment, 0u);
  EXPECT_NEAR(inside.min_clearance_m, -5.0, 1e-12);
  EXPECT_EQ(inside.worst_point, Vec2(50.0, 5.0));
  EXPECT_NE(inside.describe().find("waypoint 0 lies inside obstacle 'c1' (5.00 m deep)"), std::string::npos)
      << inside.describe();
  const RouteCheck outside = check_route({{50.0, 20.0}}, field);
  EXPECT_TRUE(outside.safe);
  EXPECT_NEAR(outside.min_clearance_m, 10.0, 1e-12);
}

TEST(RouteCheck, EmptyObstacleSet) {
  const ObstacleField field(ObstacleSet{}, kMargin);
  const RouteCheck c = check_route({{0.0, 0.0}, {100.0, 0.0}, {100.0, 50.0}}, field);
  EXPECT_TRUE(c.safe);
  EXPECT_EQ(c.min_clearance_m, kInf);
  EXPECT_EQ(c.worst_obstacle, "");
  EXPECT_EQ(c.describe(), "no obstacles (margin 5 m)");
}

TEST(RouteCheck, BadWaypointsAreInputErrors) {
  const ObstacleField field = safe_scene();
  const auto message = [&](const std::vector<Vec2>& route) {
    try {
      check_route(route, field);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  const std::string nan_msg = message({{0.0, 0.0}, {1.0, 1.0}, {std::nan(""), 2.0}});
  EXPECT_NE(nan_msg.find("waypoint 2"), std::string::npos) << nan_msg;
  EXPECT_EQ(nan_msg.find('\n'), std::string::npos);
  const std::string inf_msg = message({{kInf, 0.0}, {1.0, 1.0}});
  EXPECT_NE(inf_msg.find("waypoint 0"), std::string::npos) << inf_msg;
  EXPECT_NE(message({{0.0, 0.0}, {1.0, -kInf}}).find("waypoint 1"), std::string::npos);
  EXPECT_NE(message({}).find("at least one waypoint"), std::string::npos);
}

TEST(RouteCheck, HundredThousandObstacles) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double extent = 20000.0;
  ObstacleSet set;
  for (int i = 0; i < 100000; ++i) {
    const Vec2 c(extent * unit(rng), extent * unit(rng));
    const double a = 2.0 + 18.0 * unit(rng);
    if (i % 2 == 0) {
      add_ellipse(set, "", Ellipse{c, a, a * (0.2 + 0.8 * unit(rng)), kPi * (2.0 * unit(rng) - 1.0)});
    } else {
      add_polygon(set, "", rectangle(c.x() - a, c.y() - 0.5 * a, c.x() + a, c.y() + 0.5 * a));
    }
  }
  const ObstacleField field(std::move(set), kMargin);
  ASSERT_EQ(field.size(), 100000u);
  std::vector<Vec2> route{{500.0, 500.0}};
  for (int k = 1; k <= 20; ++k) route.emplace_back(500.0 + 900.0 * k, k % 2 == 0 ? 500.0 + 900.0 * k : 900.0 * k);
  const RouteCheck c = check_route(route, field);
  EXPECT_EQ(c.segments, 20u);
  ASSERT_TRUE(std::isfinite(c.min_clearance_m));
  EXPECT_EQ(c.safe, c.min_clearance_m >= kMargin - 1e-6);

  // The worst segment against every obstacle, without the R-tree: a disc around
  // each obstacle's centre bounds its distance from below, the rest is exact.
  const Vec2& a = route[c.worst_segment];
  const Vec2& b = route[c.worst_segment + 1];
  const auto segment_point = [&](const Vec2& p) {
    const Vec2 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (a + t * d - p).norm();
  };
  const ObstacleSet& obstacles = field.obstacles();
  double brute = kInf;
  for (std::size_t i = 0; i < field.size(); ++i) {
    double lower;
    if (i < obstacles.ellipses.size()) {
      const Ellipse& e = obstacles.ellipses[i].footprint;
      lower = segment_point(e.centre) - e.a;
    } else {
      const BgBox box =
          boost::geometry::return_envelope<BgBox>(obstacles.polygons[i - obstacles.ellipses.size()].footprint);
      const Vec2 lo = to_eigen(box.min_corner());
      const Vec2 hi = to_eigen(box.max_corner());
      lower = segment_point(0.5 * (lo + hi)) - 0.5 * (hi - lo).norm();
    }
    if (lower <= brute) brute = std::min(brute, field.segment_distance_to(i, a, b).distance);
  }
  EXPECT_EQ(c.min_clearance_m, brute);
}

// ------------------------------------------------------------ lines and arcs

namespace {

// An arc round `core` grown by `offset`, anticlockwise from normal angle phi0 to phi1.
RouteLeg arc_round(const Ellipse& core, double offset, double phi0, double phi1) {
  RouteLeg leg;
  leg.kind = RouteLeg::Kind::arc;
  leg.core = core;
  leg.offset_m = offset;
  leg.phi_from = phi0;
  leg.phi_to = phi1;
  leg.turn = phi1 > phi0 ? 1 : -1;
  leg.obstacle = "rock";
  leg.from = arc_point(leg, phi0);
  leg.to = arc_point(leg, phi1);
  return leg;
}

// The least distance from the arc to `e`, by 200,001 points along it.
double sampled_distance(const RouteLeg& leg, const Ellipse& e) {
  double best = kInf;
  for (int i = 0; i <= 200000; ++i) {
    const double phi = leg.phi_from + (leg.phi_to - leg.phi_from) * i / 200000.0;
    best = std::min(best, signed_distance(e, arc_point(leg, phi)));
  }
  return best;
}

}  // namespace

// An arc on its own obstacle's zone is judged by that obstacle's exact
// clearance along it (the offset) and by the others' chords; a second
// obstacle that comes within the margin of it, or an arc grown by less than
// the margin, is unsafe, by the distance a dense sampling finds.
TEST(RouteCheckLegs, AnArcOnItsOwnZoneIsJudgedAgainstEveryOtherObstacle) {
  const Ellipse rock{{0.0, 0.0}, 30.0, 12.0, 0.4};
  ObstacleSet set;
  add_ellipse(set, "rock", rock);
  const ObstacleField alone(set, kMargin);
  const RouteLeg on_zone = arc_round(rock, kMargin, -0.3, 1.9);
  const RouteCheck safe = check_route_legs({on_zone}, alone);
  EXPECT_TRUE(safe.safe) << safe.describe();
  EXPECT_NEAR(safe.min_clearance_m, kMargin, 1e-9);

  const RouteLeg inside = arc_round(rock, kMargin - 0.5, -0.3, 1.9);
  const RouteCheck shallow = check_route_legs({inside}, alone);
  EXPECT_FALSE(shallow.safe);
  EXPECT_NEAR(shallow.min_clearance_m, kMargin - 0.5, 1e-9);

  // A buoy 3 m off the arc's middle: within the margin.
  const Vec2 mid = arc_point(on_zone, 0.8);
  const Vec2 out(std::cos(0.8), std::sin(0.8));  // the arc's outward normal there
  const Ellipse buoy{mid + 5.0 * out, 2.0, 2.0, 0.0};
  add_ellipse(set, "buoy", buoy);
  const ObstacleField both(set, kMargin);
  const RouteCheck near_buoy = check_route_legs({on_zone}, both);
  EXPECT_FALSE(near_buoy.safe);
  EXPECT_EQ(near_buoy.worst_obstacle, "buoy");
  const double truth = sampled_distance(on_zone, buoy);
  EXPECT_NEAR(truth, 3.0, 1e-3);
  EXPECT_LE(near_buoy.min_clearance_m, truth + 1e-9);
  EXPECT_GE(near_buoy.min_clearance_m, truth - 1e-6);

  // A core a nanometre off the obstacle (a planner's shifted frame, rounded
  // back) is still its own: the arc's clearance is the offset less the shift.
  Ellipse moved = rock;
  moved.centre.x() += 1e-9;
  const RouteCheck shifted = check_route_legs({arc_round(moved, kMargin + 1e-6, -0.3, 1.9)}, alone);
  EXPECT_TRUE(shifted.safe) << shifted.describe();
  EXPECT_NEAR(shifted.min_clearance_m, kMargin + 1e-6 - 1e-9, 1e-12);
  // A millimetre off, it is another ellipse: the chords judge the arc against
  // the obstacle, and find it a millimetre inside the margin where the core
  // moved towards the arc (the normal at phi = 0 points along +x).
  Ellipse far = rock;
  far.centre.x() -= 1e-3;
  const RouteLeg off_core = arc_round(far, kMargin + 1e-6, -0.3, 1.9);
  const RouteCheck apart = check_route_legs({off_core}, alone);
  EXPECT_FALSE(apart.safe);
  const double truth_apart = sampled_distance(off_core, rock);
  EXPECT_LE(apart.min_clearance_m, truth_apart + 1e-9);
  EXPECT_GE(apart.min_clearance_m, truth_apart - 1e-6);
}

TEST(RouteCheckLegs, AnEllipseIsFoundByItsFootprintWithinTheShiftAllowed) {
  ObstacleSet set;
  add_ellipse(set, "a", Ellipse{{100.0, 50.0}, 20.0, 8.0, 0.3});
  add_ellipse(set, "b", Ellipse{{100.0, 50.0}, 20.0, 8.0, 0.4});
  const ObstacleField field(set, kMargin);
  EXPECT_EQ(field.ellipse_index(Ellipse{{100.0, 50.0}, 20.0, 8.0, 0.3}), 0u);
  EXPECT_EQ(field.ellipse_index(Ellipse{{100.0, 50.0}, 20.0, 8.0, 0.4}), 1u);
  const Ellipse nudged{{100.0 + 3e-10, 50.0 - 4e-10}, 20.0, 8.0, 0.4};  // 5e-10 away
  EXPECT_EQ(field.ellipse_index(nudged), ObstacleField::kNone);         // bit for bit by default
  EXPECT_EQ(field.ellipse_index(nudged, 5.001e-10), 1u);                // (the shift is 5e-10 up to rounding of 1e-14)
  EXPECT_EQ(field.ellipse_index(nudged, 4.999e-10), ObstacleField::kNone);
  EXPECT_EQ(field.ellipse_index(Ellipse{{100.0, 50.0}, 20.0, 8.0 + 1e-12, 0.4}, 1.0), ObstacleField::kNone);
}
