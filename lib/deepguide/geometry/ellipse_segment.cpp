#include "deepguide/geometry/ellipse_segment.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {

std::vector<double> segment_boundary_crossings(const Ellipse& e, const Vec2& p0, const Vec2& p1) {
  const Vec2 q0 = e.to_unit(p0);
  const Vec2 d = e.to_unit(p1) - q0;
  // |q0 + t d|^2 = 1  <=>  A t^2 + 2 B t + C = 0
  const double A = d.squaredNorm();
  const double B = q0.dot(d);
  const double C = q0.squaredNorm() - 1.0;
  std::vector<double> ts;
  if (A == 0.0) return ts;  // degenerate segment: a point has no crossing
  const double disc = B * B - A * C;
  if (disc < 0.0) return ts;
  const double root = std::sqrt(disc);
  // Numerically stable pair of roots (no cancellation between -B and root).
  const double qq = -(B + std::copysign(root, B));
  double t1 = qq / A;
  double t2 = qq != 0.0 ? C / qq : t1;
  if (t1 > t2) std::swap(t1, t2);
  for (double t : {t1, t2}) {
    if (t >= 0.0 && t <= 1.0 && (ts.empty() || ts.back() != t)) ts.push_back(t);
  }
  return ts;
}

bool segment_intersects(const Ellipse& e, const Vec2& p0, const Vec2& p1) {
  const Vec2 q0 = e.to_unit(p0);
  const Vec2 d = e.to_unit(p1) - q0;
  // Closest point of the segment to the centre in the unit frame.
  const double A = d.squaredNorm();
  const double t = A > 0.0 ? std::clamp(-q0.dot(d) / A, 0.0, 1.0) : 0.0;
  return (q0 + t * d).squaredNorm() < 1.0;
}

}  // namespace deepguide
