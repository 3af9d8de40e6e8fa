#pragma once
// The navigation-mesh graph as the registry builds it (`--graph navmesh`):
// the mesh of the water (nav_mesh.hpp) round the same zone polygons the
// visibility graphs use (graph_zones.hpp), searched by Polyanya
// (polyanya.hpp). Its routes are the shortest among those polygons, as the
// full visibility graph's are, found without a graph of what sees what.
//
// The work area is the polygons' box, with the query's start and goal when
// it is built for one (GraphBuild::focus), widened by a tenth (at least
// 100 m). The shortest route never leaves the convex hull of the polygons,
// start and goal, so the box costs nothing in length; a query whose start or
// goal lies outside it widens it and triangulates again. Coordinates are
// taken about the box's centre (UTM's millions of metres cost orientation
// tests six digits).
//
// Built from a prepared chart's bytes (GraphBuild::prepared), it reads its
// zones and mesh back instead: the same graph, without the zones' union and
// the triangulation, which are most of its build.
//
// Obstacles found later (a sonar detection) go in without a rebuild
// (insert): their zones, at the margin and tolerance the graph was built
// with, are cut out of the mesh round them (NavMesh::insert), and joined to
// the zone polygons for the band test when a query next needs it. A zone
// that reaches the work area's edge widens the area (the shortest route may
// pass round it outside), and that is a new triangulation.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"
#include "deepguide/planning/polygon_visibility.hpp"

namespace DEEPGUIDE_API deepguide {

class NavMeshGraph : public RouteGraph {
 public:
  explicit NavMeshGraph(const GraphBuild& in);
  ~NavMeshGraph() override;

  /// Shortest by length (`cost` is not read: the entry prices by length
  /// only); Polyanya with its heuristic for A*, without for Dijkstra.
  PlanResult solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel* cost,
                   const SearchBudget& budget) override;
  /// The mesh's edges, in the planning frame.
  std::vector<std::pair<Vec2, Vec2>> edges() const override;

  const NavMesh& mesh() const { return *mesh_; }
  /// Where the mesh's coordinates have their origin, in the planning frame.
  Vec2 origin() const { return origin_; }
  /// The zone polygons it was built round (not those inserted since).
  const BgMultiPolygon& zones() const { return zones_; }
  /// The zones and the mesh as bytes (nav_mesh_file.hpp): the entry's `save`.
  /// A mesh obstacles were inserted into is not kept (std::logic_error):
  /// its zones no longer give the origin its coordinates are about.
  std::vector<std::uint8_t> save() const;

  /// Takes obstacles found after the build out of the water (see above).
  /// With a turning radius, their zones are widened for their own turning
  /// circles only (not for circles between them and the older obstacles);
  /// the Planner's finishing and the route checker judge the rest. Not safe
  /// while another thread queries the graph.
  NavMesh::Repair insert(const ObstacleSet& found);

 private:
  void triangulate(const Vec2& lo, const Vec2& hi);  // the area, in the mesh's coordinates

  // The band round the zones (a start or goal in no water face), built on
  // the first query that needs it: most queries start and end in water, and
  // the visibility's indexes cost as much as a tenth of the graph's build.
  const PolygonVisibility& band() const;

  BgMultiPolygon zones_;
  Vec2 origin_{0.0, 0.0};
  mutable CentredPolygons local_;  // the zones about origin_ (band() joins the inserted ones)
  mutable std::mutex band_lock_;
  mutable std::unique_ptr<PolygonVisibility> band_;
  mutable BgMultiPolygon inserted_;  // zones inserted since the band was last built, about origin_
  bool ever_inserted_ = false;
  double margin_ = 0.0, tolerance_ = 0.0, turn_radius_ = 0.0;  // what insert makes zones with
  std::unique_ptr<NavMesh> mesh_;
  std::size_t edge_count_ = 0;
};

/// The registry's entry (`--graph navmesh`).
GraphEntry nav_mesh_graph_entry();

}  // namespace deepguide
