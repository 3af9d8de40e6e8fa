// The octree graph (planning/graphs/octree/octree_graph.hpp): conservative cells in 3-D,
// routes in depth that pass the 3-D checker (band, sea floor, obstacle tops,
// dive angle), over a low rock and around a tall one, A* = Dijkstra, and bad
// input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graphs/octree/octree_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_check.hpp"
#include "planning/obstacle_builders.hpp"

using namespace deepguide;
using deepguide::test::disc;

namespace {

// A basin 400 m x 400 m: 80 m deep, a ridge rising to 45 m across x = 200.
SeaFloor basin() {
  std::vector<double> d;
  for (int j = 0; j <= 40; ++j) {
    for (int i = 0; i <= 40; ++i) {
      const double x = 10.0 * i;
      d.push_back(80.0 - 35.0 * std::exp(-std::pow((x - 200.0) / 40.0, 2)) + 3.0 * std::sin(0.3 * j));
    }
  }
  return SeaFloor({0.0, 0.0}, 10.0, 41, 41, d);
}

OctreeOptions options_over(double min_cell, double dive_deg) {
  OctreeOptions o;
  o.min_cell_m = min_cell;
  o.max_dive_deg = dive_deg;
  o.area_min = {0.0, 0.0};
  o.area_max = {400.0, 400.0};
  return o;
}

ObstacleSet rocks() {
  ObstacleSet set;
  set.ellipses.push_back(disc(100.0, 200.0, 30.0, "low rock"));
  set.ellipses.back().top_depth_m = 60.0;
  set.ellipses.push_back(disc(300.0, 150.0, 25.0, "tower"));  // the whole column
  set.ellipses.push_back(disc(300.0, 280.0, 20.0, "mound"));
  set.ellipses.back().height_m = 20.0;
  return set;
}

}  // namespace

TEST(Octree, FreeCellsAreFreeAndOccupiedCellsAreBlocked) {
  const ObstacleSet set = rocks();
  const ObstacleField field(set, 5.0);
  const SeaFloor floor = basin();
  const WaterVolume volume(field, &floor, {2.0, 5.0, 90.0});
  const OctreeGraph graph(volume, options_over(2.0, 30.0));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 smallest = graph.min_cell();
  EXPECT_NEAR(smallest.z(), 2.0, 1e-12);
  EXPECT_NEAR(smallest.x(), 2.0 / std::tan(M_PI / 6.0), 1e-9);  // flattened to the dive angle
  std::size_t free = 0, occupied = 0;
  for (const auto& leaf : graph.tree().leaves()) {
    const auto cell = graph.tree().box(leaf);
    const Vec3 lo = cell.min, hi = cell.max;
    if ((lo.head<2>().array() >= 400.0).any()) continue;  // beyond the area: occupied by rule
    const bool minimal = (hi - lo).z() <= smallest.z() + 1e-9;
    for (int k = 0; k < 10; ++k) {
      const Vec3 p = k < 8 ? Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z())
                           : Vec3(lo.x() + u(rng) * (hi - lo).x(), lo.y() + u(rng) * (hi - lo).y(),
                                  lo.z() + u(rng) * (hi - lo).z());
      if (leaf.state == CellState::free) {
        ASSERT_TRUE(volume.is_free(p)) << "free cell " << lo.transpose() << " .. " << hi.transpose() << ": "
                                       << volume.check_point(p).reason;
      } else if (!minimal && lo.z() < 90.0) {
        ASSERT_FALSE(volume.is_free(p)) << "occupied cell " << lo.transpose() << " .. " << hi.transpose();
      }
    }
    (leaf.state == CellState::free ? free : occupied)++;
  }
  EXPECT_GT(free, 1000u);
  EXPECT_GT(occupied, 1000u);
  EXPECT_EQ(graph.vertex_count(), free);
}

TEST(Octree, RoutesPassTheDepthCheckerOverTheRidgeAndAroundTheTower) {
  const ObstacleSet set = rocks();
  const ObstacleField field(set, 5.0);
  const SeaFloor floor = basin();
  const WaterVolume volume(field, &floor, {2.0, 5.0, 90.0});
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double dive : {15.0, 30.0, 60.0}) {
    for (bool smooth : {false, true}) {
      OctreeOptions o = options_over(2.0, dive);
      o.smooth = smooth;
      const OctreeGraph graph(volume, o);
      int planned = 0;
      for (int k = 0; planned < 6 && k < 100; ++k) {
        const Vec3 s(10.0 + 100.0 * u(rng), 20.0 + 360.0 * u(rng), 10.0 + 60.0 * u(rng));
        const Vec3 g(290.0 + 100.0 * u(rng), 20.0 + 360.0 * u(rng), 10.0 + 60.0 * u(rng));
        if (!volume.is_free(s) || !volume.is_free(g)) continue;
        ++planned;
        const PlanResult r = graph.solve(s, g);
        ASSERT_TRUE(r.found) << r.message;
        const DepthRouteCheck check = check_route_in_depth(r.route, volume, dive);
        ASSERT_TRUE(check.safe) << "dive " << dive << " smooth " << smooth << ": " << check.describe();
        EXPECT_LE(check.steepest_deg, dive + 1e-6);
        EXPECT_GE(check.min_floor_gap_m, 2.0 - 1e-9);
        // Never shorter than the straight line; the ridge forces every route over 45 m.
        EXPECT_GE(r.route.length(), (g - s).norm() - 1e-9);
        EXPECT_NEAR(r.cost, r.route.length(), 1e-6 * r.cost);
        double shallowest_at_ridge = 1e9;
        for (std::size_t i = 0; i + 1 < r.route.points.size(); ++i) {
          const Vec2 a = r.route.points[i], b = r.route.points[i + 1];
          if ((a.x() - 200.0) * (b.x() - 200.0) <= 0.0 && a.x() != b.x()) {
            const double t = (200.0 - a.x()) / (b.x() - a.x());
            shallowest_at_ridge =
                std::min(shallowest_at_ridge, r.route.depth_m[i] + t * (r.route.depth_m[i + 1] - r.route.depth_m[i]));
          }
        }
        EXPECT_LE(shallowest_at_ridge, 45.0 + 3.0 - 2.0 + 1e-9);
      }
      EXPECT_EQ(planned, 6);
    }
  }
}

TEST(Octree, PassesOverARockWhoseTopIsDeepEnoughAndAroundOneThatIsNot) {
  // One wide rock between start and goal at 40 m, on a flat floor at 100 m.
  const SeaFloor floor({-500.0, -500.0}, 50.0, 21, 21, std::vector<double>(21 * 21, 100.0));
  const Vec3 s(-200.0, 0.0, 40.0), g(200.0, 0.0, 40.0);
  double over = 0.0, around = 0.0;
  for (bool low : {true, false}) {
    ObstacleSet set;
    set.ellipses.push_back(disc(0.0, 0.0, 120.0, "rock"));
    if (low) set.ellipses.back().top_depth_m = 30.0;  // the vehicle climbs to 28 m over it
    const ObstacleField field(set, 5.0);
    const WaterVolume volume(field, &floor, {2.0, 5.0, 95.0});
    OctreeOptions o;
    o.min_cell_m = 1.0;
    o.max_dive_deg = 20.0;
    o.area_min = {-256.0, -256.0};
    o.area_max = {256.0, 256.0};
    o.smooth = true;
    const OctreeGraph graph(volume, o);
    const PlanResult r = graph.solve(s, g);
    ASSERT_TRUE(r.found) << r.message;
    const DepthRouteCheck check = check_route_in_depth(r.route, volume, 20.0);
    ASSERT_TRUE(check.safe) << check.describe();
    double min_off_axis = 1e9, shallowest = 1e9;
    for (std::size_t i = 0; i < r.route.points.size(); ++i) {
      min_off_axis = std::min(min_off_axis, std::abs(r.route.points[i].y()));
      shallowest = std::min(shallowest, r.route.depth_m[i]);
    }
    if (low) {
      over = r.route.length();
      EXPECT_LE(shallowest, 28.0 + 1e-9);  // it climbed over
      // The shortest way over: straight up to 28 m where the zone (radius 125)
      // begins, across at 28 m, down again: 2 sqrt(75^2 + 12^2) + 250 = 401.9 m
      // (9 deg, within the dive angle).
      const double optimum = 2.0 * std::hypot(75.0, 12.0) + 250.0;
      EXPECT_GE(over, optimum - 1e-6);
      EXPECT_LE(over, 1.05 * optimum);
      // The checker catches a leg steeper than the dive angle and one into the rock's zone.
      Route steep = r.route;
      steep.depth_m[1] = steep.depth_m[0] - 0.5 * (steep.points[1] - steep.points[0]).norm();  // 26.6 deg up
      const DepthRouteCheck bad = check_route_in_depth(steep, volume, 20.0);
      EXPECT_FALSE(bad.safe);
      EXPECT_NE(bad.describe().find("steep"), std::string::npos) << bad.describe();
      Route deep = r.route;
      for (double& z : deep.depth_m) z = 40.0;
      const DepthRouteCheck into = check_route_in_depth(deep, volume, 20.0);
      EXPECT_FALSE(into.safe);
      EXPECT_NE(into.describe().find("'rock'"), std::string::npos) << into.describe();
    } else {
      around = r.route.length();
      // Around the zone of radius 125: the 2-D optimum (tangent graph, 481.0 m) bounds it below.
      PlannerOptions po;
      po.margin = 5.0;
      po.graph = GraphKind::tangent;
      Planner exact(set, po);
      const PlanOutcome best = exact.solve({{-200.0, 0.0}, {200.0, 0.0}});
      ASSERT_TRUE(best.result.found);
      EXPECT_GE(around, best.result.exact_length_m - 1e-6);
      EXPECT_LE(around, 1.1 * best.result.exact_length_m);
    }
  }
  EXPECT_LT(over, around);
}

TEST(Octree, AStarAndDijkstraAgree) {
  const ObstacleSet set = rocks();
  const ObstacleField field(set, 5.0);
  const SeaFloor floor = basin();
  const WaterVolume volume(field, &floor, {2.0, 5.0, 90.0});
  const OctreeGraph graph(volume, options_over(4.0, 30.0));
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0;
  for (int k = 0; k < 200 && compared < 20; ++k) {
    const Vec3 s(400.0 * u(rng), 400.0 * u(rng), 5.0 + 60.0 * u(rng)),
        g(400.0 * u(rng), 400.0 * u(rng), 5.0 + 60.0 * u(rng));
    if (!volume.is_free(s) || !volume.is_free(g)) continue;
    const PlanResult a = graph.solve(s, g, SearchAlgorithm::astar), d = graph.solve(s, g, SearchAlgorithm::dijkstra);
    ASSERT_EQ(a.found, d.found);
    if (!a.found) continue;
    ++compared;
    EXPECT_NEAR(a.cost, d.cost, 1e-9 * d.cost);
    EXPECT_LE(a.stats.expanded, d.stats.expanded);
  }
  EXPECT_EQ(compared, 20);
}

TEST(Octree, PointsOnTheVolumesFarSidesLieInACell) {
  // An extent of exactly 2^k cells: the root must still hold its far faces.
  const ObstacleField field(ObstacleSet{}, 5.0);
  const WaterVolume volume(field, nullptr, {2.0, 2.0, 66.0});
  OctreeOptions o;
  o.min_cell_m = 1.0;
  o.max_dive_deg = 60.0;
  o.area_min = {0.0, 0.0};
  o.area_max = {64.0, 64.0};
  const OctreeGraph graph(volume, o);
  const PlanResult a = graph.solve({64.0, 10.0, 10.0}, {10.0, 64.0, 66.0});
  ASSERT_TRUE(a.found) << a.message;
  EXPECT_TRUE(check_route_in_depth(a.route, volume, 60.0).safe);
}

TEST(Octree, BadInputIsRefusedWithAClearError) {
  const ObstacleSet set = rocks();
  const ObstacleField field(set, 5.0);
  const SeaFloor floor = basin();
  const WaterVolume volume(field, &floor, {2.0, 5.0, 90.0});
  const auto message = [](const auto& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  EXPECT_NE(message([&] { OctreeGraph(volume, options_over(0.0, 30.0)); }).find("`min_cell_m`"), std::string::npos);
  EXPECT_NE(message([&] { OctreeGraph(volume, options_over(-1.0, 30.0)); }).find("`min_cell_m`"), std::string::npos);
  EXPECT_NE(message([&] { OctreeGraph(volume, options_over(2.0, 90.0)); }).find("`max_dive_deg`"), std::string::npos);
  EXPECT_NE(message([&] { OctreeGraph(volume, options_over(2.0, 0.0)); }).find("`max_dive_deg`"), std::string::npos);
  // No free cell: a floor everywhere shallower than the band's top plus the clearance.
  const SeaFloor shoal({0.0, 0.0}, 100.0, 5, 5, std::vector<double>(25, 6.0));
  const WaterVolume dry(field, &shoal, {2.0, 5.0, 90.0});
  EXPECT_NE(message([&] { OctreeGraph(dry, options_over(2.0, 30.0)); }).find("no free cell"), std::string::npos);
  // A band reaching below a rock-filled area still has free water above; a
  // tower covering the whole area leaves none.
  ObstacleSet wall;
  wall.ellipses.push_back(disc(200.0, 200.0, 400.0, "island"));
  const ObstacleField walled(wall, 5.0);
  const WaterVolume none(walled, &floor, {2.0, 5.0, 90.0});
  EXPECT_NE(message([&] { OctreeGraph(none, options_over(4.0, 30.0)); }).find("no free cell"), std::string::npos);
  // Start inside the sea floor, above the band, outside the volume.
  const OctreeGraph graph(volume, options_over(4.0, 30.0));
  const std::string in_floor = message([&] { graph.solve({50.0, 50.0, 85.0}, {350.0, 350.0, 20.0}); });
  EXPECT_NE(in_floor.find("the start"), std::string::npos) << in_floor;
  EXPECT_NE(in_floor.find("sea floor"), std::string::npos) << in_floor;
  EXPECT_NE(message([&] { graph.solve({50.0, 50.0, 20.0}, {350.0, 350.0, 1.0}); }).find("the goal"), std::string::npos);
  EXPECT_NE(message([&] {
              graph.solve({-50.0, 50.0, 20.0}, {350.0, 350.0, 20.0});
            }).find("outside"),
            std::string::npos);
  // The checker needs a dive angle it can use.
  Route r{{{10.0, 10.0}, {20.0, 10.0}}, {20.0, 21.0}};
  EXPECT_THROW(check_route_in_depth(r, volume, std::nan("")), InputError);
  EXPECT_THROW(check_route_in_depth(r, volume, 120.0), InputError);
  // In the tower's zone: no route, not bad input.
  EXPECT_THROW(graph.solve({300.0, 150.0, 20.0}, {50.0, 50.0, 20.0}), NoRouteError);
}
