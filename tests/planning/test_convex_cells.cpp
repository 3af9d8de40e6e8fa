// The navigation mesh's triangles merged into convex cells
// (planning/graphs/navmesh/convex_cells): every cell strictly convex and a
// union of whole triangles, the links between cells symmetric, and the merge
// as far as it goes (no edge left whose removal keeps both of its ends
// convex), on hand-derived layouts and random fields.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "deepguide/planning/graphs/navmesh/convex_cells.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 at(const NavMesh& mesh, const ConvexCells& cells, std::int32_t c, std::uint32_t k) {
  return mesh.vertices()[cells.corner[cells.begin[c] + k % cells.count[c]]];
}

double cell_area(const NavMesh& mesh, const ConvexCells& cells, std::int32_t c) {
  double twice = 0.0;
  for (std::uint32_t k = 0; k < cells.count[c]; ++k) twice += cross(at(mesh, cells, c, k), at(mesh, cells, c, k + 1));
  return 0.5 * twice;
}

// Strictly convex at corner k of cell c when the ring goes from `before`
// through it to `after`.
bool convex(const Vec2& before, const Vec2& p, const Vec2& after) {
  return cross(p - before, after - p) > 1e-9 * (p - before).norm() * (after - p).norm();
}

// Everything a search relies on, and (`maximal`) that the merge went as far
// as it could; returns the number of cells. A repair merges only the cells
// it changed, among themselves, so after one a new cell may still join an
// old one.
std::size_t check_cells(const NavMesh& mesh, bool maximal = true) {
  const ConvexCells& cells = mesh.cells();
  const auto n = static_cast<std::int32_t>(cells.count.size());
  EXPECT_EQ(cells.begin.size(), cells.count.size());
  EXPECT_EQ(cells.across.size(), cells.corner.size());
  EXPECT_EQ(cells.back.size(), cells.corner.size());
  EXPECT_EQ(cells.cell_of.size(), mesh.faces().size());
  std::vector<double> triangles(cells.count.size(), 0.0);
  std::set<std::pair<std::uint32_t, std::uint32_t>> walls;  // the triangles' edges with no water across
  for (std::size_t t = 0; t < mesh.faces().size(); ++t) {
    const NavMesh::Face& f = mesh.faces()[t];
    const Vec2 &a = mesh.vertices()[f.v[0]], &b = mesh.vertices()[f.v[1]], &c = mesh.vertices()[f.v[2]];
    for (int k = 0; k < 3; ++k) {
      if (f.next[k] == NavMesh::kNone) walls.emplace(f.v[k], f.v[(k + 1) % 3]);
    }
    const std::int32_t cell = cells.cell_of[t];
    EXPECT_TRUE(cell >= 0 && cell < n && cells.count[cell] > 0) << "triangle " << t;
    if (cell < 0 || cell >= n) continue;
    triangles[cell] += 0.5 * cross(b - a, c - a);
  }
  std::size_t live = 0, walls_seen = 0;
  for (std::int32_t c = 0; c < n; ++c) {
    const std::uint32_t m = cells.count[c];
    if (m == 0) continue;  // a number a repair freed
    ++live;
    EXPECT_GE(m, 3u);
    // Its triangles fill it: the same area (so, being inside it, all of it).
    EXPECT_NEAR(cell_area(mesh, cells, c), triangles[c], 1e-9 * std::max(1.0, triangles[c])) << "cell " << c;
    for (std::uint32_t k = 0; k < m; ++k) {
      const Vec2 before = at(mesh, cells, c, k + m - 1), p = at(mesh, cells, c, k), after = at(mesh, cells, c, k + 1);
      EXPECT_TRUE(convex(before, p, after)) << "cell " << c << " corner " << k;
      const std::int32_t d = cells.across[cells.begin[c] + k];
      if (d == ConvexCells::kNone) {
        // Only where the triangles have a wall: a lost link would be one too.
        const auto ends = std::make_pair(cells.corner[cells.begin[c] + k], cells.corner[cells.begin[c] + (k + 1) % m]);
        EXPECT_EQ(walls.count(ends), 1u) << "cell " << c << " edge " << k << " is no wall of the water";
        ++walls_seen;
        continue;
      }
      // The cell across has the same edge, the other way round, looking back.
      const std::uint32_t back = cells.back[cells.begin[c] + k];
      EXPECT_EQ(cells.across[cells.begin[d] + back], c) << "cell " << c << " edge " << k;
      EXPECT_EQ(at(mesh, cells, d, back), after);
      EXPECT_EQ(at(mesh, cells, d, back + 1), p);
      // Maximal: joining the two cells would leave a reflex (or straight)
      // corner at one end of the edge. Before the edge's start p, c's ring
      // comes from `before`; after it, d's ring goes on past p.
      const Vec2 d_after_p = at(mesh, cells, d, back + 2);
      const Vec2 d_before_after = at(mesh, cells, d, back + cells.count[d] - 1);
      const Vec2 c_after_after = at(mesh, cells, c, k + 2);
      EXPECT_FALSE(maximal && convex(before, p, d_after_p) && convex(d_before_after, after, c_after_after))
          << "cells " << c << " and " << d << " could be one";
    }
  }
  EXPECT_EQ(walls_seen, walls.size());
  EXPECT_EQ(live, cells.live);
  std::size_t used = 0;
  for (const std::uint32_t m : cells.count) used += m;
  EXPECT_EQ(used + cells.garbage, cells.corner.size());
  EXPECT_LE(cells.garbage, cells.corner.size() / 2);  // packed when repairs leave more
  return live;
}

BgMultiPolygon square(double x0, double y0, double x1, double y1) { return {test::box(x0, y0, x1, y1).footprint}; }

EllipticCylinder ellipse(double x, double y, double a, double b, double theta) {
  EllipticCylinder c;
  c.id = "e";
  c.footprint = Ellipse{{x, y}, a, b, theta};
  return c;
}

BgMultiPolygon zones(const ObstacleSet& set) { return merged_zone_polygons(set, ZoneOptions{5.0, 0.5}); }

}  // namespace

TEST(ConvexCells, AnOpenBoxIsOneCellAndASquareAnnulusFour) {
  const NavMesh open(BgMultiPolygon{}, {0, 0}, {10, 5});
  EXPECT_EQ(open.faces().size(), 2u);
  ASSERT_EQ(check_cells(open), 1u);
  EXPECT_EQ(open.cells().count[0], 4u);
  EXPECT_NEAR(cell_area(open, open.cells(), 0), 50.0, 1e-12);

  // The water between two squares: its 8 triangles. Each hole corner sees
  // 270 degrees of water, so an edge must stay there: four cells (one
  // trapezoid per side) is the least any convex split has, and what the
  // merge leaves here.
  const NavMesh ring(square(-10, -10, 10, 10), {-50, -50}, {50, 50});
  EXPECT_EQ(check_cells(ring), 4u);
  double area = 0.0;
  for (std::int32_t c = 0; c < 4; ++c) area += cell_area(ring, ring.cells(), c);
  EXPECT_NEAR(area, 100.0 * 100.0 - 20.0 * 20.0, 1e-9);
}

TEST(ConvexCells, RandomFieldsAndRepairsKeepEveryCellConvexAndTheMergeMaximal) {
  // DEEPGUIDE_NAVMESH_SEED shifts the seed: a claim holds only when a fresh seed confirms it.
  unsigned seed = 4711;
  if (const char* shift = std::getenv("DEEPGUIDE_NAVMESH_SEED")) seed += static_cast<unsigned>(std::atoi(shift));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-400.0, 400.0), axis(3.0, 40.0), ratio(0.2, 1.0), turn(0.0, 3.14159);
  std::size_t triangles = 0, cells = 0;
  for (int field = 0; field < 20; ++field) {
    ObstacleSet set;
    for (int k = 0; k < 25; ++k) {
      const double a = axis(rng);
      set.ellipses.push_back(ellipse(coord(rng), coord(rng), a, a * ratio(rng), turn(rng)));
    }
    NavMesh mesh(zones(set), {-500, -500}, {500, 500});
    triangles += mesh.faces().size();
    cells += check_cells(mesh);
    // Rocks inserted later (150 into the first field, enough for the
    // unused corners to be packed away): the cells round them are made
    // again, and everything holds as before.
    for (int k = 0; k < (field == 0 ? 150 : 1); ++k) {
      ObstacleSet rock;
      rock.ellipses.push_back(ellipse(coord(rng), coord(rng), 20.0, 12.0, turn(rng)));
      mesh.insert(zones(rock));
      check_cells(mesh, false);
    }
    if (HasFailure()) break;
  }
  std::printf("seed %u: %zu triangles merged into %zu convex cells\n", seed, triangles, cells);
  EXPECT_LT(cells, triangles * 3 / 4);  // the merge does merge
}
