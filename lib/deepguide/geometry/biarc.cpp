#include "deepguide/geometry/biarc.hpp"

#include <cmath>
#include <numbers>

namespace deepguide {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The arc from p, leaving along unit tangent t, to q.
std::optional<CircleArc> arc_through(const Vec2& p, const Vec2& t, const Vec2& q) {
  const Vec2 n(-t.y(), t.x());  // left normal
  const Vec2 w = q - p;
  const double across = n.dot(w);
  if (std::abs(across) <= 1e-9 * w.squaredNorm() || w.squaredNorm() == 0.0) return std::nullopt;  // a straight line
  const double r = w.squaredNorm() / (2.0 * across);  // signed: > 0 turns left
  CircleArc a;
  a.from = p;
  a.to = q;
  a.centre = p + r * n;
  a.radius_m = std::abs(r);
  a.turn = r > 0.0 ? +1 : -1;
  const Vec2 u = p - a.centre, v = q - a.centre;
  double sweep = std::atan2(cross2(u, v), u.dot(v));
  if (a.turn > 0 && sweep < 0.0) sweep += 2.0 * std::numbers::pi;
  if (a.turn < 0 && sweep > 0.0) sweep -= 2.0 * std::numbers::pi;
  if (std::abs(sweep) > std::numbers::pi) return std::nullopt;
  a.sweep = sweep;
  return a;
}

}  // namespace

Vec2 CircleArc::point_at(double f) const {
  const Vec2 u = from - centre;
  const double a = std::atan2(u.y(), u.x()) + f * sweep;
  return centre + radius_m * Vec2(std::cos(a), std::sin(a));
}

std::optional<std::array<CircleArc, 2>> biarc(const Vec2& p0, const Vec2& t0, const Vec2& p1, const Vec2& t1) {
  const Vec2 v = p1 - p0, t = t0 + t1;
  const double vt = v.dot(t), vv = v.dot(v), a = 2.0 * (t0.dot(t1) - 1.0);
  if (vv == 0.0) return std::nullopt;
  double d = 0.0;
  if (std::abs(a) < 1e-12) {
    if (vt <= 0.0) return std::nullopt;
    d = vv / (2.0 * vt);
  } else {
    // a < 0: the product of the roots vv / a is negative, so exactly one is positive.
    d = (vt - std::sqrt(vt * vt - a * vv)) / a;
  }
  if (!(d > 0.0) || !std::isfinite(d)) return std::nullopt;
  const Vec2 q0 = p0 + d * t0, q1 = p1 - d * t1;
  const Vec2 j = 0.5 * (q0 + q1);
  const std::optional<CircleArc> first = arc_through(p0, t0, j);
  const std::optional<CircleArc> second = arc_through(p1, -t1, j);  // traced back from P1
  if (!first || !second) return std::nullopt;
  CircleArc back = *second;  // reversed: from J to P1
  std::swap(back.from, back.to);
  back.turn = -back.turn;
  back.sweep = -back.sweep;
  return std::array<CircleArc, 2>{*first, back};
}

}  // namespace deepguide
