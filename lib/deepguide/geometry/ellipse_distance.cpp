#include "deepguide/geometry/ellipse_distance.hpp"

#include <cmath>

namespace deepguide {
namespace {

// Root s of G(s) = (r0 z0 / (s + r0))^2 + (z1 / (s + 1))^2 - 1, with r0 = (e0/e1)^2,
// z_i = y_i / e_i and s = t / e1^2. G is decreasing; the root is bracketed by
// [z1 - 1, |(r0 z0, z1)| - 1] (or 0 as the upper end for points inside).
double bisect_root(double r0, double z0, double z1, double g) {
  const double n0 = r0 * z0;
  double s0 = z1 - 1.0;
  double s1 = g < 0.0 ? 0.0 : std::hypot(n0, z1) - 1.0;
  double s = 0.0;
  // Each step halves the bracket; 1100 steps exhaust every double in it.
  for (int i = 0; i < 1100; ++i) {
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1) break;
    const double ratio0 = n0 / (s + r0);
    const double ratio1 = z1 / (s + 1.0);
    const double gs = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
    if (gs > 0.0) {
      s0 = s;
    } else if (gs < 0.0) {
      s1 = s;
    } else {
      break;
    }
  }
  return s;
}

// First quadrant, e0 >= e1 > 0, y0, y1 >= 0. Returns the closest point (x0, x1).
Vec2 closest_in_first_quadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0;
      const double z1 = y1 / e1;
      const double g = z0 * z0 + z1 * z1 - 1.0;
      if (g == 0.0) return {y0, y1};
      const double r0 = (e0 / e1) * (e0 / e1);
      const double s = bisect_root(r0, z0, z1, g);
      return {r0 * y0 / (s + r0), y1 / (s + 1.0)};
    }
    return {0.0, e1};
  }
  // On the major axis: the closest point leaves the axis while y0 is inside the
  // evolute's cusp, (e0^2 - e1^2) / e0.
  const double numer0 = e0 * y0;
  const double denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    return {e0 * xde0, e1 * std::sqrt(std::max(0.0, 1.0 - xde0 * xde0))};
  }
  return {e0, 0.0};
}

}  // namespace

EllipseProjection project_to_ellipse(const Ellipse& e, const Vec2& p) {
  const Vec2 q = e.to_local(p);
  const double y0 = std::abs(q.x());
  const double y1 = std::abs(q.y());
  Vec2 x = closest_in_first_quadrant(e.a, e.b, y0, y1);
  // Reflect back into the point's quadrant.
  x.x() = std::copysign(x.x(), q.x());
  x.y() = std::copysign(x.y(), q.y());
  const double dist = std::hypot(x.x() - q.x(), x.y() - q.y());
  const double z0 = y0 / e.a;
  const double z1 = y1 / e.b;
  return {e.from_local(x), dist, z0 * z0 + z1 * z1 < 1.0};
}

double signed_distance(const Ellipse& e, const Vec2& p) {
  return project_to_ellipse(e, p).signed_distance();
}

}  // namespace deepguide
