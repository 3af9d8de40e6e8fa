#pragma once
// Segment against ellipse. In the unit-circle frame the segment stays a
// segment p(t) = q0 + t (q1 - q0), t in [0, 1], and the boundary crossings are
// the roots of |p(t)|^2 = 1, a quadratic in t.

#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

/// Parameters t in [0, 1] (ascending) where the segment p0 -> p1 crosses or
/// touches the boundary of `e`.
std::vector<double> segment_boundary_crossings(const Ellipse& e, const Vec2& p0, const Vec2& p1);

/// True if some point of the closed segment lies strictly inside the ellipse.
/// A segment that only touches the boundary (a tangent) does not intersect.
bool segment_intersects(const Ellipse& e, const Vec2& p0, const Vec2& p1);

}  // namespace deepguide
