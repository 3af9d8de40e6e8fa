#pragma once
// What a plan is asked with: the graph kind (a name in the registry,
// graph_registry.hpp), the search, and the Planner's options. Apart from the
// Planner (planner.hpp), so that the registry, the extension point, does not
// depend on the facade that uses it.

#include <memory>
#include <string>

#include "deepguide/charts/prepared_graph_record.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_options.hpp"
#include "deepguide/planning/waypoint_grid.hpp"

namespace DEEPGUIDE_API deepguide {

/// A graph kind: the name of a graph in the registry (graph_registry.hpp).
/// The built-in ones are constants; a registered one is GraphKind{"name"}.
struct GraphKind {
  std::string name;
  static const GraphKind visibility, visibility_full, tangent, quadtree, octree;
  friend bool operator==(const GraphKind&, const GraphKind&) = default;
  friend auto operator<=>(const GraphKind&, const GraphKind&) = default;
};
inline const GraphKind GraphKind::visibility{"visibility"};
inline const GraphKind GraphKind::visibility_full{"visibility-full"};
inline const GraphKind GraphKind::tangent{"tangent"};
inline const GraphKind GraphKind::quadtree{"quadtree"};
/// Routes in depth (depth_planning.hpp): registered for its name and help, not built by Planner.
inline const GraphKind GraphKind::octree{"octree"};

struct PlannerOptions {
  /// Safety margin to every obstacle footprint (m). Below 1 um the graphs use
  /// 1 um (a ten-billionth of the largest coordinate where that is more: 0.6 mm
  /// at UTM northings of 6e6 m): obstacles that merely touch then overlap, and
  /// no route squeezes through a gap of zero width between them.
  double margin = 5.0;
  /// How far zone polygons (and the tangent graph's arc polylines) may reach
  /// beyond the zones (m). 0.5 m keeps polygon routes within 0.028 % of the
  /// optimum on the 1000 test scenarios (0.1 % asked); smaller is slower.
  double tolerance = 0.5;
  GraphKind graph = GraphKind::visibility;
  SearchAlgorithm search = SearchAlgorithm::astar;
  /// What the search minimises; null (or kind length) = the length. Time and
  /// energy need a visibility graph (the tangent graph's arcs are priced by
  /// length only).
  std::shared_ptr<const CostModel> cost = nullptr;
  /// Open-water vertices on a lattice (waypoint_grid.hpp), for routes that
  /// bend where the current changes; visibility graphs only. Off by default.
  WaypointGrid grid = {};
  /// The quadtree graph's cells and area (quadtree_graph.hpp). An empty area
  /// is the obstacles' zones' box, widened by a tenth (plan_single_query
  /// gives the start-goal box instead).
  QuadtreeOptions quadtree = {};
  /// The vehicle's least turning radius (m); 0 = routes may turn on the spot.
  /// Above the margin, zone corners tighter than it are rounded
  /// (turn_rounding.hpp) so every arc of the route has at least this radius.
  /// The tangent graph wraps the rounded zones along their arcs; the
  /// visibility graphs plan round polygons holding the turning circles
  /// (rounded_zone_polygons) and round each corner of the route on a circle
  /// of this radius (corner_fillets.hpp). Not the quadtree.
  double turn_radius_m = 0.0;
  /// Limits on each search (graph_search.hpp): a route not found within them
  /// is reported as such (PlanStats::stopped), never as "no route".
  SearchBudget budget = {};
  /// Time and energy routes in a current that changes from place to place
  /// are refined off the graph's vertices to the continuous optimum near
  /// them (route_refinement.hpp). Off: the graph's own optimum.
  bool refine = true;
  /// Graphs built earlier (a prepared chart's, `chart prepare --graphs`): the
  /// Planner loads the one of its graph kind whose key fits the obstacles and
  /// these options (prepared_graphs.hpp) instead of building it.
  std::shared_ptr<const std::vector<PreparedGraphRecord>> prepared = nullptr;
  /// The obstacles the `prepared` graphs were built over (the prepared
  /// chart's, as read back). When none is kept under the key of all the
  /// obstacles, one kept under these is loaded and the obstacles beyond them
  /// (a store's, a file's) are inserted into it, for a graph that can take
  /// them (GraphEntry::insert: the navmesh), instead of building it anew.
  std::shared_ptr<const ObstacleSet> prepared_obstacles = nullptr;
};

/// A registered graph's name (graph_registry.hpp) / "astar", "dijkstra"; InputError otherwise.
GraphKind parse_graph_kind(const std::string& text);
SearchAlgorithm parse_search(const std::string& text);
std::string to_string(const GraphKind& kind);
std::string to_string(SearchAlgorithm algorithm);

}  // namespace deepguide
