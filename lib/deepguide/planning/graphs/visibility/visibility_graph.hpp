#pragma once
// The seed's planning graph: a visibility graph over the polygons that enclose
// the safety zones.
//
// Vertices are the polygon corners; an edge joins two corners that see each
// other. `full` keeps every visible pair (the seed's graph). `reduced` keeps
// only edges that are supporting at both ends: the polygon neighbours of each
// end lie on one closed side of the edge's line, so the edge could be part of
// a taut string around the obstacles. Shortest paths bend only at convex
// corners and leave them along such lines, so both graphs give the same
// shortest paths, the reduced one with far fewer edges (Latombe 1991, ch. 4).
//
// The graph is built once per environment; solve() attaches start and goal to
// it (two reserved vertices whose edges are removed again afterwards), so many
// queries cost little. Not thread-safe: one query at a time per graph.

#include <cstddef>
#include <memory>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/polygon_visibility.hpp"
#include "deepguide/planning/query_focus.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/planning/waypoint_grid.hpp"

namespace DEEPGUIDE_API deepguide {

enum class VisibilityVariant { full, reduced };

/// How the reduced graph finds its pairs of corners: every pair (few
/// corners), or each corner's neighbours within its occlusion horizon (many);
/// `automatic` chooses by the count. Both give the same edges; the choice is
/// open so that tests can run each path on any field.
enum class CornerPairs { automatic, all_pairs, horizons };

class VisibilityGraph {
 public:
  /// `zones`: polygons enclosing the safety zones, in the local frame. Throws
  /// InputError when they have more corners than max_corners(variant), or
  /// (reduced) too many corners that see open water without end: the full
  /// build tries every pair of corners, the reduced one each corner's
  /// neighbours within its occlusion horizon (occlusion_horizon.hpp).
  /// With an active `focus` only the corners and edges a route from its start
  /// to its goal no longer than its bound can use are built (query_focus.hpp).
  /// With an active `grid`, its lattice points outside the zone polygons
  /// (and within the focus) are vertices too (waypoint_grid.hpp).
  VisibilityGraph(const BgMultiPolygon& zones, VisibilityVariant variant, const QueryFocus& focus = {},
                  const WaypointGrid& grid = {}, CornerPairs pairs = CornerPairs::automatic);
  static std::size_t max_corners(VisibilityVariant variant);

  /// Cheapest route from start to goal in this graph: shortest, or by `cost`
  /// (time or energy in a current, cost_model.hpp) when given. Start and goal
  /// must not lie strictly inside a zone polygon (the planner facade checks and explains).
  PlanResult solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel* cost = nullptr,
                   const SearchBudget& budget = {});

  VisibilityVariant variant() const { return variant_; }
  std::size_t vertex_count() const { return corners_.size(); }
  std::size_t edge_count() const { return base_edges_; }
  std::size_t lattice_points() const { return lattice_points_; }
  double build_ms() const { return build_ms_; }
  /// Corner positions and graph edges in the local frame (for drawings).
  std::vector<Vec2> corner_positions() const;
  std::vector<std::pair<Vec2, Vec2>> edges() const;
  /// Exact polygon visibility in the local frame.
  bool segment_visible(const Vec2& p, const Vec2& q) const;
  bool strictly_inside(const Vec2& p) const;
  Vec2 closest_boundary_point(const Vec2& p) const;

 private:
  struct Corner {
    Vec2 p, prev, next;       // translated to origin_
    bool convex;              // the obstacle's interior angle is below 180 degrees
    bool open_water = false;  // a lattice point: no polygon, every direction supports
  };
  static constexpr std::size_t kNoVertex = static_cast<std::size_t>(-1);
  std::vector<std::size_t> add_lattice_points(const WaypointGrid& grid);
  void link_lattice(const WaypointGrid& grid, const std::vector<std::size_t>& vertex, std::size_t n);
  bool supporting_at(const Corner& c, const Vec2& other) const;

  VisibilityVariant variant_;
  Vec2 origin_;
  QueryFocus focus_;  // translated to origin_
  std::unique_ptr<PolygonVisibility> visibility_;
  std::vector<Corner> corners_;
  PlanningGraph graph_;
  std::size_t base_edges_ = 0;
  std::size_t lattice_points_ = 0;
  double link_radius_ = 0.0;  // lattice points join what they see within it (0: no lattice)
  double build_ms_ = 0.0;
};

}  // namespace deepguide
