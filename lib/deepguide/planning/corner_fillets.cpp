#include "deepguide/planning/corner_fillets.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace {

constexpr double kStraight = 1e-9;  // rad: a corner turning less is left as it is

void add_line(std::vector<RouteLeg>& legs, const Vec2& from, const Vec2& to) {
  const double length = (to - from).norm();
  if (length <= 1e-9) return;
  legs.push_back(line_leg(from, to));
}

std::vector<Vec2> distinct_points(const std::vector<Vec2>& polyline) {
  std::vector<Vec2> p;
  for (const Vec2& q : polyline) {
    if (!q.allFinite()) throw InputError("route: expected finite waypoints");
    if (p.empty() || (q - p.back()).norm() > 0.0) p.push_back(q);
  }
  if (p.size() < 2) throw InputError("route: expected at least two distinct waypoints");
  return p;
}

void check_radius(double radius) {
  if (!std::isfinite(radius) || radius <= 0.0) {
    throw InputError("turn radius: expected a radius > 0 m, got " + general(radius));
  }
}

// Signed turn at each corner (0 at the ends and where it is below kStraight).
std::vector<double> turns(const std::vector<Vec2>& p) {
  std::vector<double> turn(p.size(), 0.0);
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Vec2 u = (p[i] - p[i - 1]).normalized(), v = (p[i + 1] - p[i]).normalized();
    turn[i] = std::atan2(cross(u, v), u.dot(v));
    if (std::abs(turn[i]) < kStraight) turn[i] = 0.0;
  }
  return turn;
}

// Each corner's tangent length R tan(|turn| / 2).
std::vector<double> tangents(const std::vector<double>& turn, double radius) {
  std::vector<double> t(turn.size());
  for (std::size_t i = 0; i < turn.size(); ++i) t[i] = radius * std::tan(0.5 * std::abs(turn[i]));
  return t;
}

// The first leg i (from p[i] to p[i + 1]) whose two fillets overlap, if any.
std::optional<std::size_t> first_overlap(const std::vector<Vec2>& p, const std::vector<double>& tangent) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if (tangent[i] + tangent[i + 1] > (p[i + 1] - p[i]).norm() * (1.0 + 1e-12) + 1e-12) return i;
  }
  return std::nullopt;
}

}  // namespace

std::vector<Vec2> join_tight_corners(const std::vector<Vec2>& polyline, double radius) {
  check_radius(radius);
  std::vector<Vec2> p = distinct_points(polyline);
  while (p.size() > 3) {
    const std::vector<double> turn = turns(p);
    const std::optional<std::size_t> leg = first_overlap(p, tangents(turn, radius));
    if (!leg || *leg == 0 || *leg + 2 >= p.size()) break;  // fits, or a corner beside an end
    const std::size_t i = *leg;
    if (turn[i] * turn[i + 1] <= 0.0 || std::abs(turn[i] + turn[i + 1]) >= 0.99 * std::numbers::pi) break;
    // p[i - 1] + s u meets p[i + 2] - r v: the corner both legs reach.
    const Vec2 u = (p[i] - p[i - 1]).normalized(), v = (p[i + 2] - p[i + 1]).normalized();
    const double s = cross(p[i + 2] - p[i - 1], v) / cross(u, v);
    const Vec2 corner = p[i - 1] + s * u;
    if (!corner.allFinite() || s <= (p[i] - p[i - 1]).norm() || (p[i + 2] - corner).dot(v) <= 0.0) break;
    p[i] = corner;
    p.erase(p.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  }
  return p;
}

FilletedRoute fillet_corners(const std::vector<Vec2>& polyline, double radius) {
  check_radius(radius);
  const std::vector<Vec2> p = distinct_points(polyline);
  const std::size_t n = p.size();
  const std::vector<double> turn = turns(p);
  const std::vector<double> tangent = tangents(turn, radius);
  FilletedRoute out;
  if (const std::optional<std::size_t> leg = first_overlap(p, tangent)) {
    out.too_tight = tangent[*leg] > 0.0 ? *leg : *leg + 1;
    return out;
  }
  Vec2 at = p.front();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (turn[i] == 0.0) continue;
    const Vec2 u = (p[i] - p[i - 1]).normalized(), v = (p[i + 1] - p[i]).normalized();
    const double side = turn[i] > 0.0 ? 1.0 : -1.0;
    const Vec2 t1 = p[i] - tangent[i] * u, t2 = p[i] + tangent[i] * v;
    const Vec2 centre = t1 + radius * side * Vec2(-u.y(), u.x());
    add_line(out.legs, at, t1);
    RouteLeg arc = circle_leg(centre, radius, std::atan2(t1.y() - centre.y(), t1.x() - centre.x()), turn[i]);
    arc.from = t1;  // exactly the tangent points, which the lines end and begin at
    arc.to = t2;
    out.legs.push_back(arc);
    at = t2;
  }
  add_line(out.legs, at, p.back());
  return out;
}

}  // namespace deepguide
