// Dubins ends (PlanningProblem::start_heading / goal_heading, tangent graph):
// the route leaves the start along the start heading and reaches the goal
// along the goal heading, turning no tighter than the radius. In open water
// it is the shortest Dubins path of the straight-line kind (CSC), checked
// against the textbook's closed forms written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/planner.hpp"
#include "obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;

double mod_two_pi(double a) {
  a = std::fmod(a, 2.0 * kPi);
  return a < 0.0 ? a + 2.0 * kPi : a;
}

Vec2 dir(double a) { return {std::cos(a), std::sin(a)}; }

// The shortest of the four turn-straight-turn Dubins paths (LSL, RSR, LSR,
// RSL) from (p0, a0) to (p1, a1) on radius r. Centres: left p + r (-sin, cos),
// right p + r (sin, -cos). Between a left and a right circle the straight is
// an inner tangent: its direction psi = alpha +- asin(2 r / D).
double shortest_csc(const Vec2& p0, double a0, const Vec2& p1, double a1, double r) {
  const Vec2 l0 = p0 + r * dir(a0 + kPi / 2), r0 = p0 + r * dir(a0 - kPi / 2);
  const Vec2 l1 = p1 + r * dir(a1 + kPi / 2), r1 = p1 + r * dir(a1 - kPi / 2);
  double best = std::numeric_limits<double>::infinity();
  {  // LSL
    const Vec2 v = l1 - l0;
    const double psi = std::atan2(v.y(), v.x());
    best = std::min(best, v.norm() + r * (mod_two_pi(psi - a0) + mod_two_pi(a1 - psi)));
  }
  {  // RSR
    const Vec2 v = r1 - r0;
    const double psi = std::atan2(v.y(), v.x());
    best = std::min(best, v.norm() + r * (mod_two_pi(a0 - psi) + mod_two_pi(psi - a1)));
  }
  for (const int first : {+1, -1}) {  // LSR (+1), RSL (-1)
    const Vec2 v = first > 0 ? Vec2(r1 - l0) : Vec2(l1 - r0);
    const double d = v.norm();
    if (d < 2.0 * r) continue;
    const double psi = std::atan2(v.y(), v.x()) + first * std::asin(2.0 * r / d);
    const double turns =
        first > 0 ? mod_two_pi(psi - a0) + mod_two_pi(psi - a1) : mod_two_pi(a0 - psi) + mod_two_pi(a1 - psi);
    best = std::min(best, std::sqrt(d * d - 4.0 * r * r) + r * turns);
  }
  return best;
}

// The direction of travel where a leg starts (at_end = false) or ends.
Vec2 heading(const RouteLeg& leg, bool at_end) {
  if (leg.kind == RouteLeg::Kind::line) return (leg.to - leg.from).normalized();
  const double phi = at_end ? leg.phi_to : leg.phi_from;
  return leg.turn * Vec2(-std::sin(phi), std::cos(phi));
}

// Open water: one disc far away (a planner needs an environment).
ObstacleSet far_away() {
  ObstacleSet set;
  set.ellipses.push_back(test::disc(5000.0, 5000.0, 5.0, "far"));
  return set;
}

PlannerOptions tangent_options(double margin, double radius) {
  PlannerOptions o;
  o.margin = margin;
  o.tolerance = 0.2;
  o.graph = GraphKind::tangent;
  o.turn_radius_m = radius;
  return o;
}

}  // namespace

TEST(DubinsEnds, OpenWaterRoutesAreTheHandDerivedPaths) {
  Planner planner(far_away(), tangent_options(5.0, 20.0));
  PlanningProblem p{{0.0, 0.0}, {100.0, 0.0}};
  // Facing north, goal 100 m east: a right turn on the circle centred at
  // (20, 0) until the line to the goal is tangent, at normal angle
  // acos(20 / 80): arc 20 (pi - acos(1/4)), line sqrt(80^2 - 20^2).
  p.start_heading = kPi / 2;
  PlanOutcome out = planner.solve(p);
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_NEAR(out.result.exact_length_m, 20.0 * (kPi - std::acos(0.25)) + std::sqrt(6000.0), 1e-6);
  ASSERT_EQ(out.result.legs.size(), 2u);
  EXPECT_EQ(out.result.legs[0].turn, -1);
  EXPECT_NEAR(out.result.legs[0].radius_m, 20.0, 1e-12);
  EXPECT_TRUE(out.legs_check->safe);
  // And arriving heading south: right, 60 m east, right: 20 pi + 60.
  p.goal_heading = -kPi / 2;
  out = planner.solve(p);
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_NEAR(out.result.exact_length_m, 20.0 * kPi + 60.0, 1e-6);
  ASSERT_EQ(out.result.legs.size(), 3u);
  EXPECT_NEAR(out.result.legs[1].length_m, 60.0, 1e-6);
  // Heading straight at the goal, and arriving the same way: the line alone,
  // not once round a circle.
  p.start_heading = 0.0;
  p.goal_heading = 0.0;
  out = planner.solve(p);
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_NEAR(out.result.exact_length_m, 100.0, 1e-6);
  EXPECT_EQ(out.result.legs.size(), 1u);
  // Only the goal's heading, arriving from the west going north: a left
  // quarter turn is the shortest, 80 m straight then 20 pi / 2.
  p.start_heading.reset();
  p.goal_heading = kPi / 2;
  p.start = {0.0, -20.0};
  p.goal = {100.0, 0.0};
  out = planner.solve(p);
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_NEAR(out.result.exact_length_m, 80.0 + 10.0 * kPi, 1e-6);
}

TEST(DubinsEnds, OpenWaterRoutesAreTheShortestTurnStraightTurnPaths) {
  // Start and goal more than 4 R apart, where a Dubins path of three turns is
  // never the shortest (Shkel & Lumelsky 2001), so the tangent graph's
  // route must be the shortest CSC path.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double r = 19.6;
  Planner planner(far_away(), tangent_options(5.0, r));
  for (int k = 0; k < test::cases(200); ++k) {
    PlanningProblem p{{300.0 * u(rng), 300.0 * u(rng)}, {300.0 * u(rng), 300.0 * u(rng)}};
    if ((p.goal - p.start).norm() <= 4.0 * r) continue;
    p.start_heading = kPi * u(rng);
    p.goal_heading = kPi * u(rng);
    const PlanOutcome out = planner.solve(p);
    ASSERT_TRUE(out.result.found) << k << ": " << out.result.message;
    EXPECT_NEAR(out.result.exact_length_m, shortest_csc(p.start, *p.start_heading, p.goal, *p.goal_heading, r), 1e-6)
        << k;
  }
}

TEST(DubinsEnds, RoutesAmongObstaclesKeepTheHeadingsTheRadiusAndTheMargin) {
  std::mt19937 rng(2611);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uni = [&](double lo, double hi) { return lo + (hi - lo) * u01(rng); };
  int found = 0, longer = 0, scenarios = test::cases(300);
  for (int k = 0; k < scenarios; ++k) {
    ObstacleSet set;
    for (int i = 0; i < 2 + k % 6; ++i) {
      const std::string id = "o" + std::to_string(i);
      if (i % 2 == 0) {
        set.ellipses.push_back(test::disc(uni(-120, 120), uni(-120, 120), uni(2, 25), id));
      } else {
        const double x = uni(-120, 120), y = uni(-120, 120);
        set.polygons.push_back(test::box(x, y, x + uni(5, 60), y + uni(5, 60), id));
      }
    }
    const double margin = uni(1, 10), radius = margin + uni(2, 30);
    PlanningProblem p{{-260.0, uni(-150, 150)}, {260.0, uni(-150, 150)}};
    Planner planner(set, tangent_options(margin, radius));
    PlanOutcome plain;
    try {
      plain = planner.solve(p);
    } catch (const NoRouteError&) {
      continue;  // start or goal in a zone
    }
    p.start_heading = uni(-kPi, kPi);
    if (k % 3 != 0) p.goal_heading = uni(-kPi, kPi);
    const PlanOutcome out = planner.solve(p);
    if (!out.result.found) continue;
    ++found;
    ASSERT_TRUE(out.legs_check.has_value());
    EXPECT_TRUE(out.legs_check->safe) << k << ": " << out.legs_check->describe();
    EXPECT_TRUE(out.check.safe) << k << ": " << out.check.describe();
    const auto& legs = out.result.legs;
    EXPECT_LT((legs.front().from - p.start).norm(), 1e-6) << k;
    EXPECT_LT((legs.back().to - p.goal).norm(), 1e-6) << k;
    EXPECT_LT((heading(legs.front(), false) - dir(*p.start_heading)).norm(), 1e-6) << k;
    if (p.goal_heading) {
      EXPECT_LT((heading(legs.back(), true) - dir(*p.goal_heading)).norm(), 1e-6) << k;
    }
    for (std::size_t i = 0; i < legs.size(); ++i) {
      if (i > 0) {
        EXPECT_LT((heading(legs[i - 1], true) - heading(legs[i], false)).norm(), 1e-5) << k << " leg " << i;
      }
      EXPECT_GE(min_turn_radius(legs[i]), radius * (1 - 1e-9)) << k << " leg " << i;
    }
    // Never shorter than the route free to leave and arrive any way, nor,
    // with both headings, than the open water's Dubins path.
    ASSERT_TRUE(plain.result.found);
    EXPECT_GE(out.result.exact_length_m, plain.result.exact_length_m - 1e-6) << k;
    longer += out.result.exact_length_m > plain.result.exact_length_m + 1e-3;
    if (p.goal_heading) {
      EXPECT_GE(out.result.exact_length_m,
                shortest_csc(p.start, *p.start_heading, p.goal, *p.goal_heading, radius) - 1e-6)
          << k;
    }
  }
  std::printf("[ dubins ends ] %d scenarios: %d routes, %d longer than without headings\n", scenarios, found, longer);
  EXPECT_GT(found, scenarios / 2);
  EXPECT_GT(longer, found / 2);
}

TEST(DubinsEnds, AHeadingNeedsTheTangentGraphAndARadius) {
  PlanningProblem p{{0.0, 0.0}, {100.0, 0.0}};
  p.start_heading = 0.0;
  PlannerOptions visibility = tangent_options(5.0, 20.0);
  visibility.graph = GraphKind::visibility;
  EXPECT_THROW(Planner(far_away(), visibility).solve(p), InputError);
  EXPECT_THROW(Planner(far_away(), tangent_options(5.0, 0.0)).solve(p), InputError);
  p.start_heading = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Planner(far_away(), tangent_options(5.0, 20.0)).solve(p), InputError);
}
