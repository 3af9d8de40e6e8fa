#pragma once
// Tangents to ellipses: from an outside point, and the common tangents of two
// disjoint ellipses.
//
// From a point p: in the unit-circle frame q = to_unit(p), |q| > 1, the
// tangent points are at polar angle atan2(q) +- acos(1/|q|); map them back.
//
// Common tangents, via support functions: the line {x : n.x = k} with
// n = (cos phi, sin phi) touches ellipse i, which lies on the side n.x <= k,
// iff k = n.c_i + h_i(n). Hence
//   outer (both on the same side):       g_o(phi) = n.(c1 - c2) + h1(n) - h2(n) = 0
//   inner (ellipse 2 on the other side): g_i(phi) = n.(c1 - c2) + h1(n) + h2(n) = 0
// Two disjoint ellipses give exactly two roots of each. We bracket them by
// sampling phi, then solve with TOMS 748 (Boost.Math). Tangent point on
// ellipse i for normal n: support_point(n), or support_point(-n) for the
// inner tangents' second ellipse.

#include <array>
#include <optional>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

/// The two tangent points on `e` seen from `p`: `left` lies to the left of the
/// ray from p through the centre, `right` to the right. Empty if p is not
/// strictly outside the ellipse.
struct PointTangents {
  Vec2 left;
  Vec2 right;
};
std::optional<PointTangents> tangent_points(const Ellipse& e, const Vec2& p);

enum class TangentKind { outer, inner };

/// A common tangent line touching ellipse 1 at p1 and ellipse 2 at p2.
/// `normal` is the unit normal with ellipse 1 on the side normal.x <= normal.p1;
/// for an outer tangent ellipse 2 lies on that side too, for an inner one on the other.
struct CommonTangent {
  TangentKind kind;
  Vec2 p1;
  Vec2 p2;
  Vec2 normal;
};

/// The four common tangents (two outer, then two inner) of two disjoint
/// ellipses. Returns an empty vector when the ellipses overlap or touch
/// (fewer than four tangents exist then).
std::vector<CommonTangent> common_tangents(const Ellipse& e1, const Ellipse& e2);

}  // namespace deepguide
