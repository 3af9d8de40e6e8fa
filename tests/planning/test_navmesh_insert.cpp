// Obstacles inserted into a navigation mesh without a rebuild
// (NavMesh::insert, NavMeshGraph::insert): the mesh stays sound (faces
// anticlockwise, every neighbour naming the face back across the same edge),
// covers the water a mesh made round all the obstacles covers, and gives the
// same shortest routes, every one safe of the inserted obstacles too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <boost/geometry.hpp>

#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/graphs/navmesh/polyanya.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = 3.14159265358979323846;

BgMultiPolygon square(double x0, double y0, double x1, double y1) { return {test::box(x0, y0, x1, y1).footprint}; }

// Checks the mesh's links and orientation; returns the water's area.
double sound_area(const NavMesh& mesh) {
  double area = 0.0;
  const auto& V = mesh.vertices();
  for (std::size_t id = 0; id < mesh.faces().size(); ++id) {
    const NavMesh::Face& f = mesh.faces()[id];
    const Vec2 ab = V[f.v[1]] - V[f.v[0]], ac = V[f.v[2]] - V[f.v[0]];
    const double twice = ab.x() * ac.y() - ab.y() * ac.x();
    EXPECT_GT(twice, 0.0) << "face " << id << " is not anticlockwise";
    area += 0.5 * twice;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = f.next[k];
      if (n == NavMesh::kNone) continue;
      EXPECT_LT(static_cast<std::size_t>(n), mesh.faces().size()) << "face " << id;
      if (static_cast<std::size_t>(n) >= mesh.faces().size()) continue;
      const NavMesh::Face& m = mesh.faces()[n];
      int back = 0;
      for (int j = 0; j < 3; ++j) {
        if (m.next[j] != static_cast<std::int32_t>(id)) continue;
        ++back;
        EXPECT_EQ(m.v[j], f.v[(k + 1) % 3]) << "face " << id << " edge " << k;
        EXPECT_EQ(m.v[(j + 1) % 3], f.v[k]) << "face " << id << " edge " << k;
      }
      EXPECT_EQ(back, 1) << "face " << id << " edge " << k;
    }
  }
  return area;
}

}  // namespace

// Hand-derived: a 20 m x 14 m block inserted across the right side of a 20 m
// square. The water loses the block's 210 m2 outside the square, and the
// shortest way from (-30, 0) to (40, 0) goes over both (74.04 m; under both,
// round (25, -8), is 74.49 m): (-10, 10), (10, 10) and (25, 6).
TEST(NavMeshInsert, ABlockAcrossASquaresSideTakesItsWaterAndTheRouteGoesRoundBoth) {
  NavMesh mesh(square(-10, -10, 10, 10), {-50, -50}, {50, 50});
  const NavMesh::Repair repair = mesh.insert(square(5, -8, 25, 6));
  EXPECT_GT(repair.removed, 0u);
  EXPECT_GT(repair.added, 0u);
  EXPECT_NEAR(sound_area(mesh), 100.0 * 100.0 - 400.0 - 210.0, 1e-9);
  EXPECT_TRUE(mesh.faces_at({20, 0}).empty());
  EXPECT_TRUE(mesh.faces_at({7, 0}).empty());
  EXPECT_EQ(mesh.faces_at({20, 23}).size(), 1u);
  const PolyanyaResult r = polyanya(mesh, {-30, 0}, {40, 0});
  ASSERT_TRUE(r.found);
  const double optimum = std::hypot(20.0, 10.0) + 20.0 + std::hypot(15.0, 4.0) + std::hypot(15.0, 6.0);
  EXPECT_NEAR(r.length, optimum, 1e-12);
  ASSERT_EQ(r.path.size(), 5u);
  EXPECT_NEAR((r.path[3] - Vec2(25, 6)).norm(), 0.0, 1e-12);
  // The block's corner at (25, 6) is a corner of the water now, as the
  // square's (10, 10) still is; where the block's top meets the square's
  // side, (10, 6), the water fills only 90 degrees: no route turns there.
  const auto corner_at = [&](const Vec2& at) {
    for (const NavMesh::Face& f : mesh.faces())
      for (const std::uint32_t v : f.v)
        if ((mesh.vertices()[v] - at).norm() < 1e-12) return std::optional<bool>(mesh.corner(v));
    return std::optional<bool>();  // no face uses it
  };
  EXPECT_EQ(corner_at({25, 6}), std::optional<bool>(true));
  EXPECT_EQ(corner_at({10, 10}), std::optional<bool>(true));
  EXPECT_EQ(corner_at({10, 6}), std::optional<bool>(false));
  EXPECT_EQ(corner_at({10, 0}), std::optional<bool>());  // inside the block now
}

TEST(NavMeshInsert, APolygonInNoWaterChangesNoWaterAndOneBeyondTheAreaStopsAtItsEdge) {
  NavMesh mesh(square(-10, -10, 10, 10), {-50, -50}, {50, 50});
  mesh.insert(square(-5, -5, 5, 5));  // inside the square's no-go
  EXPECT_NEAR(sound_area(mesh), 100.0 * 100.0 - 400.0, 1e-9);
  mesh.insert(square(40, 40, 70, 70));  // 10 m x 10 m of it in the area
  EXPECT_NEAR(sound_area(mesh), 100.0 * 100.0 - 400.0 - 100.0, 1e-9);
  EXPECT_TRUE(mesh.faces_at({45, 45}).empty());
  mesh.insert(square(60, 60, 80, 80));  // wholly outside
  EXPECT_NEAR(sound_area(mesh), 100.0 * 100.0 - 400.0 - 100.0, 1e-9);
  // A ring round the start: the goal can no longer be reached.
  BgPolygon ring;
  ring.outer() = square(-40, -40, -20, -20).front().outer();
  ring.inners().push_back(square(-35, -35, -25, -25).front().outer());
  boost::geometry::correct(ring);
  ASSERT_TRUE(polyanya(mesh, {-30, -30}, {30, 30}).found);
  mesh.insert(BgMultiPolygon{ring});
  EXPECT_NEAR(sound_area(mesh), 100.0 * 100.0 - 400.0 - 100.0 - 300.0, 1e-9);
  EXPECT_FALSE(polyanya(mesh, {-30, -30}, {30, 30}).found);
  EXPECT_TRUE(polyanya(mesh, {-30, -30}, {-26, -34}).found);  // in the ring's hole, water still
}

// Random fields: a graph built round some obstacles, then given more
// (overlapping the old ones and each other; every fourth field gets them
// twice), against a graph built round all of them: the same water, the same
// shortest routes to 1e-9, and every inserted-into route safe of every
// obstacle; the corners kept face by face equal those found afresh, and the
// face index agrees with a scan of every face.
TEST(NavMeshInsert, InsertedObstaclesGiveTheRoutesOfAGraphBuiltRoundThemAll) {
  unsigned seed = 5150;
  if (const char* shift = std::getenv("DEEPGUIDE_NAVMESH_SEED")) seed += static_cast<unsigned>(std::atoi(shift));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-200.0, 200.0), ang(-kPi, kPi), u01(0.0, 1.0);
  int routes = 0, local_repairs = 0;
  for (int scenario = 0; scenario < test::cases(200); ++scenario) {
    const auto obstacles = [&](int n, const std::string& prefix) {
      ObstacleSet set;
      for (int i = 0; i < n; ++i) {
        if (i % 4 == 3) {
          const double x = pos(rng), y = pos(rng);
          set.polygons.push_back(
              test::box(x, y, x + 10 + 40 * u01(rng), y + 10 + 40 * u01(rng), prefix + std::to_string(i)));
        } else {
          EllipticCylinder c;
          c.id = prefix + std::to_string(i);
          const double a = 5.0 + 35.0 * u01(rng);
          c.footprint = Ellipse{{pos(rng), pos(rng)}, a, a * (0.2 + 0.8 * u01(rng)), ang(rng)};
          set.ellipses.push_back(c);
        }
      }
      return set;
    };
    const ObstacleSet old = obstacles(1 + scenario % 12, "o"), found = obstacles(1 + scenario % 3, "d");
    ObstacleSet all = old;
    all.ellipses.insert(all.ellipses.end(), found.ellipses.begin(), found.ellipses.end());
    all.polygons.insert(all.polygons.end(), found.polygons.begin(), found.polygons.end());
    const double margin = 10.0 * u01(rng);
    PlannerOptions options{margin, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar};
    Planner before(old, options);
    Planner whole(all, options);
    NavMeshGraph& repaired = *before.graph().as<NavMeshGraph>();
    const Vec2 area_before = repaired.mesh().area_min();
    repaired.insert(found);
    local_repairs += repaired.mesh().area_min() == area_before ? 1 : 0;  // else the area widened: a rebuild
    if (scenario % 4 == 0) repaired.insert(found);                       // reported twice: the same water
    // The corners kept face by face are those found afresh from the same
    // faces; the face index finds what a scan of every face finds.
    {
      const NavMesh& m = repaired.mesh();
      const NavMesh fresh(m.vertices(), m.faces(), m.area_min(), m.area_max());
      for (const NavMesh::Face& f : m.faces())
        for (const std::uint32_t v : f.v) ASSERT_EQ(m.corner(v), fresh.corner(v)) << "scenario " << scenario;
      for (int k = 0; k < 20; ++k) {
        const Vec2 p = m.area_min() + Vec2(u01(rng), u01(rng)).cwiseProduct(m.area_max() - m.area_min());
        std::size_t holding = 0;
        for (const NavMesh::Face& f : m.faces()) {
          bool inside = true;
          for (int e = 0; e < 3 && inside; ++e) {
            const Vec2 a = m.vertices()[f.v[e]], b = m.vertices()[f.v[(e + 1) % 3]];
            inside = (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x() > 0.0;
          }
          holding += inside ? 1 : 0;
        }
        ASSERT_EQ(std::min<std::size_t>(m.faces_at(p).size(), 1), holding) << "scenario " << scenario;
      }
    }
    // The water of the same area less all the zones (found ones may reach
    // beyond the area), about the same origin.
    BgMultiPolygon zones;
    for (const BgPolygon& z : merged_zone_polygons(all, {margin, 0.5})) {
      BgPolygon moved;
      boost::geometry::transform(z, moved,
                                 boost::geometry::strategy::transform::translate_transformer<double, 2, 2>(
                                     -repaired.origin().x(), -repaired.origin().y()));
      zones.push_back(std::move(moved));
    }
    const BgBox area(to_bg(repaired.mesh().area_min()), to_bg(repaired.mesh().area_max()));
    BgMultiPolygon zones_in_area;
    boost::geometry::intersection(zones, area, zones_in_area);
    const double water = sound_area(repaired.mesh());
    const double expected = boost::geometry::area(area) - boost::geometry::area(zones_in_area);
    ASSERT_NEAR(water, expected, 1e-6 * water) << "scenario " << scenario;
    const ObstacleField field(all, margin);
    for (int q = 0; q < 10; ++q) {
      const Vec2 s(pos(rng), pos(rng)), g(pos(rng), pos(rng));
      if (!field.is_free(s) || !field.is_free(g)) continue;
      const PlanOutcome expected = whole.solve({s, g});
      const PlanResult got = repaired.solve({s, g}, SearchAlgorithm::astar, nullptr, {});
      ASSERT_EQ(got.found, expected.result.found) << "scenario " << scenario << " query " << q;
      if (!got.found) continue;
      ++routes;
      const double want = expected.result.route.length();
      ASSERT_NEAR(got.route.length(), want, 1e-9 * want) << "scenario " << scenario << " query " << q;
      const RouteCheck check = check_route(got.route.points, field);
      ASSERT_TRUE(check.safe) << "scenario " << scenario << " query " << q << ": " << check.describe();
    }
  }
  EXPECT_GT(routes, test::cases(200) * 3);
  EXPECT_GT(local_repairs, test::cases(200) / 3);
  std::printf(
      "seed %u: %d routes on inserted-into meshes equal to those of meshes built round everything (%d of %d inserts "
      "without a rebuild)\n",
      seed, routes, local_repairs, test::cases(200));
}

TEST(NavMeshInsert, AGraphInsertedIntoIsNotKeptAndAStartInTheNewZonesBandStepsOut) {
  ObstacleSet set;
  set.ellipses.push_back(test::disc(0, 0, 10, "rock"));
  Planner planner(set, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar});
  NavMeshGraph& graph = *planner.graph().as<NavMeshGraph>();
  EXPECT_NO_THROW(graph.save());
  ObstacleSet found;
  found.ellipses.push_back(test::disc(60, 0, 10, "detection"));
  graph.insert(found);
  EXPECT_THROW(graph.save(), std::logic_error);
  // Just outside the new rock's true zone (15 m), inside its polygon's band.
  const Vec2 s(60 + 15.0 + 1e-4, 0.0), g(200, 0);
  const PlanResult r = graph.solve({s, g}, SearchAlgorithm::astar, nullptr, {});
  ASSERT_TRUE(r.found) << r.message;
  EXPECT_EQ(r.route.points.front(), s);
  ObstacleSet all = set;
  all.ellipses.push_back(found.ellipses.front());
  EXPECT_TRUE(check_route(r.route.points, ObstacleField(all, 5.0)).safe);
  // A route from west of both to east of both goes round the new one too.
  const PlanResult round = graph.solve({{-100, 0}, {200, 0}}, SearchAlgorithm::astar, nullptr, {});
  ASSERT_TRUE(round.found);
  const PlanOutcome both =
      Planner(all, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar}).solve({{-100, 0}, {200, 0}});
  ASSERT_TRUE(both.result.found);
  EXPECT_NEAR(round.route.length(), both.result.route.length(), 1e-9 * both.result.route.length());
  EXPECT_TRUE(check_route(round.route.points, ObstacleField(all, 5.0)).safe);
}

TEST(NavMeshInsert, APlannerTakesFoundObstaclesIntoItsMeshAndItsChecker) {
  ObstacleSet set;
  set.ellipses.push_back(test::disc(0, 0, 10, "rock"));
  Planner planner(set, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar});
  const PlanOutcome before = planner.solve({{-100, 2}, {200, 2}});
  ASSERT_TRUE(before.result.found);
  ObstacleSet found;
  found.ellipses.push_back(test::disc(80, 3, 12, "detection"));
  // The old route runs through the new rock: the planner's checker must know it now.
  ObstacleSet all = set;
  all.ellipses.push_back(found.ellipses.front());
  ASSERT_FALSE(check_route(before.result.route.points, ObstacleField(all, 5.0)).safe);
  planner.insert(found);
  EXPECT_EQ(planner.field().size(), 2u);
  EXPECT_FALSE(check_route(before.result.route.points, planner.field()).safe);
  // The same length as a planner built round both, and the checker passes it.
  const PlanOutcome after = planner.solve({{-100, 2}, {200, 2}});
  const PlanOutcome fresh =
      Planner(all, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar}).solve({{-100, 2}, {200, 2}});
  ASSERT_TRUE(after.result.found && fresh.result.found);
  EXPECT_NEAR(after.result.route.length(), fresh.result.route.length(), 1e-9 * fresh.result.route.length());
  EXPECT_GT(after.result.route.length(), before.result.route.length() + 1.0);
  EXPECT_TRUE(after.check.safe) << after.check.describe();
  // A bad obstacle is refused and changes nothing.
  ObstacleSet bad;
  bad.ellipses.push_back(test::disc(150, 0, 5, "bad"));
  bad.ellipses.back().footprint.b = 2 * bad.ellipses.back().footprint.a;
  EXPECT_THROW(planner.insert(bad), InputError);
  EXPECT_EQ(planner.field().size(), 2u);
  EXPECT_NEAR(planner.solve({{-100, 2}, {200, 2}}).result.route.length(), after.result.route.length(), 1e-12);
  // A graph built per query cannot take them, and says which can.
  Planner visibility(set, {5.0, 0.5, GraphKind::visibility, SearchAlgorithm::astar});
  try {
    visibility.insert(found);
    ADD_FAILURE() << "the visibility graph took an obstacle";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("navmesh"), std::string::npos) << e.what();
  }
}

TEST(NavMeshInsert, TheSameRockReportedTwiceOrNearlySoLeavesNoWaterInsideIt) {
  // A sonar reports one rock again and again, a little moved: each report
  // is cut in, and no piece of water may be left inside their union (a
  // sliver between two nearly equal rings), nor any route shorter or less
  // safe than one on a mesh built round them all.
  ObstacleSet set;
  set.ellipses.push_back(test::disc(0, 0, 10, "rock"));
  Planner planner(set, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar});
  ObstacleSet all = set;
  for (const double shift : {0.0, 0.0, 1e-7, 1e-4, 0.3}) {
    ObstacleSet report;
    report.ellipses.push_back(test::disc(80 + shift, 3, 12, "report"));
    planner.insert(report);
    all.ellipses.push_back(report.ellipses.front());
  }
  Planner fresh(all, {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar});
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> x(-60, 160), y(-60, 60);
  const ObstacleField field(all, 5.0);
  int compared = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec2 s(x(rng), y(rng)), g(x(rng), y(rng));
    if (!field.is_free(s) || !field.is_free(g) || (s - g).norm() < 1.0) continue;
    const PlanOutcome a = planner.solve({s, g}), b = fresh.solve({s, g});
    ASSERT_EQ(a.result.found, b.result.found) << k;
    if (!a.result.found) continue;
    EXPECT_TRUE(a.check.safe) << k << ": " << a.check.describe();
    // Where routes turn at a corner two reports' rings make, the inserted
    // mesh has CGAL's crossing of the rings and the fresh one the union's:
    // the same point to rounding (1e-7 m seen), not bit for bit.
    EXPECT_NEAR(a.result.route.length(), b.result.route.length(), 1e-6) << k;
    ++compared;
  }
  EXPECT_GT(compared, 150);
  // The reports' own middle is no water for the mesh.
  EXPECT_THROW(planner.solve({{80, 3}, {150, 50}}), NoRouteError);
}
