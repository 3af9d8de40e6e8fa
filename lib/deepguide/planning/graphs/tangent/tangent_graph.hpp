#pragma once
// The exact tangent graph over the safety zones' curved boundaries (beyond
// the seed): its shortest paths are the true shortest paths around the zones,
// with no polygon approximation.
//
// A shortest path among convex obstacles is made of segments tangent to the
// obstacles at both ends (or at the start/goal) and arcs along obstacle
// boundaries between tangent points (Liu & Arimoto 1992). Vertices are the
// tangent points of the collision-free common tangents between zone pieces
// (see zone_pieces.hpp) and of the tangents from start and goal; edges are
// those tangents plus the boundary arcs between consecutive tangent points of
// a piece that stay outside every other zone. Tangent normals solve
// h_i(u) = h_j(u) (outer) and h_i(u) + h_j(-u) = 0 (inner) for support
// functions h; segments are checked with the exact obstacle field.
//
// Routes come out as exact legs (lines and arcs) and as a polyline that
// replaces each arc by tangent lines (so it stays outside the zone, by at
// most `tolerance`). Not thread-safe: one query at a time.

#include <memory>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/query_focus.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/planning/route_graph.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

class TangentGraph : public RouteGraph {
 public:
  /// With an active `focus` only what a route from its start to its goal no
  /// longer than its bound can use is built (query_focus.hpp); solve() then
  /// answers that query.
  ///
  /// With `turn_radius` R above the margin, routes turn only where the
  /// boundary's radius is at least R: on the ellipses' zones away from sharp
  /// tips, and on the turning circles of radius R over tighter corners
  /// (turn_rounding.hpp), which are places to turn, not obstacles.
  TangentGraph(const ObstacleSet& obstacles, double margin, double tolerance, const QueryFocus& focus = {},
               double turn_radius = 0.0);
  ~TangentGraph() override;
  TangentGraph(TangentGraph&&) noexcept;
  TangentGraph& operator=(TangentGraph&&) noexcept;

  /// Shortest by length: the arcs are priced by length only, so `cost` is
  /// not read (the registry's entry says so, and the Planner refuses others).
  PlanResult solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel* cost,
                   const SearchBudget& budget) override;
  std::vector<std::pair<Vec2, Vec2>> edges() const override { return tangent_segments(); }

  std::size_t piece_count() const;
  std::size_t tangent_count() const;  ///< collision-free common tangents found at build
  double build_ms() const;
  /// Tangent segments of the environment in the local frame (for drawings).
  std::vector<std::pair<Vec2, Vec2>> tangent_segments() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The registry's entry (`--graph tangent`).
GraphEntry tangent_graph_entry();

}  // namespace deepguide
