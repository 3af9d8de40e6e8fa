#pragma once
// Biarcs: two circular arcs, joined with a common tangent, from a point P0
// with unit tangent T0 to a point P1 with unit tangent T1. A smooth curve
// sampled at points with their tangents becomes a chain of arcs with no
// corner anywhere, which a vehicle can sail at its turning radius and which
// route formats carry as arcs (RTZ's radius, a loiter) instead of as many
// short lines.
//
// The equal-chord biarc: control points Q0 = P0 + d T0 and Q1 = P1 - d T1 with
// |Q1 - Q0| = 2d; the arcs meet at J = (Q0 + Q1) / 2, tangent to Q1 - Q0
// there. With v = P1 - P0 and t = T0 + T1 that is the quadratic
//   2 (T0.T1 - 1) d^2 - 2 (v.t) d + v.v = 0,
// whose positive root is d; parallel tangents (T0.T1 = 1) give
// d = v.v / (2 v.t). The arc tangent to T at P through J has its centre on
// P's normal n at signed distance r = |J - P|^2 / (2 n.(J - P)).

#include <array>
#include <optional>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct CircleArc {
  Vec2 from{0.0, 0.0}, to{0.0, 0.0}, centre{0.0, 0.0};
  double radius_m = 0.0;
  int turn = 0;        ///< +1 anticlockwise (turning left), -1 clockwise
  double sweep = 0.0;  ///< signed angle swept (rad), the sign of turn

  double length_m() const { return radius_m * (sweep < 0.0 ? -sweep : sweep); }
  /// The point a fraction f in [0, 1] of the way along it.
  Vec2 point_at(double f) const;
};

/// The equal-chord biarc (header); nullopt when it does not exist as two
/// proper arcs (the tangents lead away from each other, or an arc would be
/// a straight line or sweep more than a half turn).
std::optional<std::array<CircleArc, 2>> biarc(const Vec2& p0, const Vec2& t0, const Vec2& p1, const Vec2& t1);

}  // namespace deepguide
