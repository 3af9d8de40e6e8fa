// A planned route sailed by the vehicle: a straight route, a dog-leg round a
// rock that is never hit, a hairpin (a leg doubling back, as quadtree routes
// do) that is sailed to the end instead of circled, and routes that do not
// join start and target refused.
#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"
#include "deepguide/simulation/route_following.hpp"

using namespace deepguide;

namespace {
Scenario open_water(const Vec2& target) {
  Scenario sc;
  sc.name = sc.source = "route test";
  sc.start = Vec2(0.0, 0.0);
  sc.target = target;
  sc.sonar.range_m = 0.0;
  return sc;
}
}  // namespace

TEST(RouteFollowing, StraightRouteIsSailedStraight) {
  const Scenario sc = open_water({400.0, 0.0});
  const SimulationResult r = follow_route(sc, Route{{sc.start, sc.target}});
  EXPECT_EQ(r.end, SimulationEnd::reached);
  EXPECT_NEAR(r.stats.path_length_m, 395.0, 0.5);  // stops at the 5 m arrival radius
  EXPECT_LT(r.stats.max_abs_rate_ref, 1e-9);
  for (const TrajectorySample& x : r.trajectory) EXPECT_LT(std::abs(x.position.y()), 1e-9);
}

TEST(RouteFollowing, DogLegRoundARockStaysClear) {
  Scenario sc = open_water({400.0, 0.0});
  EllipticCylinder rock;
  rock.id = "rock";
  rock.footprint = Ellipse{Vec2(200.0, 0.0), 20.0, 20.0, 0.0};
  sc.obstacles.push_back(rock);
  // Round the rock's 10 m zone by two corners 45 m off the line.
  const Route route{{sc.start, {150.0, 45.0}, {250.0, 45.0}, sc.target}};
  const SimulationResult r = follow_route(sc, route);
  EXPECT_EQ(r.end, SimulationEnd::reached);
  EXPECT_FALSE(r.stats.collided);
  EXPECT_GT(r.stats.min_clearance_m, 15.0);  // the corners are cut by at most a few metres
  EXPECT_LT(r.stats.path_length_m, route.length());
  EXPECT_GT(r.stats.max_abs_rate_ref, 0.0);
}

TEST(RouteFollowing, HairpinIsSailedNotCircled) {
  Scenario sc = open_water({-100.0, 2.0});
  sc.start_heading = 0.0;  // east, along the first leg (the default faces the target)
  // Out 150 m and back past the start: the legs (almost) coincide.
  const Route route{{sc.start, {150.0, 0.0}, sc.target}};
  const SimulationResult r = follow_route(sc, route);
  EXPECT_EQ(r.end, SimulationEnd::reached);
  // One U-turn: half a circle of the vehicle's 23.6 m (74 m), ending 47 m off
  // the leg, and the way back onto it at atan(e / 20 m) (about 55 m, 25 m of
  // it along the leg): about +105 m. An orbit would add 150 m each.
  EXPECT_LT(r.stats.path_length_m, route.length() + 130.0);
  EXPECT_GT(r.stats.path_length_m, route.length());
}

TEST(RouteFollowing, RouteMustJoinStartAndTarget) {
  const Scenario sc = open_water({400.0, 0.0});
  deepguide::test::expect_one_line_error([&] { (void)follow_route(sc, Route{{{1.0, 0.0}, sc.target}}); },
                                         "expected a route from the start");
  deepguide::test::expect_one_line_error([&] { (void)follow_route(sc, Route{{sc.start}}); }, "two points");
}
