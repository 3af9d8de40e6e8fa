// Quadtree / octree decomposition (planning/cell_tree.hpp) and the quadtree
// graph (planning/graphs/quadtree/quadtree_graph.hpp): conservative cells, neighbours against
// brute force in 2-D and 3-D, routes that pass the independent checker and
// are never shorter than the visibility graph's, smoothing, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/cell_tree.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/single_query.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

using deepguide::test::box;

ObstacleSet random_ellipses(std::mt19937& rng, int count, double area) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ObstacleSet set;
  for (int i = 0; i < count; ++i) {
    EllipticCylinder c;
    c.id = "e" + std::to_string(i);
    const double a = 10.0 + 50.0 * u(rng);
    c.footprint = Ellipse{{area * u(rng), area * u(rng)}, a, a * (0.3 + 0.7 * u(rng)), M_PI * u(rng)};
    set.ellipses.push_back(c);
  }
  return set;
}

// Brute force: leaves whose closed boxes touch; a face when they share a (D-1)-dimensional piece.
template <int D>
std::set<std::pair<std::size_t, bool>> touching(const CellTree<D>& tree, std::size_t i) {
  std::set<std::pair<std::size_t, bool>> out;
  const auto a = tree.box(i);
  const double eps = 1e-9 * tree.root_size().maxCoeff();
  for (std::size_t j = 0; j < tree.leaves().size(); ++j) {
    if (j == i) continue;
    const auto b = tree.box(j);
    bool meet = true;
    int flat = 0;  // axes along which they only touch
    for (int k = 0; k < D; ++k) {
      const double lo = std::max(a.min[k], b.min[k]), hi = std::min(a.max[k], b.max[k]);
      if (hi < lo - eps)
        meet = false;
      else if (hi - lo <= eps)
        ++flat;
    }
    if (meet) out.emplace(j, flat == 1);
  }
  return out;
}

template <int D>
void expect_neighbours_match_brute_force(const CellTree<D>& tree) {
  ASSERT_GT(tree.leaves().size(), 20u);
  for (std::size_t i = 0; i < tree.leaves().size(); ++i) {
    const auto found = tree.neighbours(i);
    const std::set<std::pair<std::size_t, bool>> got(found.begin(), found.end());
    ASSERT_EQ(got.size(), found.size()) << "duplicates for leaf " << i;
    ASSERT_EQ(got, touching(tree, i)) << "leaf " << i;
  }
}

}  // namespace

TEST(CellTree, NeighboursAcrossLevelsMatchBruteForceIn2D) {
  // A disc of radius 30 in a 128 m square, split down to 4 m cells.
  const CellTree<2> tree(Eigen::Vector2d(0, 0), 128.0, 5, [](const CellTree<2>::Box& b) {
    const double d = (b.centre() - Eigen::Vector2d(70, 50)).norm() - 30.0, r = 0.5 * (b.max - b.min).norm();
    return d - r >= 0 ? CellState::free : d + r < 0 ? CellState::occupied : CellState::mixed;
  });
  expect_neighbours_match_brute_force(tree);
  // Every point is in exactly one leaf.
  for (double x = 0.5; x < 128; x += 3.7) {
    for (double y = 0.5; y < 128; y += 2.9) {
      const auto leaf = tree.locate({x, y});
      ASSERT_TRUE(leaf);
      const auto b = tree.box(*leaf);
      EXPECT_TRUE(x >= b.min.x() && x < b.max.x() && y >= b.min.y() && y < b.max.y());
    }
  }
  EXPECT_FALSE(tree.locate({-1.0, 5.0}));
  EXPECT_FALSE(tree.locate({5.0, 128.0}));
}

TEST(CellTree, NeighboursAcrossLevelsMatchBruteForceIn3D) {
  // The same generic code as an octree: a ball of radius 12 in a 32 m cube, 2 m cells.
  const CellTree<3> tree(Eigen::Vector3d(0, 0, 0), 32.0, 4, [](const CellTree<3>::Box& b) {
    const double d = (b.centre() - Eigen::Vector3d(17, 14, 15)).norm() - 12.0, r = 0.5 * (b.max - b.min).norm();
    return d - r >= 0 ? CellState::free : d + r < 0 ? CellState::occupied : CellState::mixed;
  });
  expect_neighbours_match_brute_force(tree);
}

TEST(Quadtree, FreeCellsAreFreeAndOccupiedCellsAreInsideZones) {
  std::mt19937 rng(55);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const ObstacleSet set = random_ellipses(rng, 15, 800.0);
  const ObstacleField field(set, 5.0);
  QuadtreeOptions q;
  q.min_cell_m = 2.0;
  q.area_min = {-50.0, -50.0};
  q.area_max = {850.0, 850.0};
  const QuadtreeGraph graph(field, q);
  std::size_t free = 0, occupied = 0;
  for (const auto& leaf : graph.tree().leaves()) {
    const auto cell = graph.tree().box(leaf);
    const Vec2 lo = cell.min, hi = cell.max;
    const bool minimal = (hi - lo).x() <= q.min_cell_m + 1e-9;
    // Out of the area (the root square reaches past its far sides) is occupied by rule, not by a zone.
    const bool outside = (lo.array() >= q.area_max.array()).any();
    if (outside) {
      EXPECT_EQ(leaf.state, CellState::occupied);
      continue;
    }
    for (int k = 0; k < 6; ++k) {
      // Corners and random points: free cells hold only free points; occupied
      // cells above the minimum size only points inside a zone.
      const Vec2 p = k < 4 ? Vec2(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y())
                           : Vec2(lo.x() + u(rng) * (hi - lo).x(), lo.y() + u(rng) * (hi - lo).y());
      if (leaf.state == CellState::free) {
        ASSERT_TRUE(field.is_free(p)) << "free cell " << lo.transpose() << " .. " << hi.transpose();
      } else if (!minimal) {
        ASSERT_LT(field.clearance(p), field.margin()) << "occupied cell " << lo.transpose();
      }
    }
    (leaf.state == CellState::free ? free : occupied)++;
  }
  EXPECT_GT(free, 100u);
  EXPECT_GT(occupied, 100u);
  EXPECT_EQ(graph.vertex_count(), free);
}

TEST(Quadtree, RoutesPassTheCheckerAndAreNeverShorterThanTheVisibilityGraphs) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int planned = 0;
  for (int scenario = 0; scenario < 40; ++scenario) {
    const ObstacleSet set = random_ellipses(rng, 10, 1000.0);
    const PlanningProblem problem{{-40.0, 1000.0 * u(rng)}, {1040.0, 1000.0 * u(rng)}};
    PlannerOptions visibility;
    const SingleQueryPlan best = plan_single_query(set, problem, visibility);
    if (!best.outcome.result.found) continue;
    PlannerOptions quad;
    quad.graph = GraphKind::quadtree;
    quad.quadtree.min_cell_m = 4.0;
    const SingleQueryPlan raw = plan_single_query(set, problem, quad);
    quad.quadtree.smooth = true;
    const SingleQueryPlan smooth = plan_single_query(set, problem, quad);
    ASSERT_TRUE(raw.outcome.result.found) << "scenario " << scenario;
    ASSERT_TRUE(smooth.outcome.result.found);
    ++planned;
    for (const SingleQueryPlan* p : {&raw, &smooth}) {
      EXPECT_TRUE(p->outcome.check.safe) << "scenario " << scenario << ": " << p->outcome.check.describe();
      // The visibility route is within 0.03 % of the optimum; nothing beats the optimum.
      EXPECT_GE(p->outcome.result.route.length(), best.outcome.result.route.length() * (1.0 - 3e-4));
      EXPECT_NEAR(p->outcome.result.cost, p->outcome.result.route.length(), 1e-6 * p->outcome.result.cost);
    }
    EXPECT_LE(smooth.outcome.result.route.length(), raw.outcome.result.route.length() + 1e-9);
    EXPECT_EQ(smooth.outcome.result.route.points.front(), problem.start);
    EXPECT_EQ(smooth.outcome.result.route.points.back(), problem.goal);
  }
  EXPECT_GE(planned, 35);
}

TEST(Quadtree, AStarAndDijkstraAgreeOnTheCells) {
  std::mt19937 rng(3);
  const ObstacleSet set = random_ellipses(rng, 12, 600.0);
  PlannerOptions o;
  o.graph = GraphKind::quadtree;
  o.quadtree.min_cell_m = 3.0;
  const PlanningProblem problem{{-30.0, 300.0}, {630.0, 280.0}};
  const SingleQueryPlan a = plan_single_query(set, problem, o);
  o.search = SearchAlgorithm::dijkstra;
  const SingleQueryPlan d = plan_single_query(set, problem, o);
  ASSERT_TRUE(a.outcome.result.found);
  EXPECT_NEAR(a.outcome.result.cost, d.outcome.result.cost, 1e-9 * d.outcome.result.cost);
  EXPECT_LT(a.outcome.result.stats.expanded, d.outcome.result.stats.expanded);
}

TEST(Quadtree, BadInputIsRefusedWithAClearError) {
  using deepguide::test::expect_error;
  const auto error_of = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  ObstacleSet set;
  set.polygons.push_back(box(0.0, 0.0, 100.0, 100.0, "block"));
  const ObstacleField field(set, 5.0);
  QuadtreeOptions q;
  q.area_min = {-50.0, -50.0};
  q.area_max = {150.0, 150.0};
  q.min_cell_m = 0.0;
  expect_error(error_of([&] { QuadtreeGraph g(field, q); }), {"`min_cell_m`", "> 0"});
  q.min_cell_m = -2.0;
  expect_error(error_of([&] { QuadtreeGraph g(field, q); }), {"`min_cell_m`", "-2"});
  q.min_cell_m = 1e-9;
  expect_error(error_of([&] { QuadtreeGraph g(field, q); }), {"`min_cell_m`", "levels"});
  // An area wholly inside the block's zone has no free cell.
  q.min_cell_m = 2.0;
  q.area_min = {20.0, 20.0};
  q.area_max = {80.0, 80.0};
  expect_error(error_of([&] { QuadtreeGraph g(field, q); }), {"no free cell"});
  // Start outside the area; start inside a zone (the planner names the obstacle).
  PlannerOptions o;
  o.graph = GraphKind::quadtree;
  o.quadtree.area_min = {-50.0, -50.0};
  o.quadtree.area_max = {150.0, 150.0};
  Planner planner(set, o);
  expect_error(error_of([&] { planner.solve({{-500.0, 0.0}, {120.0, 120.0}}); }), {"the start", "outside"});
  expect_error(error_of([&] { planner.solve({{50.0, 50.0}, {120.0, 120.0}}); }), {"the start", "block"});
  expect_error(error_of([&] {
                 o.grid = waypoint_grid_for({0, 0}, {100, 100}, 10.0);
                 Planner p(set, o);
               }),
               {"`waypoint_grid`", "quadtree"});
}
