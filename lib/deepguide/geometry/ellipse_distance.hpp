#pragma once
// Exact distance from a point to an ellipse (Eberly, "Distance from a point to
// an ellipse, an ellipsoid, or a hyperellipsoid", Geometric Tools 2013).
//
// In the ellipse frame, reflected into the first quadrant (y0, y1 >= 0,
// e0 >= e1), the closest boundary point is x_i = e_i^2 y_i / (t + e_i^2) where
// t is the unique root of F(t) = sum (e_i y_i / (t + e_i^2))^2 - 1 on
// t > -e1^2. F is strictly decreasing there, so bisection in double precision
// converges to the last bit without any starting guess: robust for points
// inside, outside, on the axes and at the centre.

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

struct EllipseProjection {
  Vec2 point;       ///< closest point on the boundary
  double distance;  ///< unsigned distance to the boundary
  bool inside;      ///< the query point is strictly inside
  double signed_distance() const { return inside ? -distance : distance; }
};

/// Closest boundary point of `e` to `p` and the distance to it.
EllipseProjection project_to_ellipse(const Ellipse& e, const Vec2& p);

/// Signed distance to the boundary: negative inside, positive outside.
double signed_distance(const Ellipse& e, const Vec2& p);

}  // namespace deepguide
