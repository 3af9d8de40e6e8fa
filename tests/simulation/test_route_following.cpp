// A planned route sailed by the vehicle: a straight route, a dog-leg round a
// rock that is never hit, a hairpin (a leg doubling back, as quadtree routes
// do) that is sailed to the end instead of circled, and routes that do not
// join start and target refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>

#include "../test_support.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/simulation/path_following.hpp"
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
  deepguide::test::expect_one_line_error(
      [&] {
        (void)follow_route(sc, Route{{{1.0, 0.0}, sc.target}});
      },
      "expected a route from the start");
  deepguide::test::expect_one_line_error([&] { (void)follow_route(sc, Route{{sc.start}}); }, "two points");
}

TEST(PathFollowing, NearestPointsOnLinesAndArcs) {
  RouteLeg line;
  line.from = {0.0, 0.0};
  line.to = {10.0, 0.0};
  line.length_m = 10.0;
  PathPoint q = nearest_on_leg(line, {4.0, 3.0});
  EXPECT_NEAR((q.point - Vec2(4.0, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(q.left_m, 3.0, 1e-12);
  EXPECT_NEAR(q.to_end_m, 6.0, 1e-12);
  EXPECT_FALSE(q.past_end);
  q = nearest_on_leg(line, {12.0, -1.0});
  EXPECT_TRUE(q.past_end);
  EXPECT_NEAR(q.left_m, -1.0, 1e-12);
  EXPECT_NEAR((q.point - Vec2(10.0, 0.0)).norm(), 0.0, 1e-12);

  // A quarter circle of radius 10 round the origin, anticlockwise from east.
  RouteLeg arc;
  arc.kind = RouteLeg::Kind::arc;
  arc.core = Ellipse{{0.0, 0.0}, 0.0, 0.0, 0.0};
  arc.offset_m = 10.0;
  arc.turn = +1;
  arc.phi_from = 0.0;
  arc.phi_to = std::numbers::pi / 2;
  arc.from = {10.0, 0.0};
  arc.to = {0.0, 10.0};
  const double c = std::sqrt(0.5);
  q = nearest_on_leg(arc, {12.0 * c, 12.0 * c});
  EXPECT_NEAR((q.point - Vec2(10.0 * c, 10.0 * c)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((q.tangent - Vec2(-c, c)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(q.curvature, 0.1, 1e-12);
  EXPECT_NEAR(q.left_m, -2.0, 1e-12);  // outside a left turn is right of it
  EXPECT_NEAR(q.to_end_m, 10.0 * std::numbers::pi / 4, 1e-12);
  // The same quarter clockwise: outside is now left.
  std::swap(arc.phi_from, arc.phi_to);
  std::swap(arc.from, arc.to);
  arc.turn = -1;
  q = nearest_on_leg(arc, {12.0 * c, 12.0 * c});
  EXPECT_NEAR(q.left_m, 2.0, 1e-12);
  EXPECT_NEAR(q.curvature, -0.1, 1e-12);
  EXPECT_NEAR((q.tangent - Vec2(c, -c)).norm(), 0.0, 1e-12);
  EXPECT_TRUE(nearest_on_leg(arc, {15.0, -1.0}).past_end);

  // Round the tip of an ellipse's zone (a = 20, b = 5, offset 3): radius b^2/a + 3 there.
  RouteLeg tip = arc;
  tip.core = Ellipse{{0.0, 0.0}, 20.0, 5.0, 0.0};
  tip.offset_m = 3.0;
  tip.turn = +1;
  tip.phi_from = -0.5;
  tip.phi_to = 0.5;
  q = nearest_on_leg(tip, {30.0, 0.0});
  EXPECT_NEAR((q.point - Vec2(23.0, 0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(q.left_m, -7.0, 1e-9);
  EXPECT_NEAR(q.curvature, 1.0 / (25.0 / 20.0 + 3.0), 1e-9);
}

TEST(PathFollowing, ACornerIsTurnedFromItsTangentPointOn) {
  // A right-angle corner at (100, 0), turning left; on a 20 m radius the turn
  // begins R tan(45 deg) = 20 m before it.
  PathFollower f;
  f.legs = {line_leg({0.0, 0.0}, {100.0, 0.0}), line_leg({100.0, 0.0}, {100.0, 100.0})};
  f.lookahead_m = 10.0;
  const Vec2 east(2.0, 0.0);
  PathFollower::Command c = f.steer({79.0, 0.0}, east);
  EXPECT_EQ(f.leg, 0u);  // no corner radius: on the first leg to its end
  EXPECT_NEAR(c.course, 0.0, 1e-12);
  EXPECT_NEAR(c.to_end_m, 21.0, 1e-12);
  f.corner_radius_m = 20.0;
  c = f.steer({79.0, 0.0}, east);
  EXPECT_EQ(f.leg, 0u);  // 21 m out: not yet
  c = f.steer({81.0, 0.0}, east);
  EXPECT_EQ(f.leg, 1u);  // 19 m out: the second leg, 19 m to its right, steered for
  EXPECT_NEAR(c.course, std::numbers::pi / 2 - std::atan(19.0 / 10.0), 1e-12);
  EXPECT_NEAR(c.to_end_m, 100.0, 1e-12);
  // Legs that join without a corner are not led: an arc after a line.
  PathFollower g;
  g.legs = {line_leg({0.0, 0.0}, {100.0, 0.0}), circle_leg({100.0, 20.0}, 20.0, -std::numbers::pi / 2, 1.0)};
  g.corner_radius_m = 20.0;
  g.steer({99.0, 0.0}, east);
  EXPECT_EQ(g.leg, 0u);
}

TEST(RouteFollowing, ArcsWithinTheTurningRadiusAreSailedOnTheRoute) {
  // A route round two rocks in a 0.4 m/s cross-current, planned within the
  // radius the vehicle can follow and with the tracking allowance: the
  // vehicle stays within the allowance of it and keeps the margin.
  for (const Vec2& current : {Vec2(0.0, 0.0), Vec2(0.0, 0.4), Vec2(-0.3, -0.25)}) {
    Scenario sc = open_water({500.0, 0.0});
    sc.current = current;
    for (const auto& [x, y, r] : {std::tuple{150.0, 8.0, 25.0}, std::tuple{320.0, -15.0, 18.0}}) {
      EllipticCylinder rock;
      rock.id = "rock";
      rock.footprint = Ellipse{Vec2(x, y), r, r * 0.6, 0.4};
      sc.obstacles.push_back(rock);
    }
    ObstacleSet set;
    set.ellipses = sc.obstacles;
    PlannerOptions options;
    options.margin = sc.reactive.margin_m + kPathTrackingAllowance_m;
    options.graph = GraphKind::tangent;
    options.turn_radius_m = route_turn_radius(sc.vehicle, sc.reactive.speed_mps, current.norm());
    Planner planner(set, options);
    const PlanOutcome plan = planner.solve({sc.start, sc.target});
    ASSERT_TRUE(plan.result.found);
    int arcs = 0;
    for (const RouteLeg& leg : plan.result.legs) arcs += leg.kind == RouteLeg::Kind::arc;
    ASSERT_GE(arcs, 2);
    const SimulationResult r = follow_route(sc, plan.result.legs);
    EXPECT_EQ(r.end, SimulationEnd::reached);
    EXPECT_GE(r.stats.min_clearance_m, sc.reactive.margin_m);
    double off = 0.0;
    for (const TrajectorySample& x : r.trajectory) {
      double nearest = 1e9;
      for (const RouteLeg& leg : plan.result.legs)
        nearest = std::min(nearest, (nearest_on_leg(leg, x.position).point - x.position).norm());
      // Away from the start, where the vehicle first turns onto the route.
      if ((x.position - sc.start).norm() > 60.0) off = std::max(off, nearest);
    }
    EXPECT_LT(off, kPathTrackingAllowance_m) << "current " << current.transpose();
    std::printf(
        "[ route following ] current (%.2f, %.2f): %d arcs, furthest off the route %.2f m, least clearance %.2f m\n",
        current.x(), current.y(), arcs, off, r.stats.min_clearance_m);
  }
}
