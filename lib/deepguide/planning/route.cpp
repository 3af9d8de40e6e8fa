#include "deepguide/planning/route.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace deepguide {

double Route::length() const {
  const bool in_depth = depth_m.size() == points.size();
  double sum = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double dz = in_depth ? depth_m[i] - depth_m[i - 1] : 0.0;
    sum += std::hypot((points[i] - points[i - 1]).norm(), dz);
  }
  return sum;
}

Vec2 Route::point_at(double s) const {
  if (points.empty()) return Vec2(0.0, 0.0);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double len = (points[i + 1] - points[i]).norm();
    if (s <= len)
      return len > 0.0 ? Vec2(points[i] + (std::max(s, 0.0) / len) * (points[i + 1] - points[i])) : points[i];
    s -= len;
  }
  return points.back();
}

Vec2 leg_direction(const RouteLeg& leg, bool at_end) {
  if (leg.kind == RouteLeg::Kind::line) {
    const Vec2 d = leg.to - leg.from;
    return d.norm() > 0.0 ? Vec2(d.normalized()) : Vec2(1.0, 0.0);
  }
  const double phi = at_end ? leg.phi_to : leg.phi_from;
  return leg.turn * Vec2(-std::sin(phi), std::cos(phi));
}

RouteLeg line_leg(const Vec2& from, const Vec2& to) {
  RouteLeg leg;
  leg.from = from;
  leg.to = to;
  leg.length_m = (to - from).norm();
  return leg;
}

RouteLeg circle_leg(const Vec2& centre, double radius, double phi_from, double sweep) {
  RouteLeg leg;
  leg.kind = RouteLeg::Kind::arc;
  leg.turn = sweep >= 0.0 ? 1 : -1;
  leg.radius_m = radius;
  leg.length_m = radius * std::abs(sweep);
  leg.core = Ellipse{centre, 0.0, 0.0, 0.0};
  leg.offset_m = radius;
  leg.phi_from = phi_from;
  leg.phi_to = phi_from + sweep;
  leg.from = arc_point(leg, leg.phi_from);
  leg.to = arc_point(leg, leg.phi_to);
  return leg;
}

double offset_ellipse_radius(const Ellipse& e, double offset, double phi) {
  const double c = std::cos(phi - e.theta), s = std::sin(phi - e.theta);
  const double h = std::sqrt(e.a * e.a * c * c + e.b * e.b * s * s);
  if (h <= 0.0) return offset;
  return e.a * e.a * e.b * e.b / (h * h * h) + offset;
}

Vec2 arc_point(const RouteLeg& leg, double phi) {
  const Vec2 u(std::cos(phi), std::sin(phi));
  // A point core (a polygon corner's) is its own support point.
  const Vec2 core = leg.core.a > 0.0 ? leg.core.support_point(u) : leg.core.centre;
  return core + leg.offset_m * u;
}

double least_offset_ellipse_radius(const Ellipse& e, double offset, double lo, double hi) {
  double best = std::min(offset_ellipse_radius(e, offset, lo), offset_ellipse_radius(e, offset, hi));
  const double first_tip = e.theta + std::numbers::pi * std::ceil((lo - e.theta) / std::numbers::pi);
  if (first_tip <= hi) best = std::min(best, offset_ellipse_radius(e, offset, first_tip));
  return best;
}

double min_turn_radius(const RouteLeg& leg) {
  if (leg.kind != RouteLeg::Kind::arc) return std::numeric_limits<double>::infinity();
  return least_offset_ellipse_radius(leg.core, leg.offset_m, std::min(leg.phi_from, leg.phi_to),
                                     std::max(leg.phi_from, leg.phi_to));
}

}  // namespace deepguide
