#pragma once
// The 2-D vector of the local frame: x = easting, y = northing (m), and the
// two small formulas every planar module needs.

#include <Eigen/Core>
#include <algorithm>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {
using Vec2 = Eigen::Vector2d;

/// z of the 3-D cross product: positive when b lies anticlockwise of a.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Distance from p to the segment a-b (to a when the segment is a point).
inline double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

}  // namespace deepguide
