#pragma once
// A single query's focus: its start s, goal g and a length bound U.
//
// Why it is exact: every point x of a path of length <= U from s to g has
// |x - s| + |x - g| <= U, and every segment p-q on it has
//   via(p, q) = min(|s - p| + |p - q| + |q - g|, |s - q| + |q - p| + |p - g|) <= U.
// A graph built with a focus leaves out every vertex and edge that fails
// these tests: its shortest path, when no longer than U, is the shortest path
// of the whole graph; when longer (or absent), nothing is known and the
// caller widens U (plan_single_query does). For two discs (c1, r1), (c2, r2)
// holding two zone pieces, the same bound with distances to the discs,
//   min over the two orders of d(s, D1) + d(D1, D2) + d(D2, g),
// bounds every segment between the pieces from below, so a pair of pieces
// fails as a whole before any of its tangents is computed.

#include <algorithm>
#include <cmath>
#include <limits>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct QueryFocus {
  Vec2 start{0.0, 0.0};
  Vec2 goal{0.0, 0.0};
  double bound_m = std::numeric_limits<double>::infinity();  ///< infinite: no focus, the whole graph

  bool active() const { return std::isfinite(bound_m); }

  /// The same focus in a frame whose origin is at `origin`.
  QueryFocus shifted(const Vec2& origin) const { return {start - origin, goal - origin, bound_m}; }

  bool keeps_point(const Vec2& p) const { return (p - start).norm() + (p - goal).norm() <= bound_m; }

  bool keeps_segment(const Vec2& p, const Vec2& q) const {
    const double pq = (p - q).norm();
    const double forward = (start - p).norm() + pq + (q - goal).norm();
    const double backward = (start - q).norm() + pq + (p - goal).norm();
    return std::min(forward, backward) <= bound_m;
  }

  /// False when no segment between a point of disc (c1, r1) and one of disc
  /// (c2, r2) can lie on a path within the bound.
  bool keeps_disc_pair(const Vec2& c1, double r1, const Vec2& c2, double r2) const {
    if (!active()) return true;
    auto gap = [](double d) { return std::max(d, 0.0); };
    const double between = gap((c1 - c2).norm() - r1 - r2);
    const double forward = gap((start - c1).norm() - r1) + between + gap((c2 - goal).norm() - r2);
    const double backward = gap((start - c2).norm() - r2) + between + gap((c1 - goal).norm() - r1);
    return std::min(forward, backward) <= bound_m;
  }
};

}  // namespace deepguide
