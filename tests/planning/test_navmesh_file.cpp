// The navigation mesh kept as bytes (nav_mesh_file.hpp) and the Planner
// taking a kept graph (prepared_graphs.hpp): the round trip gives back the
// same mesh and the same routes; a kept graph is taken only for the
// obstacles and options it was built for; damaged bytes are a one-line
// InputError, never a crash or a mesh the search would wander off.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_file.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/prepared_graphs.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

using test::box;
using test::disc;

ObstacleSet field_of_rocks() {
  ObstacleSet set;
  set.polygons.push_back(box(200, -50, 260, 80, "pier"));
  set.polygons.push_back(box(400, 40, 430, 300, "wall"));
  set.ellipses.push_back(disc(100, 10, 25, "rock"));
  set.ellipses.push_back(disc(330, -20, 15, "buoy"));
  return set;
}

PlannerOptions navmesh_options() { return {5.0, 0.5, GraphKind{"navmesh"}, SearchAlgorithm::astar}; }

// Byte offsets of the format's parts for `bytes` (nav_mesh_file.hpp's layout).
struct Layout {
  std::size_t vertices_count, first_vertex, faces_count, first_face;
};
Layout layout_of(const std::vector<std::uint8_t>& bytes, std::size_t nv, std::size_t nf) {
  const std::size_t faces_count = bytes.size() - nf * 24 - 4;
  const std::size_t first_vertex = faces_count - nv * 16;
  return {first_vertex - 4, first_vertex, faces_count, faces_count + 4};
}

template <class T>
void poke(std::vector<std::uint8_t>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

}  // namespace

TEST(NavMeshFile, TheRoundTripGivesBackTheSameMeshAndRoutes) {
  const ObstacleSet set = field_of_rocks();
  Planner built(set, navmesh_options());
  const NavMeshGraph& a = *built.graph().as<NavMeshGraph>();
  const KeptNavMesh back = read_nav_mesh(a.save());
  EXPECT_EQ(back.origin, a.origin());
  EXPECT_TRUE(boost::geometry::equals(back.zones, a.zones()));
  ASSERT_EQ(back.mesh->vertices().size(), a.mesh().vertices().size());
  ASSERT_EQ(back.mesh->faces().size(), a.mesh().faces().size());
  for (std::size_t v = 0; v < a.mesh().vertices().size(); ++v) {
    ASSERT_EQ(back.mesh->vertices()[v], a.mesh().vertices()[v]) << v;
    ASSERT_EQ(back.mesh->corner(static_cast<std::uint32_t>(v)), a.mesh().corner(static_cast<std::uint32_t>(v))) << v;
  }
  for (std::size_t f = 0; f < a.mesh().faces().size(); ++f) {
    ASSERT_EQ(back.mesh->faces()[f].v, a.mesh().faces()[f].v) << f;
    ASSERT_EQ(back.mesh->faces()[f].next, a.mesh().faces()[f].next) << f;
  }
  EXPECT_EQ(back.mesh->area_min(), a.mesh().area_min());
  EXPECT_EQ(back.mesh->area_max(), a.mesh().area_max());

  // A Planner given the record reads it (stats.prepared) and plans the same
  // routes, point for point, as the one that built its mesh.
  PlannerOptions o = navmesh_options();
  o.prepared =
      std::make_shared<const std::vector<PreparedGraphRecord>>(std::vector<PreparedGraphRecord>{built.save_graph()});
  Planner loaded(set, o);
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<double> x(-100, 600), y(-150, 400);
  int compared = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec2 s(x(rng), y(rng)), g(x(rng), y(rng));
    if (!built.field().is_free(s) || !built.field().is_free(g)) continue;
    const PlanOutcome p = built.solve({s, g}), q = loaded.solve({s, g});
    ASSERT_TRUE(q.result.stats.prepared);
    ASSERT_FALSE(p.result.stats.prepared);
    ASSERT_EQ(p.result.found, q.result.found);
    ASSERT_EQ(p.result.route.points, q.result.route.points);
    ASSERT_TRUE(q.check.safe) << q.check.describe();
    ++compared;
  }
  EXPECT_GT(compared, 120);
}

// The key names the obstacles and every option the zones are made of: with
// another margin, tolerance or turning radius, or one obstacle more, the
// kept graph is not taken and the graph is built (and routes round the new
// obstacle).
TEST(PreparedGraphs, AKeptGraphIsTakenOnlyForTheObstaclesAndOptionsItWasBuiltFor) {
  const ObstacleSet set = field_of_rocks();
  const auto kept = std::make_shared<const std::vector<PreparedGraphRecord>>(
      std::vector<PreparedGraphRecord>{Planner(set, navmesh_options()).save_graph()});
  const auto taken = [&](const ObstacleSet& s, PlannerOptions o) {
    o.prepared = kept;
    Planner p(s, o);
    const PlanOutcome out = p.solve({{-80, 0}, {560, 60}});
    EXPECT_TRUE(out.result.found && out.check.safe) << out.check.describe();
    return out.result.stats.prepared;
  };
  EXPECT_TRUE(taken(set, navmesh_options()));
  PlannerOptions o = navmesh_options();
  o.margin = 6.0;
  EXPECT_FALSE(taken(set, o));
  o = navmesh_options();
  o.tolerance = 0.25;
  EXPECT_FALSE(taken(set, o));
  o = navmesh_options();
  o.turn_radius_m = 8.0;
  EXPECT_FALSE(taken(set, o));
  ObstacleSet more = set;
  more.ellipses.push_back(disc(500, 40, 20, "new contact"));
  EXPECT_FALSE(taken(more, navmesh_options()));
  ObstacleSet moved = set;
  moved.ellipses[0].footprint.centre.x() += 1e-9;  // bit for bit
  EXPECT_FALSE(taken(moved, navmesh_options()));
  // Another graph kind never takes the navmesh's bytes.
  o = navmesh_options();
  o.graph = GraphKind::visibility;
  EXPECT_FALSE(taken(set, o));
  // A graph that cannot be kept says so, naming those that can.
  test::expect_one_line_error(
      [&] {
        Planner(set, {5.0, 0.5, GraphKind::tangent, SearchAlgorithm::astar}).save_graph();
      },
      "expected navmesh");
  test::expect_one_line_error([&] { graph_preparer({GraphKind::quadtree}, navmesh_options()); },
                              "the quadtree graph cannot be kept");
}

// Damaged bytes: every cut of the data, and each kind of lie a table could
// tell, is refused with one line saying what was expected.
TEST(NavMeshFile, DamagedBytesAreRefusedWithOneLine) {
  const ObstacleSet set = field_of_rocks();
  Planner built(set, navmesh_options());
  const NavMesh& mesh = built.graph().as<NavMeshGraph>()->mesh();
  const std::vector<std::uint8_t> good = built.save_graph().data;
  ASSERT_NO_THROW(read_nav_mesh(good));
  for (std::size_t cut = 0; cut < good.size(); cut += 1 + cut / 7) {
    std::vector<std::uint8_t> shorter(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(cut));
    test::expect_one_line_error([&] { read_nav_mesh(shorter); }, "navigation mesh");
  }
  const Layout at = layout_of(good, mesh.vertices().size(), mesh.faces().size());
  std::uint32_t vertices_read = 0;
  std::memcpy(&vertices_read, good.data() + at.vertices_count, 4);
  ASSERT_EQ(vertices_read, mesh.vertices().size()) << "the layout helper has the format wrong";
  auto damaged = [&](auto change, const char* expected) {
    std::vector<std::uint8_t> b = good;
    change(b);
    test::expect_one_line_error([&] { read_nav_mesh(b); }, expected);
  };
  damaged([](auto& b) { b[0] = 'X'; }, "the mark DGNAVMSH");
  damaged([](auto& b) { poke<std::uint32_t>(b, 8, 2); }, "format version 1, got 2");
  damaged([](auto& b) { b.push_back(0); }, "1 more bytes");
  damaged([&](auto& b) { poke<double>(b, at.first_vertex, std::nan("")); }, "a vertex as a finite number");
  damaged([&](auto& b) { poke<std::uint32_t>(b, at.vertices_count, 0xfffffff0u); }, "that the data left holds");
  damaged([&](auto& b) { poke<std::uint32_t>(b, at.first_face, 99999999u); }, "a vertex below");
  damaged([&](auto& b) { poke<std::int32_t>(b, at.first_face + 12, -7); }, "a neighbour below");
  // A work area wider than the faces cover (they would overlap or leave gaps the same way).
  damaged(
      [&](auto& b) {
        double x = 0.0;
        std::memcpy(&x, b.data() + at.vertices_count - 16, 8);
        poke(b, at.vertices_count - 16, x + 1.0);
      },
      "expected faces covering the water's");
  // Two corners swapped: the first face turns clockwise.
  damaged(
      [&](auto& b) {
        std::uint32_t v0, v1;
        std::memcpy(&v0, b.data() + at.first_face, 4);
        std::memcpy(&v1, b.data() + at.first_face + 4, 4);
        poke(b, at.first_face, v1);
        poke(b, at.first_face + 4, v0);
      },
      "expected an anticlockwise triangle");
  // A face that names a neighbour which does not name it back.
  std::size_t lonely = 0, edge = 0;
  for (; lonely < mesh.faces().size(); ++lonely) {
    for (edge = 0; edge < 3 && mesh.faces()[lonely].next[edge] == NavMesh::kNone; ++edge) {
    }
    if (edge < 3) break;
  }
  const auto other = static_cast<std::int32_t>((mesh.faces()[lonely].next[edge] + 1) % mesh.faces().size());
  damaged([&](auto& b) { poke<std::int32_t>(b, at.first_face + lonely * 24 + 12 + edge * 4, other); },
          "to name it back");
  // Through the Planner, the message names the file the record came from.
  std::vector<std::uint8_t> bad = good;
  bad[0] = 'X';
  PlannerOptions o = navmesh_options();
  PreparedGraphRecord r = built.save_graph();
  r.data = bad;
  r.source = "harbour.gpkg";
  o.prepared = std::make_shared<const std::vector<PreparedGraphRecord>>(std::vector<PreparedGraphRecord>{r});
  test::expect_one_line_error([&] { Planner(set, o); }, "harbour.gpkg: table deepguide_graphs, graph 'navmesh': ");
}
