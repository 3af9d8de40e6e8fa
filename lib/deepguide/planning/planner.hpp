#pragma once
// The planning facade (in the spirit of OMPL's SimpleSetup): one environment,
// built once, many start/goal queries. It owns the obstacles, the exact
// obstacle field used to judge start and goal, and the graph of the chosen
// kind, built by its registry entry (graph_registry.hpp). What it does is
// what every graph shares: it refuses the options the graph cannot serve
// (the entry's capabilities), leaves a start inside a zone (escape), finishes
// the routes of the graphs that ask for it (route_finishing.hpp), times
// build and queries, and runs the independent route checker on every route.

#include <memory>
#include <optional>
#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/planner_options.hpp"
#include "deepguide/planning/query_focus.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/route_graph.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace DEEPGUIDE_API deepguide {

/// What a query's route looks like against the exact obstacles.
struct PlanOutcome {
  PlanResult result;
  RouteCheck check;  ///< the independent checker's verdict on result.route (after the escape leg)
  /// The same on the exact lines and arcs (check_route_legs), when the graph gives them.
  std::optional<RouteCheck> legs_check;
  std::string escaped_from;  ///< obstacle whose zone the start left first (PlanningProblem::escape)
};

class Planner {
 public:
  /// With an active `focus` the graph holds only what one query can use
  /// (query_focus.hpp): the planner then answers that query, exactly when its
  /// route is within the bound (plan_single_query). Without: the whole graph,
  /// for any number of queries.
  Planner(ObstacleSet obstacles, const PlannerOptions& options, const QueryFocus& focus = {});
  ~Planner();
  Planner(Planner&&) noexcept;
  Planner& operator=(Planner&&) noexcept;

  /// Plans from start to goal. Throws InputError for non-finite or identical
  /// points and NoRouteError (naming the obstacle) when start or goal lies in
  /// a safety zone (the start only without `escape`, or when the way out
  /// ends in another zone). A search that finds nothing returns found == false.
  PlanOutcome solve(const PlanningProblem& problem);
  /// Obstacles found after the build (a sonar's contacts, an import into a
  /// store): into the graph without a rebuild (GraphEntry::insert: the
  /// navigation mesh cuts them out of its water), and into the field that
  /// checks every route. InputError for a graph that cannot take them (the
  /// message names those that can) or a bad obstacle; then nothing changes.
  void insert(const ObstacleSet& found);

  const ObstacleField& field() const;
  const PlannerOptions& options() const { return options_; }
  /// The graph; its extras by type: `graph().as<QuadtreeGraph>()`.
  RouteGraph& graph();
  const RouteGraph& graph() const;
  /// The graph as a prepared chart keeps it (GraphEntry::save), under the key
  /// of these obstacles and options (prepared_graphs.hpp); `about` is left to
  /// the caller. InputError when the graph's entry cannot save.
  PreparedGraphRecord save_graph() const;
  /// The graph's edges, for drawings.
  std::vector<std::pair<Vec2, Vec2>> graph_edges() const { return graph().edges(); }

 private:
  std::string why_no_turning_route(const PlanningProblem& problem);
  struct Impl;
  PlannerOptions options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace deepguide
