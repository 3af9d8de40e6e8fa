#pragma once
// The graph kinds, by name: what `plan --graph`, `evaluate --methods`, mission
// control and the Planner find a graph by. Each entry says what the graph can
// do (price time and energy, take open-water vertices, keep a turning radius)
// so every caller refuses the same requests with the same words, and gives
// the one phrase `--graph`'s help shows.
//
// A new graph needs no edit elsewhere: a RouteGraph that answers queries, and
// its entry given to register_graph before the first plan (a test's or a
// program's start-up). The Planner builds it from the obstacles, checks the
// start and goal and every route it returns (the independent checker), and
// plan_single_query plans with it over the obstacles that can matter.
// docs/ARCHITECTURE.md works one through; tests/planning/test_toy_graph.cpp
// is one.
//
// The built-in graphs (visibility, visibility-full, tangent, quadtree) are
// entries without a build function: the Planner builds them itself, for what
// they add beyond the interface (Dubins ends, corner rounding, the quadtree's
// cells for D* Lite). The octree plans in depth (depth_planning.hpp): its
// entry names it, and callers send it there.

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/planner_options.hpp"
#include "deepguide/planning/query_focus.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace DEEPGUIDE_API deepguide {

/// A graph built for one environment, answering any number of queries.
class RouteGraph {
 public:
  virtual ~RouteGraph() = default;
  /// A route from start to goal, both outside every safety zone (the Planner
  /// has checked), weighed by `cost` when it is not null (else by length);
  /// found == false with a one-line message when the graph has none. Its
  /// searches keep to `budget` (shortest_path takes it; stats.stopped says
  /// when one ran out).
  virtual PlanResult solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel* cost,
                           const SearchBudget& budget) = 0;
  /// Its edges, for drawings (`plan --render-graph`).
  virtual std::vector<std::pair<Vec2, Vec2>> edges() const = 0;
};

/// What a graph is built from.
struct GraphBuild {
  const ObstacleSet& obstacles;
  const ObstacleField& field;  ///< exact, at the options' margin: is_free, clearance, segment_free
  const PlannerOptions& options;
  /// The one query the graph may restrict itself to (query_focus.hpp); inactive: any query.
  const QueryFocus& focus;
};

struct GraphCapabilities {
  bool weighs_cost = false;      ///< plans by time and energy too (else by length only)
  bool open_water_grid = false;  ///< takes PlannerOptions::grid
  bool turn_radius = false;      ///< keeps PlannerOptions::turn_radius_m
  bool in_depth = false;         ///< plans in depth (the octree), not by the Planner
};

struct GraphEntry {
  std::string name;  ///< what --graph and evaluate's methods call it
  std::string help;  ///< one phrase, e.g. "exact, curved"
  GraphCapabilities can;
  /// Builds the graph; null for the built-in graphs, which the Planner builds itself.
  std::function<std::unique_ptr<RouteGraph>(const GraphBuild&)> build;
};

/// Adds a graph kind. Throws InputError for an empty name, one with a comma
/// or colon (evaluate's method syntax), one already taken, or no build function.
void register_graph(GraphEntry entry);
/// The entry of `kind`; InputError "`graph`: expected visibility, ..., got 'X'" otherwise.
const GraphEntry& graph_entry(const GraphKind& kind);
/// Every entry, the built-in ones first, then in the order they were registered.
std::vector<GraphEntry> graph_entries();
/// "visibility, visibility-full, tangent, quadtree or octree": the names (of
/// those `which` accepts, when given), for messages.
std::string graph_names_text(const std::function<bool(const GraphEntry&)>& which = {});
/// "visibility (reduced polygon graph), ..., or octree (...)": --graph's help.
std::string graph_help_text();

}  // namespace deepguide
