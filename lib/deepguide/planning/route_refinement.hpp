#pragma once
// A time or energy route taken from the graph to the continuous optimum
// (issue 23, item 5).
//
// Why: a graph search is optimal over its vertices only. Where the current
// changes from place to place the cheapest route bends in open water, and a
// lattice of 16 directions (waypoint_grid.hpp) bends it only in those
// directions: routes stayed 0.4-1.2 % slower than the continuous optimum at
// every lattice spacing. Refinement moves the route's vertices off the
// lattice.
//
// Method: coarse to fine. At each level every leg longer than h is cut into
// equal pieces (the new vertices lie on the old legs, so the cost does not
// change), then Gauss-Seidel sweeps move each inner vertex p_i to lower
//   f(p) = w(p_{i-1} -> p, t_{i-1}) + w(p -> p_{i+1}, t_{i-1} + time of the first leg)
// by Brent's method along the normal of the chord p_{i-1} p_{i+1}, then along
// the chord, within half the shorter neighbouring leg. A move is kept only
// when it lowers f and both legs keep the margin from every zone (the exact
// obstacle field, not the graph's polygons) and stay feasible in the current.
// h starts at a quarter of the route's length and halves until the finest
// level (the route's length / 256 by default); a level ends when a sweep
// gains less than the tolerance. Long waves of the route's shape are
// settled on the coarse levels, where one vertex moves a long stretch: that
// is what makes Gauss-Seidel converge in a few sweeps per level. Last,
// vertices go while their removal costs, all together, less than a second
// tolerance (10^-4 of the cost by default; open water where
// the current bends nothing keeps no vertices).
//
// Time-dependent currents: each leg is priced leaving at the time the sweep
// reaches its first vertex. For time (and energy at a fixed speed, which is
// P(v) times the time) an earlier arrival at p_{i+1} never arrives later at
// the goal (FIFO, cost_model.hpp), so lowering f never raises the route's
// cost; the whole route is priced after each sweep and a sweep that did not
// gain is undone.
//
// The result is a local optimum near the graph's route: the graph chooses
// the way round obstacles and the side of a jet, refinement the exact line.
// It is never costlier than the route it was given.

#include <cstddef>
#include <functional>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/cost_model.hpp"

namespace DEEPGUIDE_API deepguide {

/// Whether the straight leg a -> b keeps the margin from every zone.
using LegIsFree = std::function<bool(const Vec2& a, const Vec2& b)>;

struct RefinementOptions {
  /// A level ends, and a vertex goes at the end, when it changes the route's
  /// cost by less than this fraction of it.
  double relative_tolerance = 1e-7;
  /// Vertices go at the end while all removals together cost at most this
  /// fraction of the route's cost (9 s in a day's route).
  double prune_tolerance = 1e-4;
  /// The finest level's leg length is the route's length / this.
  double finest_division = 256.0;
  /// Never finer than this (m).
  double finest_leg_m = 5.0;
  std::size_t max_sweeps_per_level = 60;
  /// The most vertices a refined route may have (the finest level is coarser when it would have more).
  std::size_t max_points = 2000;
};

struct RefinedRoute {
  std::vector<Vec2> points;
  double cost_before = 0.0;  ///< the given route's, in the model's kind
  double cost_after = 0.0;
  std::size_t sweeps = 0;  ///< Gauss-Seidel sweeps over all levels
  std::size_t levels = 0;
};

/// Whether refinement can change a route under this model: time or energy
/// in a current that changes from place to place (in a uniform one, or none,
/// straight legs between corners are already optimal).
bool refinement_applies(const CostModel& model);

/// The route `points` (start and goal kept) refined as the header says.
/// Returns the route as it was when it is infeasible or has no inner room to
/// move (two points and a straight leg already optimal are both fine).
/// Throws InputError for fewer than two points or a non-finite point.
RefinedRoute refine_route(const CostModel& model, std::vector<Vec2> points, const LegIsFree& leg_is_free,
                          const RefinementOptions& options = {});

}  // namespace deepguide
