// The visibility-graph planner against independent references: a hand-derived
// optimum, a lower bound from polygons inscribed in the zones, the full graph,
// Dijkstra, and the exact route checker.
#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <random>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graphs/visibility/visibility_graph.hpp"
#include "deepguide/planning/graphs/visibility/zone_visibility_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;
namespace bg = boost::geometry;

namespace {

using deepguide::test::box;

constexpr double kPi = 3.14159265358979323846;

EllipticCylinder ellipse(double x, double y, double a, double b, double theta, std::string id = "") {
  EllipticCylinder c;
  c.id = std::move(id);
  c.footprint = Ellipse{{x, y}, a, b, theta};
  return c;
}

// Polygon with its vertices ON the zone boundary (points of the offset curve):
// inside the convex zone, so shortest paths around it are never longer than
// the true optimum around the zone.
BgPolygon inscribed_zone(const Ellipse& e, double d, int n) {
  BgPolygon poly;
  for (int k = n; k >= 0; --k) {  // clockwise
    const double t = 2.0 * kPi * k / n;
    poly.outer().push_back(to_bg(e.point_at(t) + d * e.normal_at(t)));
  }
  return poly;
}

// Single disc R at the origin, start (-150, 0), goal (150, 0):
// L* = 2 sqrt(150^2 - R^2) + R (pi - 2 acos(R / 150)); 302.67 m for R = 20.
double single_disc_optimum(double r) {
  return 2.0 * std::sqrt(150.0 * 150.0 - r * r) + r * (kPi - 2.0 * std::acos(r / 150.0));
}

}  // namespace

TEST(VisibilityPlanner, SingleDiscMatchesTheClosedFormOptimum) {
  EXPECT_NEAR(single_disc_optimum(20.0), 302.67, 0.005);
  for (GraphKind kind : {GraphKind::visibility, GraphKind::visibility_full}) {
    ObstacleSet set;
    set.ellipses.push_back(ellipse(0, 0, 15, 15, 0.3, "disc"));
    Planner planner(set, {5.0, 0.01, kind, SearchAlgorithm::astar});
    const PlanOutcome out = planner.solve({{-150, 0}, {150, 0}});
    ASSERT_TRUE(out.result.found);
    EXPECT_TRUE(out.check.safe) << out.check.describe();
    const double l = out.result.route.length();
    EXPECT_GE(l, single_disc_optimum(20.0));
    EXPECT_LE(l, single_disc_optimum(20.0) * 1.0001) << to_string(kind);
    EXPECT_GE(out.check.min_clearance_m, 5.0 - 1e-9);
    EXPECT_LE(out.check.min_clearance_m, 5.0 + 0.01 + 1e-9);  // hugs the zone within the tolerance
  }
}

TEST(VisibilityPlanner, NoObstaclesGivesTheStraightLine) {
  Planner planner(ObstacleSet{}, {5.0, 0.05, GraphKind::visibility, SearchAlgorithm::astar});
  const PlanOutcome out = planner.solve({{0, 0}, {300, 400}});
  ASSERT_TRUE(out.result.found);
  ASSERT_EQ(out.result.route.points.size(), 2u);
  EXPECT_DOUBLE_EQ(out.result.route.length(), 500.0);
  EXPECT_TRUE(out.check.safe);
}

// 1000 random scenarios (fixed seed): every route passes the checker; the
// reduced graph equals the full graph; A* equals Dijkstra; with disjoint
// zones the route lies within 0.1 % above the inscribed-polygon lower bound.
TEST(VisibilityPlanner, RandomScenariosAgreeWithEveryReference) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> pos(-180.0, 180.0), ang(-kPi, kPi), u01(0.0, 1.0);
  std::uniform_int_distribution<int> count(1, 6);
  int disjoint_cases = 0, merged_cases = 0, no_route = 0;
  double worst_excess = 0.0, worst_exact_gap = 0.0;
  for (int scenario = 0; scenario < test::cases(1000); ++scenario) {
    ObstacleSet set;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      const double a = 5.0 + 35.0 * u01(rng);
      set.ellipses.push_back(
          ellipse(pos(rng), pos(rng), a, a * (0.2 + 0.8 * u01(rng)), ang(rng), "e" + std::to_string(i)));
    }
    if (scenario % 5 == 0) {
      const double x = pos(rng), y = pos(rng);
      set.polygons.push_back(box(x, y, x + 10 + 40 * u01(rng), y + 10 + 40 * u01(rng), "box"));
    }
    const double margin = 10.0 * u01(rng);
    const Vec2 start(-250.0, pos(rng)), goal(250.0, pos(rng));
    const PlannerOptions base{margin, 0.5, GraphKind::visibility, SearchAlgorithm::astar};
    Planner reduced(set, base);
    const PlanOutcome r = reduced.solve({start, goal});
    PlannerOptions full_options = base;
    full_options.graph = GraphKind::visibility_full;
    full_options.search = SearchAlgorithm::dijkstra;
    Planner full(set, full_options);
    const PlanOutcome f = full.solve({start, goal});
    ASSERT_EQ(r.result.found, f.result.found) << "scenario " << scenario;
    if (!r.result.found) {
      ++no_route;
      continue;
    }
    ASSERT_TRUE(r.check.safe) << "scenario " << scenario << ": " << r.check.describe();
    ASSERT_TRUE(f.check.safe) << "scenario " << scenario << ": " << f.check.describe();
    const double lr = r.result.route.length(), lf = f.result.route.length();
    ASSERT_NEAR(lr, lf, 1e-9 * lf) << "scenario " << scenario;
    PlannerOptions dijkstra_options = base;
    dijkstra_options.search = SearchAlgorithm::dijkstra;
    const double ld = Planner(set, dijkstra_options).solve({start, goal}).result.route.length();
    ASSERT_NEAR(lr, ld, 1e-9 * ld) << "scenario " << scenario;
    PlannerOptions tangent_options = base;
    tangent_options.graph = GraphKind::tangent;
    const PlanOutcome t = Planner(set, tangent_options).solve({start, goal});
    ASSERT_TRUE(t.result.found) << "scenario " << scenario;
    ASSERT_TRUE(t.check.safe) << "scenario " << scenario << ": " << t.check.describe();
    // Enclosing polygons only lengthen routes: the exact route is never longer.
    ASSERT_LE(t.result.exact_length_m, lr * (1 + 1e-12)) << "scenario " << scenario;
    // One query over only the obstacles within the ellipse bound: the same optimum.
    // (The tangent graph's exact length; its polyline depends on which
    // tangent points split the arcs, which differs with the obstacles taken.)
    for (const auto& [options, length] : {std::pair{base, lr}, std::pair{tangent_options, t.result.exact_length_m}}) {
      const SingleQueryPlan one = plan_single_query(set, {start, goal}, options);
      ASSERT_TRUE(one.outcome.result.found) << "scenario " << scenario;
      ASSERT_TRUE(one.outcome.check.safe) << "scenario " << scenario << ": " << one.outcome.check.describe();
      const double got =
          options.graph == GraphKind::tangent ? one.outcome.result.exact_length_m : one.outcome.result.route.length();
      ASSERT_NEAR(got, length, 1e-9 * length) << "scenario " << scenario << " " << to_string(options.graph);
    }

    if (bg::num_geometries(reduced.graph().as<ZoneVisibilityGraph>()->zones()) != set.size()) {
      ++merged_cases;
      continue;
    }
    ++disjoint_cases;
    if (!set.polygons.empty()) continue;  // the inscribed bound below is for ellipse zones
    BgMultiPolygon inscribed;
    for (const auto& c : set.ellipses) inscribed.push_back(inscribed_zone(c.footprint, margin, 256));
    VisibilityGraph lower(inscribed, VisibilityVariant::reduced);
    const PlanResult lb = lower.solve({start, goal}, SearchAlgorithm::astar);
    ASSERT_TRUE(lb.found);
    const double excess = lr / lb.route.length() - 1.0;
    const double exact_gap = t.result.exact_length_m / lb.route.length() - 1.0;
    worst_exact_gap = std::max(worst_exact_gap, exact_gap);
    EXPECT_GE(exact_gap, -1e-12) << "scenario " << scenario;
    EXPECT_LE(exact_gap, 1e-4) << "scenario " << scenario;
    worst_excess = std::max(worst_excess, excess);
    EXPECT_GE(excess, -1e-12) << "scenario " << scenario;
    EXPECT_LE(excess, 1e-3) << "scenario " << scenario;
  }
  std::printf(
      "[ planner ] %d disjoint, %d with merged zones, %d without route; worst excess over the lower bound: "
      "polygon graphs %.3g %%, tangent graph %.3g %%\n",
      disjoint_cases, merged_cases, no_route, 100.0 * worst_excess, 100.0 * worst_exact_gap);
  EXPECT_GT(disjoint_cases, test::cases(300));
  EXPECT_GT(merged_cases, test::cases(50));
}
