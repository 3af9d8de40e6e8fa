#include "deepguide/geometry/ellipse_distance.hpp"

#include <cmath>

namespace deepguide {
namespace {

// Root u of G(u) = (r0 z0 / (u + r0 - 1))^2 + (z1 / u)^2 - 1, with r0 = (e0/e1)^2,
// z_i = y_i / e_i and u = t / e1^2 + 1 (Eberly's s + 1). We solve for u rather
// than s because for points inside near the major axis (and near the centre)
// the root sits at u ~ z1 -> 0, where s = u - 1 would round to -1 and
// x1 = y1 / u lose every digit; doubles near 0 keep full relative precision.
//
// G is a sum of convex, decreasing terms on u > 0 (r0 >= 1), so the root is
// bracketed by lower bounds where G >= 0 (u = z1 makes the second term 1;
// u = r0 z0 - r0 + 1 the first) and upper ones where G <= 0 (|(r0 z0, z1)|,
// or 1 for points inside). Newton's step from the left of the root stays left
// of it and converges quadratically; a step that leaves the bracket (from
// the right, or rounding) is replaced by the bracket's midpoint, so the
// search ends as Eberly's bisection does, with the bracket exhausted, in a
// handful of steps instead of some sixty.
double bracketed_root(double r0, double z0, double z1, double g) {
  const double n0 = r0 * z0;
  const double rm1 = r0 - 1.0;
  double lo = std::max(z1, n0 - rm1);
  double hi = g < 0.0 ? 1.0 : std::hypot(n0, z1);
  if (!(lo < hi)) return lo;  // the bounds met: the root to rounding
  double u = lo;
  // Every step either shrinks the bracket by Newton or halves it: 1100
  // steps exhaust every double in it.
  for (int i = 0; i < 1100; ++i) {
    const double ratio0 = n0 / (u + rm1);
    const double ratio1 = z1 / u;
    const double gu = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
    if (gu == 0.0) return u;
    if (gu > 0.0) {
      lo = u;
    } else {
      hi = u;
    }
    const double slope = -2.0 * (ratio0 * ratio0 / (u + rm1) + ratio1 * ratio1 / u);
    double next = u - gu / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == u || next == lo || next == hi) break;
    u = next;
  }
  return u;
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
      const double u = bracketed_root(r0, z0, z1, g);
      // r0 - 1 first: u + r0 would round u away when u << 1.
      return {r0 * y0 / (u + (r0 - 1.0)), y1 / u};
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

double signed_distance(const Ellipse& e, const Vec2& p) { return project_to_ellipse(e, p).signed_distance(); }

}  // namespace deepguide
