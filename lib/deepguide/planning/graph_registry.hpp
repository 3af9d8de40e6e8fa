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
// Every graph comes in by this door, the built-in ones too (each in its
// folder under planning/graphs/, listed in graphs/builtin_graphs.cpp): an
// entry with its build function and what it can do, stated once, in the
// graph's folder. The octree plans in depth (depth_planning.hpp), not among
// obstacles in the plane: its entry names it and has no build function, and
// callers send it there.

#include <cstdint>
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
#include "deepguide/planning/route_graph.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace DEEPGUIDE_API deepguide {

/// What a graph is built from.
struct GraphBuild {
  const ObstacleSet& obstacles;
  const ObstacleField& field;  ///< exact, at the options' margin: is_free, clearance, segment_free
  const PlannerOptions& options;
  /// The one query the graph may restrict itself to (query_focus.hpp); inactive: any query.
  const QueryFocus& focus;
  /// The margin the graph plans with: options.margin, but never below a
  /// micrometre or a ten-billionth of the largest coordinate (planner.cpp says why).
  double margin = 0.0;
  /// Bytes the entry's `save` wrote for the same obstacles and options
  /// (prepared_graphs.hpp): the graph is read from them, not built. Null: build.
  const std::vector<std::uint8_t>* prepared = nullptr;
};

struct GraphCapabilities {
  bool weighs_cost = false;      ///< plans by time and energy too (else by length only)
  bool open_water_grid = false;  ///< takes PlannerOptions::grid
  bool turn_radius = false;      ///< keeps PlannerOptions::turn_radius_m (with `smooth` when it steps)
  /// Its routes step from cell to cell: it takes PlannerOptions::quadtree.smooth
  /// (string pulling), and keeps a turning radius only with it.
  bool steps = false;
  /// Its routes are finished by the Planner: refined off the vertices in a
  /// changing current, corners rounded within a turning radius
  /// (route_finishing.hpp). Otherwise the graph keeps the radius itself.
  bool finished_by_planner = false;
  bool dubins_ends = false;  ///< plans a start or goal heading (PlanningProblem::start_heading)
  /// Repairs its route as the sonar finds obstacles, without a rebuild
  /// (replanning.hpp): D* Lite on the quadtree's cells, the mesh cut round
  /// them and searched again on the navmesh.
  bool repairs = false;
  /// It covers a work area, not the ellipse round start and goal that a
  /// focus bounds: plan_single_query builds it once, over every obstacle,
  /// and the focus it is given only names the query (its area is sized for it).
  bool covers_area = false;
  bool in_depth = false;  ///< plans in depth (the octree), not by the Planner
};

struct GraphEntry {
  std::string name;  ///< what --graph and evaluate's methods call it
  std::string help;  ///< one phrase, e.g. "exact, curved"
  GraphCapabilities can;
  /// Builds the graph; null only for a graph that plans in depth.
  std::function<std::unique_ptr<RouteGraph>(const GraphBuild&)> build;
  /// The graph as bytes its `build` reads back (GraphBuild::prepared), for
  /// `chart prepare --graphs`; null when the graph cannot be kept.
  std::function<std::vector<std::uint8_t>(const RouteGraph&)> save = {};
  /// Takes obstacles found after the build into the graph without building
  /// it again (Planner::insert); null when the graph must be built anew.
  std::function<void(RouteGraph&, const ObstacleSet&)> insert = {};
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
