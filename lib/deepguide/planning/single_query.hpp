#pragma once
// One query without a reusable environment (what `deepguide plan` does): the
// graph is built only over the obstacles that can matter for this start and
// goal, and the answer is the same as Planner(all obstacles).solve(problem).
//
// Math on top. Every point x of a path from s to g of length L satisfies
// |x - s| + |x - g| <= L, so the path lies in the ellipse
//   E(U) = { x : |x - s| + |x - g| <= U }   for any U >= L
// (the "informed set" of Informed RRT*). Plan with only the obstacles whose
// zone (or zone polygon) meets E(U):
//  - no route among fewer obstacles => no route among all of them;
//  - a route of polyline length L <= U lies in E(U), where every obstacle was
//    present, so it is safe among all obstacles; and it is optimal: any
//    shorter route of the full problem also lies in E(U) and was available to
//    the restricted graph (the graph inside E(U) is the same).
// Otherwise grow U past L and plan again; with every obstacle in (U beyond
// the farthest), the last round is final.
// The graph of each round is also built with U as its focus
// (query_focus.hpp): only the vertices and edges a path within U can use.
// A focused graph without a route proves nothing, so that round is repeated
// over the same obstacles without the focus; no route then means none at all.
// The first U is 1.01 |g - s| (single_query.cpp says why).
// An obstacle is kept when a disc around it (footprint radius + margin +
// polygon tolerance) meets E(U): for a disc of centre c and radius r,
// min over the disc of |x - s| + |x - g| >= |c - s| + |c - g| - 2 r.
// Weighed by time or energy (cost_model.hpp), a route of cost C is at most
// C / c long, c the cost per metre's lower bound, so the argument holds with
// L replaced by C / c: the route is final once C / c <= U.

#include <cstddef>
#include <memory>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/planner.hpp"

namespace DEEPGUIDE_API deepguide {

struct SingleQueryPlan {
  /// The route, checked against ALL obstacles (not only those used).
  PlanOutcome outcome;
  /// The planner of the last round (its graph is what the route was found in; for drawings).
  std::unique_ptr<Planner> planner;
  std::size_t obstacles_used = 0;
  std::size_t obstacles_total = 0;
  int rounds = 0;
  double bound_m = 0.0;   ///< U of the last round (infinite: all obstacles, no focus)
  double build_ms = 0.0;  ///< graph builds over all rounds
  double query_ms = 0.0;  ///< queries over all rounds
};

/// Plans one route among `obstacles`. Throws what Planner and Planner::solve
/// throw (InputError for bad options or points, NoRouteError for a start or
/// goal inside a safety zone).
SingleQueryPlan plan_single_query(const ObstacleSet& obstacles, const PlanningProblem& problem,
                                  const PlannerOptions& options);

}  // namespace deepguide
