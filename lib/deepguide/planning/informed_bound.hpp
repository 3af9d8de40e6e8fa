#pragma once
// The informed bound, written once: a search that plans only with what can
// lie on a route of length at most U, and grows U until its answer is final.
//
// Math on top. Every point x of a path from s to g of length L satisfies
// |x - s| + |x - g| <= L, so the path lies in the ellipse
//   E(U) = { x : |x - s| + |x - g| <= U }   for any U >= L
// (the "informed set" of Informed RRT*). A graph that joins start and goal
// only to what lies in E(U) (the visibility and tangent graphs), or is built
// only over the obstacles that meet E(U) (plan_single_query), loses nothing
// a route within U could use. So a route it finds whose reach is within U is
// final: no route it left out is shorter. The reach of a route is its
// length, or, weighed by time or energy, its cost C over the least cost per
// metre c (a route of cost C is at most C / c long). Otherwise U grows past
// that reach (one more round is then final), or, with no route, doubles,
// until it holds everything (`farthest`).

#include <algorithm>
#include <cmath>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/graph_search.hpp"

namespace DEEPGUIDE_API deepguide {

/// |p - s| + |p - g|: the least U whose E(U) holds p.
inline double informed_reach(const Vec2& p, const Vec2& s, const Vec2& g) { return (p - s).norm() + (p - g).norm(); }

/// After a round at `bound`: whether its answer (a route of reach `reach`
/// when `found`) is final, and else the next bound. A bound at or beyond
/// `farthest` holds everything, so its round is final whatever it found.
struct NextBound {
  bool final = true;
  double bound = 0.0;
};
inline NextBound next_bound(double bound, double farthest, bool found, double reach, double growth = 1.0) {
  if (bound >= farthest || (found && reach <= bound)) return {true, bound};
  return {false, found ? growth * std::max(reach, bound) : std::min(2.0 * bound, farthest)};
}

/// Runs `round(bound)`, a search over what lies in E(bound) returning a
/// SearchResult, from `first` on, until its answer is final (next_bound).
/// `per_metre` turns a cost into a reach (1 for lengths).
template <class Round>
SearchResult search_in_growing_bound(double first, double farthest, double per_metre, Round&& round) {
  for (double bound = first;;) {
    SearchResult found = round(bound);
    if (found.stopped != SearchStop::none) return found;  // out of budget: nothing is proven
    const NextBound next = next_bound(bound, farthest, found.found, found.cost / per_metre);
    if (next.final) return found;
    bound = next.bound;
  }
}

}  // namespace deepguide
