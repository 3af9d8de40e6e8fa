// Routes within a turning radius (planning/turn_rounding.hpp, the tangent
// graph with turn_radius): every arc at least R wide, legs that join without
// a corner, the margin kept, straight channels left open.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/turn_rounding.hpp"
#include "obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;

EllipticCylinder ellipse(double x, double y, double a, double b, double theta, std::string id) {
  EllipticCylinder c;
  c.id = std::move(id);
  c.footprint = Ellipse{{x, y}, a, b, theta};
  return c;
}

PolygonObstacle polygon(const std::vector<Vec2>& pts, std::string id) {
  PolygonObstacle p;
  p.id = std::move(id);
  for (const Vec2& q : pts) p.footprint.outer().push_back(to_bg(q));
  p.footprint.outer().push_back(to_bg(pts.front()));
  boost::geometry::correct(p.footprint);
  return p;
}

// A triangle with its tip at `tip` pointing along `dir` (rad), the tip's
// angle `angle` (rad) and sides `length` long.
PolygonObstacle spike(const Vec2& tip, double dir, double angle, double length, std::string id) {
  const Vec2 back1 = tip - length * Vec2(std::cos(dir - angle / 2), std::sin(dir - angle / 2));
  const Vec2 back2 = tip - length * Vec2(std::cos(dir + angle / 2), std::sin(dir + angle / 2));
  return polygon({tip, back1, back2}, std::move(id));
}

// The direction of travel where a leg starts (at_end = false) or ends.
Vec2 heading(const RouteLeg& leg, bool at_end) {
  if (leg.kind == RouteLeg::Kind::line) return (leg.to - leg.from).normalized();
  const double phi = at_end ? leg.phi_to : leg.phi_from;
  return leg.turn * Vec2(-std::sin(phi), std::cos(phi));
}

// Radius of the circle through three points.
double circumradius(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double area2 = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  if (area2 == 0.0) return std::numeric_limits<double>::infinity();
  return (b - a).norm() * (c - b).norm() * (c - a).norm() / (2.0 * area2);
}

}  // namespace

TEST(TurningCircles, HoldTheCornersZone) {
  const double d = 2.0, r = 10.0;
  ObstacleSet square;
  square.polygons.push_back(test::box(0, 0, 40, 40, "sq"));
  const auto circles = turning_circles(square, d, r);
  ASSERT_EQ(circles.size(), 4u);  // the corners, not the closing point twice
  for (const TurningCircle& c : circles) {
    // The nearest corner lies R - d (less the micrometre push) from the centre.
    double nearest = 1e9;
    for (const Vec2& v : {Vec2(0, 0), Vec2(0, 40), Vec2(40, 40), Vec2(40, 0)})
      nearest = std::min(nearest, (c.centre - v).norm());
    EXPECT_NEAR(nearest, r - d - 1e-6, 1e-9);
    EXPECT_EQ(c.obstacle, 0u);
  }
  // A wide zone needs none; nor any zone when R <= d.
  ObstacleSet round;
  round.ellipses.push_back(ellipse(0, 0, 30, 30, 0, "c"));
  EXPECT_TRUE(turning_circles(round, 5.0, 20.0).empty());
  EXPECT_TRUE(turning_circles(square, 10.0, 10.0).empty());
  EXPECT_THROW(turning_circles(square, 2.0, 0.0), InputError);
  EXPECT_THROW(turning_circles(square, 2.0, -1.0), InputError);
  EXPECT_THROW(turning_circles(square, 2.0, std::nan("")), InputError);

  // A thin ellipse: every point of its zone's boundary tighter than R lies
  // inside one of its two circles (the rolling argument), checked densely.
  for (const auto& [a, b, m, rr] : {std::tuple{40.0, 2.0, 1.0, 15.0}, {12.0, 8.0, 1.0, 25.0}, {30.0, 0.5, 0.0, 5.0}}) {
    ObstacleSet thin;
    thin.ellipses.push_back(ellipse(3, -4, a, b, 0.7, "e"));
    const auto tips = turning_circles(thin, m, rr);
    ASSERT_EQ(tips.size(), 2u);
    int tight = 0;
    for (int k = 0; k < 20000; ++k) {
      const double phi = 2.0 * kPi * k / 20000;
      const Vec2 u(std::cos(phi), std::sin(phi));
      const Vec2 p = thin.ellipses[0].footprint.support_point(u) + m * u;
      if (offset_ellipse_radius(thin.ellipses[0].footprint, m, phi) >= rr) continue;
      ++tight;
      double inside = 1e9;
      for (const TurningCircle& c : tips) inside = std::min(inside, (p - c.centre).norm() - rr);
      EXPECT_LT(inside, -1e-7) << "a " << a << " phi " << phi;
    }
    EXPECT_GT(tight, 100);
  }
}

namespace {

struct SuiteCounts {
  int scenarios = 0, found = 0, wider = 0, none = 0, refused = 0, arcs = 0, on_circles = 0, unrounded = 0;
  double longest_ratio = 1.0;  ///< the route's length over the tangent graph's within the same radius
  int near_tangent = 0;        ///< routes at most 1 % longer than that
};

// Random scenarios of `lo`..`hi` obstacles: spikes, thin ellipses, rotated
// boxes and discs; every route `graph` finds is checked leg by leg.
SuiteCounts turn_radius_suite(unsigned seed, int scenarios, int lo, int hi, GraphKind graph) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uni = [&](double lo, double hi) { return lo + (hi - lo) * u01(rng); };
  int found = 0, wider = 0, none = 0, refused = 0, arcs = 0, on_circles = 0, unrounded = 0, near_tangent = 0;
  double longest_ratio = 1.0;
  double least_seen = 1e9, worst_join = 0.0;
  for (int scenario = 0; scenario < scenarios; ++scenario) {
    ObstacleSet set;
    const int n = lo + scenario % (hi - lo + 1);
    for (int i = 0; i < n; ++i) {
      const std::string id = "o" + std::to_string(i);
      const Vec2 at(uni(-120, 120), uni(-120, 120));
      switch ((scenario + i) % 4) {
        case 0:  // far sharper than any turning radius: tips of 4 to 40 degrees
          set.polygons.push_back(spike(at, uni(-kPi, kPi), uni(4, 40) * kPi / 180, uni(20, 80), id));
          break;
        case 1: {
          const double a = uni(8, 45);
          set.ellipses.push_back(ellipse(at.x(), at.y(), a, a * uni(0.03, 0.6), uni(-kPi, kPi), id));
          break;
        }
        case 2: {
          const double w = uni(5, 40), h = uni(5, 40), t = uni(-kPi, kPi);
          std::vector<Vec2> pts;
          for (const Vec2& c : {Vec2(-w, -h), Vec2(w, -h), Vec2(w, h), Vec2(-w, h)}) {
            pts.push_back(at +
                          Vec2(std::cos(t) * c.x() - std::sin(t) * c.y(), std::sin(t) * c.x() + std::cos(t) * c.y()));
          }
          set.polygons.push_back(polygon(pts, id));
          break;
        }
        default: set.ellipses.push_back(test::disc(at.x(), at.y(), uni(2, 15), id));
      }
    }
    const double margin = uni(1, 10);
    const double radius = scenario % 7 == 0 ? uni(40, 70) : margin + uni(2, 30);
    const PlanningProblem problem{{-260.0, uni(-150, 150)}, {260.0, uni(-150, 150)}};
    PlannerOptions options{margin, 0.2, graph, SearchAlgorithm::astar, nullptr, {}, {}, radius};
    options.quadtree.smooth = true;  // the quadtree keeps a radius only with its route smoothed
    options.quadtree.area_min = Vec2(-300, -300);
    options.quadtree.area_max = Vec2(300, 300);
    options.quadtree.min_cell_m = 1.0;
    Planner turning(set, options);
    Planner free_turning(set, {margin, 0.2, GraphKind::tangent, SearchAlgorithm::astar});
    PlanOutcome out, plain, exact;
    try {
      out = turning.solve(problem);
      plain = free_turning.solve(problem);
      if (graph == GraphKind::tangent) {
        exact = out;
      } else {
        Planner tangent(set, {margin, 0.2, GraphKind::tangent, SearchAlgorithm::astar, nullptr, {}, {}, radius});
        exact = tangent.solve(problem);
      }
    } catch (const NoRouteError&) {
      ++refused;  // start or goal in a zone
      continue;
    }
    if (!out.result.found) {
      // The visibility graph's 32-gons block gaps the tangent graph's circles
      // leave open, and a corner beside start or goal may not round.
      const bool too_tight = out.result.message.find("route cannot turn at") != std::string::npos;
      unrounded += too_tight;
      none += !too_tight;
      if (!too_tight) {
        EXPECT_NE(out.result.message.find("turning no tighter than"), std::string::npos) << out.result.message;
      }
      continue;
    }
    if (exact.result.found) {
      longest_ratio = std::max(longest_ratio, out.result.exact_length_m / exact.result.exact_length_m);
      near_tangent += out.result.exact_length_m <= 1.01 * exact.result.exact_length_m;
    }
    ++found;
    EXPECT_TRUE(plain.result.found) << scenario;
    EXPECT_TRUE(out.check.safe) << scenario << ": " << out.check.describe();
    if (!out.legs_check.has_value()) {
      ADD_FAILURE() << scenario << ": no legs";
      continue;
    }
    EXPECT_TRUE(out.legs_check->safe) << scenario << ": " << out.legs_check->describe();
    // Never shorter than the route that may turn on the spot.
    EXPECT_GE(out.result.exact_length_m, plain.result.exact_length_m * (1 - 1e-9)) << scenario;
    if (out.result.exact_length_m > plain.result.exact_length_m + 1e-6) ++wider;
    const auto& legs = out.result.legs;
    EXPECT_LT((legs.front().from - problem.start).norm(), 1e-6);
    EXPECT_LT((legs.back().to - problem.goal).norm(), 1e-6);
    for (std::size_t k = 0; k < legs.size(); ++k) {
      const RouteLeg& leg = legs[k];
      if (k > 0) {
        // No corner where two legs meet: the headings agree.
        const double turn = std::acos(std::clamp(heading(legs[k - 1], true).dot(heading(leg, false)), -1.0, 1.0));
        worst_join = std::max(worst_join, turn);
        EXPECT_LT(turn, 1e-5) << scenario << " leg " << k;
      }
      if (leg.kind != RouteLeg::Kind::arc) continue;
      ++arcs;
      on_circles += leg.core.a == leg.core.b;
      EXPECT_LT((arc_point(leg, leg.phi_from) - leg.from).norm(), 1e-6) << scenario;
      EXPECT_LT((arc_point(leg, leg.phi_to) - leg.to).norm(), 1e-6) << scenario;
      EXPECT_GE(min_turn_radius(leg), radius * (1 - 1e-9)) << scenario << " leg " << k;
      // Independently of the closed form: circles through three close points of the curve.
      const int samples = 40;
      for (int s = 0; s <= samples; ++s) {
        const double phi = leg.phi_from + (leg.phi_to - leg.phi_from) * s / samples;
        const double h = 2e-3;
        const double rho = circumradius(arc_point(leg, phi - h), arc_point(leg, phi), arc_point(leg, phi + h));
        least_seen = std::min(least_seen, rho / radius);
        EXPECT_GE(rho, radius * (1 - 1e-4)) << scenario << " leg " << k << " phi " << phi;
      }
    }
  }
  std::printf(
      "[ turn radius ] %s, seed %u, %d scenarios of %d-%d obstacles: %d routes (%d longer than turning on "
      "the spot; %d within 1 %% of the tangent graph's, the longest %.4f x), %d without a route, %d not rounded, %d "
      "refused "
      "start/goal; %d arcs (%d on circles), least sampled radius %.6f R, worst join %.2g rad\n",
      to_string(graph).c_str(), seed, scenarios, lo, hi, found, wider, near_tangent, longest_ratio, none, unrounded,
      refused, arcs, on_circles, least_seen, worst_join);
  return {scenarios, found, wider, none, refused, arcs, on_circles, unrounded, longest_ratio, near_tangent};
}

}  // namespace

TEST(TurnRadius, RandomScenariosTurnNoTighterThanTheRadius) {
  const SuiteCounts sparse = turn_radius_suite(2311, test::cases(500), 2, 6, GraphKind::tangent);
  EXPECT_GT(sparse.found, sparse.scenarios / 2);
  EXPECT_GT(sparse.wider, sparse.scenarios / 10);  // the radius matters in these scenarios
  EXPECT_GT(sparse.on_circles, sparse.scenarios / 10);
  // A fresh seed and a denser field, where gaps close and routes wind.
  const SuiteCounts dense = turn_radius_suite(90210, test::cases(200), 8, 14, GraphKind::tangent);
  EXPECT_GT(dense.found, dense.scenarios / 2);
  EXPECT_GT(dense.wider, dense.found / 2);
}

TEST(TurnRadius, VisibilityRoutesRoundTheirCornersWithinTheRadius) {
  // The same suites through the visibility graph: zones joined with 32-gons
  // round the turning circles, every corner filleted on R.
  const SuiteCounts sparse = turn_radius_suite(2311, test::cases(500), 2, 6, GraphKind::visibility);
  EXPECT_GT(sparse.found, sparse.scenarios / 2);
  EXPECT_GT(sparse.wider, sparse.scenarios / 10);
  EXPECT_EQ(sparse.on_circles, sparse.arcs);
  // What the blocking 32-gons cost: most routes are within 1 % of the
  // tangent graph's; with radii of 40-70 m round 2-10 m margins some detour.
  EXPECT_GT(sparse.near_tangent, sparse.found * 3 / 4);
  EXPECT_LT(sparse.longest_ratio, 1.4);
  const SuiteCounts dense = turn_radius_suite(90210, test::cases(200), 8, 14, GraphKind::visibility_full);
  EXPECT_GT(dense.found, dense.scenarios / 2);
}

TEST(TurnRadius, SmoothedQuadtreeRoutesRoundTheirCornersWithinTheRadius) {
  // Cells kept out of the turning circles, the route pulled taut and its
  // corners rounded: fewer routes than the exact graphs find, every one checked.
  const SuiteCounts sparse = turn_radius_suite(2311, test::cases(300), 2, 6, GraphKind::quadtree);
  EXPECT_GT(sparse.found, sparse.scenarios * 3 / 4);
  EXPECT_EQ(sparse.on_circles, sparse.arcs);
  const SuiteCounts dense = turn_radius_suite(90210, test::cases(100), 8, 14, GraphKind::quadtree);
  EXPECT_GT(dense.found, dense.scenarios / 2);
}

TEST(TurnRadius, AStraightChannelStaysOpen) {
  // A 25 m gap between two long walls, margin 10: 5 m of water a straight
  // route crosses without turning, though the corners' circles bulge into it.
  ObstacleSet set;
  set.polygons.push_back(test::box(0, 12.5, 40, 500, "north"));
  set.polygons.push_back(test::box(0, -500, 40, -12.5, "south"));
  Planner planner(set, {10.0, 0.2, GraphKind::tangent, SearchAlgorithm::astar, nullptr, {}, {}, 19.6});
  const PlanOutcome out = planner.solve({{-200.0, 0.0}, {240.0, 0.0}});
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_NEAR(out.result.exact_length_m, 440.0, 1e-9);
}

TEST(TurnRadius, NoWayRoundSaysWhichTurnIsTooTight) {
  // A pocket whose only way out is a 2 m gap over the end of a 10 m wall:
  // turning round the wall's end on a 5 m radius fits; on 19.6 m it does not.
  ObstacleSet set;
  set.polygons.push_back(test::box(-5, -200, 5, 0, "wall"));
  set.polygons.push_back(test::box(-110, 12, 100, 40, "roof"));
  set.polygons.push_back(test::box(-110, -220, 100, -200, "floor"));
  set.polygons.push_back(test::box(-110, -220, -100, 40, "back"));
  const PlanningProblem problem{{-50.0, -100.0}, {50.0, -100.0}};
  Planner tight(set, {5.0, 0.2, GraphKind::tangent, SearchAlgorithm::astar});
  ASSERT_TRUE(tight.solve(problem).result.found);
  Planner wide(set, {5.0, 0.2, GraphKind::tangent, SearchAlgorithm::astar, nullptr, {}, {}, 19.6});
  const PlanOutcome out = wide.solve(problem);
  ASSERT_FALSE(out.result.found);
  EXPECT_NE(out.result.message.find("turning no tighter than 19.6 m"), std::string::npos) << out.result.message;
  EXPECT_NE(out.result.message.find("'wall'"), std::string::npos) << out.result.message;
  EXPECT_NE(out.result.message.find("5.0 m radius"), std::string::npos) << out.result.message;
  // The quadtree's cell-to-cell steps cannot be rounded: a radius needs its smoothing.
  EXPECT_THROW(Planner(set, {5.0, 0.2, GraphKind::quadtree, SearchAlgorithm::astar, nullptr, {}, {}, 19.6}),
               InputError);
  EXPECT_THROW(Planner(set, {5.0, 0.2, GraphKind::tangent, SearchAlgorithm::astar, nullptr, {}, {}, -1.0}), InputError);
}
