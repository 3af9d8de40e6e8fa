#include "deepguide/simulation/path_following.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "deepguide/core/angles.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"

namespace deepguide {
namespace {
constexpr double kMaxLedTurn = 150.0 * std::numbers::pi / 180.0;
}  // namespace

PathPoint nearest_on_leg(const RouteLeg& leg, const Vec2& p) {
  PathPoint q;
  if (leg.kind == RouteLeg::Kind::line) {
    const Vec2 d = leg.to - leg.from;
    const double len = d.norm();
    q.tangent = len > 0.0 ? Vec2(d / len) : Vec2(1.0, 0.0);
    const double along = (p - leg.from).dot(q.tangent);
    q.past_end = along >= len;
    q.point = leg.from + std::clamp(along, 0.0, len) * q.tangent;
    q.to_end_m = len - std::clamp(along, 0.0, len);
    const Vec2 r = p - q.point;
    q.left_m = q.tangent.x() * r.y() - q.tangent.y() * r.x();
    return q;
  }
  // The nearest point of core (+) disc(offset) has the normal from the core's
  // nearest point towards p.
  const Ellipse& e = leg.core;
  Vec2 from_core = e.a == e.b ? Vec2(p - e.centre) : Vec2(p - project_to_ellipse(e, p).point);
  if (from_core.norm() == 0.0) from_core = arc_point(leg, leg.phi_from) - e.centre;
  double phi = std::atan2(from_core.y(), from_core.x());
  // Unwrap next to the arc's middle, then clamp to the arc in the direction of travel.
  const double mid = 0.5 * (leg.phi_from + leg.phi_to);
  phi = mid + wrap_pi(phi - mid);
  const double lo = std::min(leg.phi_from, leg.phi_to), hi = std::max(leg.phi_from, leg.phi_to);
  q.past_end = leg.turn > 0 ? phi >= leg.phi_to : phi <= leg.phi_to;
  phi = std::clamp(phi, lo, hi);
  q.point = arc_point(leg, phi);
  const Vec2 u(std::cos(phi), std::sin(phi));
  q.tangent = leg.turn * Vec2(-u.y(), u.x());
  const double rho = offset_ellipse_radius(e, leg.offset_m, phi);
  q.curvature = leg.turn / rho;
  // Along the arc to its end: at most the largest radius per radian.
  q.to_end_m = std::abs(leg.phi_to - phi) * (e.b > 0.0 ? e.a * e.a / e.b + leg.offset_m : leg.offset_m);
  q.left_m = -leg.turn * (p - q.point).dot(u);  // left of anticlockwise travel is inwards
  return q;
}

PathFollower::Command PathFollower::steer(const Vec2& position, const Vec2& ground_velocity) {
  Command cmd;
  // How far before leg k's end the next leg is taken: a corner's tangent length.
  const auto corner_lead = [&](std::size_t k) {
    if (corner_radius_m <= 0.0) return 0.0;
    const Vec2 u = leg_direction(legs[k], true), v = leg_direction(legs[k + 1], false);
    const double turn = std::min(std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)), kMaxLedTurn);
    return turn > 1e-6 ? corner_radius_m * std::tan(0.5 * turn) : 0.0;
  };
  PathPoint q = nearest_on_leg(legs[leg], position);
  while (leg + 1 < legs.size() && (q.past_end || q.to_end_m < corner_lead(leg))) {
    q = nearest_on_leg(legs[++leg], position);
  }
  cmd.to_end_m = q.to_end_m;
  cmd.at_end = q.past_end && leg + 1 == legs.size();
  const double l = lookahead_m, e = q.left_m;
  const double alpha = std::atan2(q.tangent.y(), q.tangent.x());
  cmd.course = wrap_pi(alpha - std::atan(e / l));
  cmd.left_m = e;
  const Vec2 n(-q.tangent.y(), q.tangent.x());
  // The curvature lead_m ahead: the next leg's start when this leg ends sooner.
  double ahead = q.curvature;
  double along = q.to_end_m;
  for (std::size_t k = leg + 1; along < lead_m && k < legs.size(); ++k) {
    const RouteLeg& next = legs[k];
    ahead = next.kind == RouteLeg::Kind::arc
                ? next.turn / offset_ellipse_radius(next.core, next.offset_m, next.phi_from)
                : 0.0;
    along += next.length_m;
  }
  // The parallel curve through the vehicle: radius rho - e on a left turn.
  double kappa = 0.0;
  if (ahead != 0.0) {
    const double rho = 1.0 / ahead;  // signed
    kappa = std::abs(rho - e) > 1e-3 ? 1.0 / (rho - e) : 0.0;
  }
  cmd.course_rate = kappa * ground_velocity.dot(q.tangent) - l * ground_velocity.dot(n) / (l * l + e * e);
  return cmd;
}

}  // namespace deepguide
