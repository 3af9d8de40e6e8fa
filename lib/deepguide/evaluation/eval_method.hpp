#pragma once
// The methods `deepguide evaluate` compares, by name, and one run of a method
// on one scenario: one row of the results (evaluation/eval_rows.hpp).
//
// Names:
//   geometric, dipole, potential   the reactive level (reactive/): the vehicle
//                                  sees the obstacles with the scenario's sonar
//                                  and evades them as it goes
//   GRAPH[:SEARCH][:COST]          a planner (planning/planner.hpp) that knows
//                                  the true obstacles: GRAPH visibility,
//                                  visibility-full, tangent or quadtree; SEARCH
//                                  astar (default) or dijkstra; COST length
//                                  (default), time or energy in the scenario's
//                                  current. The route is planned once with
//                                  the scenario's margin and then sailed by
//                                  the vehicle (simulation/route_following.hpp).
// Every method is measured by the same simulation (plant, statistics, stop
// rules), so path, energy, time, clearance and turning rates compare.
// Compute time: a planner's graph builds and searches; a reactive method's
// guidance over the whole run (sonar, contacts and the method's steps).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace DEEPGUIDE_API deepguide {

struct EvalMethod {
  std::string
      name;  ///< canonical: "quadtree:dijkstra", "visibility:astar:energy" shortened to what differs from the defaults
  std::optional<ReactiveMethod> reactive;  ///< set for a reactive method; otherwise a planner:
  GraphKind graph = GraphKind::visibility;
  SearchAlgorithm search = SearchAlgorithm::astar;
  CostKind cost = CostKind::length;

  bool is_planner() const { return !reactive.has_value(); }
};

/// Parses a method name (header). Throws InputError "unknown method 'X':
/// expected ..." listing the names.
EvalMethod parse_eval_method(const std::string& text);
/// Parses a comma-separated list of method names, in order.
std::vector<EvalMethod> parse_eval_methods(const std::string& list);

/// What one method did on one scenario.
struct MethodRun {
  std::string end;   ///< reached, stalled, target_in_zone, no_progress, time_out, or no_route (planners)
  std::string note;  ///< why there is no route, or what the reactive method collided with; empty otherwise
  bool reached = false, collided = false;
  /// A reactive method's collision that no guidance could have avoided
  /// (simulation/collision_envelope.hpp); false for every other run.
  bool unavoidable = false;
  double route_length_m = 0.0;                               ///< the planned route (planners; 0 for reactive methods)
  double path_length_m = 0.0, energy_j = 0.0, time_s = 0.0;  ///< sailed (0 without a route)
  double min_clearance_m = 0.0;                              ///< +inf without obstacles
  double max_rate_ref = 0.0, rms_rate_ref = 0.0, max_rate = 0.0, rms_rate = 0.0;  ///< rad/s
  /// Kept only when asked (run_method's keep_track; never in the rows): the
  /// planner's route and the positions sailed, a sample a step (local frame).
  std::vector<Vec2> route, track;
  int heading_reversals = 0;
  double compute_ms = 0.0;
  std::size_t graph_vertices = 0, graph_edges = 0;
};

/// Runs `method` on `scenario` (validated by the caller's loader). Throws
/// InputError for what the scenario cannot do (e.g. a current the planner's
/// cost model refuses); a planner that finds no route is a row (no_route).
/// With `keep_track`, the run also keeps the planner's route and the track
/// sailed (MethodRun::route, track: for maps of it, evaluation/eval_maps.hpp).
MethodRun run_method(const Scenario& scenario, const EvalMethod& method, bool keep_track = false);

}  // namespace deepguide
