// The navigation mesh (planning/graphs/navmesh): its triangulation of the
// water, Polyanya's routes on hand-derived layouts, and the graph's routes
// against the full visibility graph's on the same zone polygons (the same
// shortest route, to rounding) over random fields, every one checked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <boost/geometry.hpp>

#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/graphs/navmesh/polyanya.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/single_query.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = 3.14159265358979323846;

using test::box;
using test::disc;

BgMultiPolygon square(double x0, double y0, double x1, double y1) { return {box(x0, y0, x1, y1).footprint}; }

EllipticCylinder ellipse(double x, double y, double a, double b, double theta, std::string id) {
  EllipticCylinder c;
  c.id = std::move(id);
  c.footprint = Ellipse{{x, y}, a, b, theta};
  return c;
}

std::string describe(const std::vector<Vec2>& points) {
  std::string text;
  for (const Vec2& p : points) text += "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ") ";
  return text;
}

}  // namespace

TEST(NavMesh, ABoxWithASquareHoleIsItsWaterInAnticlockwiseTrianglesWithSymmetricNeighbours) {
  const NavMesh mesh(square(-10, -10, 10, 10), {-50, -50}, {50, 50});
  // 8 vertices; the annulus between two squares has 8 triangles (Euler: V - E + F = 0 for one hole).
  EXPECT_EQ(mesh.vertices().size(), 8u);
  EXPECT_EQ(mesh.faces().size(), 8u);
  double area = 0.0;
  for (std::size_t id = 0; id < mesh.faces().size(); ++id) {
    const NavMesh::Face& f = mesh.faces()[id];
    const Vec2 &a = mesh.vertices()[f.v[0]], &b = mesh.vertices()[f.v[1]], &c = mesh.vertices()[f.v[2]];
    const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    EXPECT_GT(twice, 0.0) << "face " << id << " is not anticlockwise";
    area += 0.5 * twice;
    for (int k = 0; k < 3; ++k) {
      if (f.next[k] == NavMesh::kNone) continue;
      const NavMesh::Face& n = mesh.faces()[f.next[k]];
      int back = 0;
      for (int j = 0; j < 3; ++j) back += n.next[j] == static_cast<std::int32_t>(id) ? 1 : 0;
      EXPECT_EQ(back, 1) << "face " << id << " edge " << k;
    }
  }
  EXPECT_NEAR(area, 100.0 * 100.0 - 20.0 * 20.0, 1e-9);
  // The hole's corners see 270 degrees of water: a route turns there. The
  // box's see 90: no shortest route turns there.
  for (std::uint32_t v = 0; v < mesh.vertices().size(); ++v)
    EXPECT_EQ(mesh.corner(v), mesh.vertices()[v].cwiseAbs().maxCoeff() == 10.0) << v;
  EXPECT_TRUE(mesh.faces_at({0, 0}).empty());    // in the hole
  EXPECT_TRUE(mesh.faces_at({60, 0}).empty());   // outside the area
  EXPECT_EQ(mesh.faces_at({30, 3}).size(), 1u);  // inside one face
  EXPECT_GE(mesh.faces_at({10, 0}).size(), 1u);  // on the hole's edge
  // Within rounding of the edge, on the hole's side: still on it (a start
  // stepped onto a zone polygon comes out so); a micrometre in: not.
  EXPECT_GE(mesh.faces_at({3, 10 - 1e-12}).size(), 1u);
  EXPECT_TRUE(mesh.faces_at({3, 10 - 1e-6}).empty());
  EXPECT_EQ(mesh.edges().size(), 16u);  // 8 boundary edges and 8 between faces
  EXPECT_THROW(NavMesh(square(-1, -1, 1, 1), {0, 0}, {0, 5}), InputError);
}

TEST(Polyanya, RoundASquareTheRouteTurnsAtItsTwoNearCorners) {
  const NavMesh mesh(square(-10, -10, 10, 10), {-50, -50}, {50, 50});
  // Start and goal level with the square's centre: over its top or under its
  // bottom, 2 sqrt(10^2 + 10^2) + 20 either way.
  const PolyanyaResult r = polyanya(mesh, {-20, 0}, {20, 0});
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.length, 20.0 + 2.0 * std::sqrt(200.0), 1e-12);
  ASSERT_EQ(r.path.size(), 4u);
  EXPECT_NEAR(std::abs(r.path[1].y()), 10.0, 1e-12);
  EXPECT_NEAR(r.path[1].x(), -10.0, 1e-12);
  EXPECT_NEAR(r.path[2].x(), 10.0, 1e-12);
  // A goal in sight: the straight line, whatever faces lie between.
  const PolyanyaResult straight = polyanya(mesh, {-40, -40}, {40, -30});
  ASSERT_TRUE(straight.found);
  EXPECT_EQ(straight.path.size(), 2u);
  EXPECT_NEAR(straight.length, std::hypot(80.0, 10.0), 1e-12);
  // Off-centre: one corner. From (-30, 5) to (30, 12) over the top: round
  // (-10, 10), from where the goal clears (10, 10) (the line is at y 11 there).
  const PolyanyaResult one = polyanya(mesh, {-30, 5}, {30, 12});
  ASSERT_TRUE(one.found);
  EXPECT_NEAR(one.length, std::hypot(20.0, 5.0) + std::hypot(40.0, 2.0), 1e-12);
  ASSERT_EQ(one.path.size(), 3u);
  EXPECT_NEAR((one.path[1] - Vec2(-10, 10)).norm(), 0.0, 1e-12);
  // In the no-go or outside the area: no route.
  EXPECT_FALSE(polyanya(mesh, {0, 0}, {30, 0}).found);
  EXPECT_FALSE(polyanya(mesh, {-30, 0}, {80, 0}).found);
}

TEST(Polyanya, AGoalInsideAClosedRingIsUnreachable) {
  // A ring-shaped no-go (a square with a square hole) round the goal.
  BgPolygon ring = box(-20, -20, 20, 20).footprint;
  ring.inners().resize(1);
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}, {-10, -10}}) {
    ring.inners()[0].push_back(BgPoint(x, y));
  }
  boost::geometry::correct(ring);
  const NavMesh mesh(BgMultiPolygon{ring}, {-50, -50}, {50, 50});
  const PolyanyaResult r = polyanya(mesh, {-40, 0}, {0, 0});
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.stopped, SearchStop::none);
  // Both inside the hole: the straight line.
  EXPECT_TRUE(polyanya(mesh, {-5, -5}, {5, 5}).found);
}

TEST(Polyanya, ABudgetStopsTheSearchAndSaysSo) {
  BgMultiPolygon zones;
  for (int i = 0; i < 6; ++i) {
    for (const BgPolygon& p : square(-50 + 20 * i, -30 + 7 * (i % 3), -42 + 20 * i, 30 + 7 * (i % 3)))
      zones.push_back(p);
  }
  const NavMesh mesh(zones, {-100, -100}, {100, 100});
  SearchBudget budget;
  budget.max_expansions = 3;
  const PolyanyaResult r = polyanya(mesh, {-80, 0}, {80, 0}, budget);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.stopped, SearchStop::budget);
  EXPECT_TRUE(polyanya(mesh, {-80, 0}, {80, 0}).found);
}

// The navmesh route against the full visibility graph's on the same zone
// polygons: equal length to 1e-9 relative, every route checked. Sparse and
// dense fields of ellipses and boxes, fresh seeds.
// DEEPGUIDE_NAVMESH_SEED shifts the seeds: a claim holds only when a fresh seed confirms it.
void expect_navmesh_equals_visibility_full(unsigned seed, int scenarios, int most_obstacles, double spread) {
  if (const char* shift = std::getenv("DEEPGUIDE_NAVMESH_SEED")) seed += static_cast<unsigned>(std::atoi(shift));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-spread, spread), ang(-kPi, kPi), u01(0.0, 1.0);
  std::uniform_int_distribution<int> count(1, most_obstacles);
  int routes = 0, none = 0;
  for (int scenario = 0; scenario < scenarios; ++scenario) {
    ObstacleSet set;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      if (i % 4 == 3) {
        const double x = pos(rng), y = pos(rng);
        set.polygons.push_back(box(x, y, x + 10 + 40 * u01(rng), y + 10 + 40 * u01(rng), "b" + std::to_string(i)));
      } else {
        const double a = 5.0 + 35.0 * u01(rng);
        set.ellipses.push_back(
            ellipse(pos(rng), pos(rng), a, a * (0.2 + 0.8 * u01(rng)), ang(rng), "e" + std::to_string(i)));
      }
    }
    const double margin = 10.0 * u01(rng);
    const Vec2 start(-spread - 70.0, pos(rng)), goal(spread + 70.0, pos(rng));
    PlannerOptions options{margin, 0.5, GraphKind::visibility_full, SearchAlgorithm::astar};
    const PlanOutcome full = Planner(set, options).solve({start, goal});
    options.graph = GraphKind{"navmesh"};
    Planner navmesh(set, options);
    const PlanOutcome mesh = navmesh.solve({start, goal});
    ASSERT_EQ(mesh.result.found, full.result.found)
        << "seed " << seed << " scenario " << scenario << ": " << mesh.result.message;
    if (!full.result.found) {
      ++none;
      continue;
    }
    ++routes;
    ASSERT_TRUE(mesh.check.safe) << "seed " << seed << " scenario " << scenario << ": " << mesh.check.describe();
    const double lf = full.result.route.length(), lm = mesh.result.route.length();
    ASSERT_NEAR(lm, lf, 1e-9 * lf) << "seed " << seed << " scenario " << scenario << "\n"
                                   << describe(full.result.route.points) << "\n"
                                   << describe(mesh.result.route.points);
    // The same in one query over the obstacles that can matter.
    const SingleQueryPlan one = plan_single_query(set, {start, goal}, options);
    ASSERT_TRUE(one.outcome.result.found) << "seed " << seed << " scenario " << scenario;
    ASSERT_TRUE(one.outcome.check.safe) << "seed " << seed << " scenario " << scenario;
    ASSERT_NEAR(one.outcome.result.route.length(), lf, 1e-9 * lf) << "seed " << seed << " scenario " << scenario;
  }
  EXPECT_GT(routes, scenarios / 2);
  std::printf("seed %u: %d routes equal to the full visibility graph's, %d scenarios without a route\n", seed, routes,
              none);
}

TEST(NavMeshGraph, SparseFieldsGiveTheFullVisibilityGraphsShortestRoute) {
  expect_navmesh_equals_visibility_full(20261206, test::cases(500), 6, 180.0);
}

TEST(NavMeshGraph, DenseFieldsGiveTheFullVisibilityGraphsShortestRoute) {
  expect_navmesh_equals_visibility_full(77001, test::cases(300), 24, 200.0);
}

TEST(NavMeshGraph, IsARegisteredGraphThatPricesByLengthOnly) {
  const GraphEntry& e = graph_entry(GraphKind{"navmesh"});
  EXPECT_FALSE(e.can.weighs_cost);
  EXPECT_FALSE(e.can.open_water_grid);
  EXPECT_TRUE(e.can.turn_radius);
  ObstacleSet set;
  set.ellipses.push_back(disc(0, 0, 10, "rock"));
  PlannerOptions o{5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar};
  auto time = std::make_shared<CostModel>();
  time->kind = CostKind::time;
  o.cost = time;
  try {
    Planner refused(set, o);
    ADD_FAILURE() << "a time cost was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the navmesh graph prices by length only"), std::string::npos) << e.what();
  }
  // A start or goal beyond the area it was built over: the area widens.
  Planner planner(set, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar});
  const PlanOutcome far = planner.solve({{-5000, 3}, {4000, -2}});
  ASSERT_TRUE(far.result.found);
  EXPECT_TRUE(far.check.safe);
  // Dijkstra's order (h = 0): the same route, more intervals expanded.
  PlannerOptions dijkstra{5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::dijkstra};
  const PlanOutcome slow = Planner(set, dijkstra).solve({{-5000, 3}, {4000, -2}});
  ASSERT_TRUE(slow.result.found);
  EXPECT_NEAR(slow.result.route.length(), far.result.route.length(), 1e-9 * far.result.route.length());
  EXPECT_GT(slow.result.stats.expanded, far.result.stats.expanded);
  // A start inside a zone: the Planner's one-line refusal, as for every graph.
  EXPECT_THROW(planner.solve({{0, 0}, {100, 0}}), NoRouteError);
}

// The exactness comparison can fail: a mesh that lost one constraint (the
// square's corner at (-10, 10), its two edges replaced by the diagonal) gives
// a route that cuts the corner, shorter than the optimum round the square and
// through its zone.
TEST(NavMesh, AMeshThatLostAConstraintCutsTheCornerTheComparisonWouldCatch) {
  const Vec2 s(-30, 5), g(30, 12);
  const double optimum = std::hypot(20.0, 5.0) + std::hypot(40.0, 2.0);
  const PolyanyaResult whole = polyanya(NavMesh(square(-10, -10, 10, 10), {-50, -50}, {50, 50}), s, g);
  ASSERT_TRUE(whole.found);
  EXPECT_NEAR(whole.length, optimum, 1e-12);
  BgPolygon cut;
  cut.outer() = {to_bg({-10, -10}), to_bg({10, 10}), to_bg({10, -10}), to_bg({-10, -10})};
  boost::geometry::correct(cut);
  const PolyanyaResult lost = polyanya(NavMesh(BgMultiPolygon{cut}, {-50, -50}, {50, 50}), s, g);
  ASSERT_TRUE(lost.found);
  EXPECT_LT(lost.length, optimum - 0.2);  // 60.41 m, through (10, 10)
  ObstacleSet square_obstacle;
  square_obstacle.polygons.push_back(box(-10, -10, 10, 10, "square"));
  EXPECT_FALSE(check_route(lost.path, ObstacleField(square_obstacle, 0.0)).safe);
}

// A start in the band between a zone and its polygon steps onto the polygon's
// boundary, which rounding leaves a hair to either side of the edge; the mesh
// must still hold it. (On US4MD81M 1 in 1000 random starts had no face: the
// box around the point missed an axis-parallel edge by 1e-12 m.)
TEST(NavMeshGraph, StartsInTheBandRoundAZoneStepOntoItsPolygonAndPlan) {
  ObstacleSet set;
  set.polygons.push_back(box(4000, 5000, 4100, 5050, "pier"));
  const double margin = 5.0;
  PlannerOptions options{margin, 0.5, GraphKind::visibility_full, SearchAlgorithm::astar};
  Planner full(set, options);
  options.graph = GraphKind{"navmesh"};
  Planner mesh(set, options);
  int planned = 0;
  for (int i = 1; i < 200; ++i) {
    // Just outside the true zone over the pier's top and along its right side.
    for (const Vec2& s : {Vec2(4000 + 0.5 * i, 5050 + margin + 1e-7), Vec2(4100 + margin + 1e-7, 5000 + 0.25 * i)}) {
      const Vec2 g(3000, 4000);
      const PlanOutcome a = full.solve({s, g}), b = mesh.solve({s, g});
      ASSERT_TRUE(b.result.found) << "from (" << s.x() << ", " << s.y() << "): " << b.result.message;
      ASSERT_TRUE(b.check.safe) << b.check.describe();
      ASSERT_NEAR(b.result.route.length(), a.result.route.length(), 1e-9 * a.result.route.length());
      ++planned;
    }
  }
  EXPECT_EQ(planned, 398);
}
