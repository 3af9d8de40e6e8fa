#pragma once
// Post-smoothing of a graph route by string pulling (docs/PLANNING.md,
// `--smooth`): from each anchor, jump to the farthest later waypoint the anchor
// sees, where `sees(a, b)` says the straight leg a -> b is allowed (free, and
// flyable in depth). Greedy, O(k^2) tests at worst, not optimal: it can only
// shortcut between the waypoints the search chose. The quadtree (2-D) and the
// octree (3-D) use it.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

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

/// Tightens a pulled route towards the locally shortest one through the
/// same corridor by cutting corners: corner c between a and b becomes
/// c + s u_a, c + s u_b (u: unit vectors along its legs) for the largest s up
/// to the shorter leg whose cut c + s u_a -> c + s u_b is allowed (bisection
/// to 1/4096), which shortens the route by 2 s - |cut|. A corner a greedy jump
/// left beyond an obstacle walks back to it, and one that cuts round a curve
/// splits until the corners wrap it. Pass after pass until a pass gains no
/// more than `settle` or `passes` are done; cuts that gain less than a
/// tenth of `settle` are not made, and at most `max_points` waypoints are
/// kept. A final pull_string drops waypoints left on a straight line. Never
/// longer than the input; every leg it adds is allowed.
template <class Point, class Sees>
std::vector<Point> tighten_string(const std::vector<Point>& points, const Sees& sees, int passes = 200,
                                  double settle = 1e-3, std::size_t max_points = 4096) {
  if (points.size() <= 2) return points;
  std::vector<Point> p = points;
  for (int pass = 0; pass < passes; ++pass) {
    double gained = 0.0;
    std::vector<Point> out{p.front()};
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const Point a = out.back(), c = p[k], b = p[k + 1];
      const double la = (a - c).norm(), lb = (b - c).norm();
      if (la <= 0.0 || lb <= 0.0 || p.size() + out.size() > max_points) {
        out.push_back(c);
        continue;
      }
      const Point ua = (a - c) / la, ub = (b - c) / lb;
      const auto allowed = [&](double s) { return sees(Point(c + s * ua), Point(c + s * ub)); };
      double cut = std::min(la, lb);
      if (!allowed(cut)) {
        double lo = 0.0;
        for (int i = 0; i < 12; ++i) {
          const double mid = 0.5 * (lo + cut);
          (allowed(mid) ? lo : cut) = mid;
        }
        cut = lo;
      }
      const Point c1 = c + cut * ua, c2 = c + cut * ub;
      const double gain = 2.0 * cut - (c2 - c1).norm();
      if (!(gain > 0.1 * settle)) {
        out.push_back(c);
        continue;
      }
      gained += gain;
      if ((c1 - a).norm() > 0.0) out.push_back(c1);
      if ((c2 - b).norm() > 0.0) out.push_back(c2);
    }
    out.push_back(p.back());
    p = std::move(out);
    if (gained <= settle) break;
  }
  return pull_string(p, sees);
}

}  // namespace deepguide
