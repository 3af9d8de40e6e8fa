#pragma once
// Post-smoothing of a graph route by string pulling (shared/notes/algorithms.md
// §4.3): from each anchor, jump to the farthest later waypoint the anchor
// sees, where `sees(a, b)` says the straight leg a -> b is allowed (free, and
// flyable in depth). Greedy, O(k^2) tests at worst, not optimal: it can only
// shortcut between the waypoints the search chose. The quadtree (2-D) and the
// octree (3-D) use it.

#include <cstddef>
#include <vector>

namespace deepguide {

template <class Point, class Sees>
std::vector<Point> pull_string(const std::vector<Point>& points, const Sees& sees) {
  if (points.size() <= 2) return points;
  std::vector<Point> pulled{points.front()};
  std::size_t anchor = 0;
  while (anchor + 1 < points.size()) {
    std::size_t next = points.size() - 1;
    while (next > anchor + 1 && !sees(points[anchor], points[next])) --next;
    pulled.push_back(points[next]);
    anchor = next;
  }
  return pulled;
}

}  // namespace deepguide
