#pragma once
// Going around an object (the seed's Figs. 15-16; docs/IDENTIFICATION.md,
// "Going around"): the path at distance D from the object's ellipse, its true offset
// curve (not a scaled ellipse, which would run closer than D along the flat
// sides).
//
// Parametrised by the ellipse parameter t of the foot point
// q(t) = c + a cos t u + b sin t v (u, v the major and minor axis directions):
//   o(t) = q(t) + D n(t),   n the outward unit normal at q(t).
// Its tangent is the ellipse's tangent at q(t) (the normal does not turn
// relative to it), and its radius of curvature is the ellipse's plus D:
//   rho(t) = (a^2 sin^2 t + b^2 cos^2 t)^(3/2) / (a b) + D,
// smallest at the ends of the major axis: b^2 / a + D. A vehicle that cannot
// turn that tightly cannot follow the path (offset_path_fits).
// The nearest point of the offset curve to a point p outside the object is
// q + D n(q) with q the nearest ellipse point to p (convexity: the normals
// of a convex curve do not cross outside it), and the signed distance to the
// path is dist(p, ellipse) - D (negative between the object and the path).

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/biarc.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

/// The offset curve's point for ellipse parameter t.
Vec2 offset_point(const Ellipse& object, double distance_m, double t);

/// Its unit tangent at t, anticlockwise (the direction of increasing t).
Vec2 offset_tangent(const Ellipse& object, double t);

/// Curvature of the offset curve at t (1/m, > 0: it turns anticlockwise with t): 1 / rho(t).
double offset_curvature(const Ellipse& object, double distance_m, double t);

/// Smallest radius of curvature of the offset curve: b^2 / a + D.
double offset_min_radius(const Ellipse& object, double distance_m);

struct OffsetProjection {
  Vec2 point;             ///< nearest point of the offset curve
  double t = 0.0;         ///< its ellipse parameter, in (-pi, pi]
  Vec2 tangent;           ///< unit tangent there, anticlockwise
  double signed_m = 0.0;  ///< distance from the path: positive outside it, negative between it and the object
};

/// The nearest point of the offset curve to `p` (header). Inside the object
/// the nearest ellipse point is used alike (signed_m < -D).
OffsetProjection project_to_offset(const Ellipse& object, double distance_m, const Vec2& p);

/// One lap of the offset path, anticlockwise from the point of parameter t0
/// back to it, as circular arcs with no corner between them: biarcs
/// (geometry/biarc.hpp) between points of the path with its tangents there,
/// halved until every arc lies within `tolerance_m` of the path.
std::vector<CircleArc> offset_lap_arcs(const Ellipse& object, double distance_m, double t0, double tolerance_m);

/// Throws InputError when a vehicle turning at most with `turn_radius_m`
/// cannot follow the offset path (its smallest radius is smaller), naming
/// the object, both radii and the smallest distance that fits.
void check_offset_path_fits(const Ellipse& object, double distance_m, double turn_radius_m, const std::string& name);

}  // namespace deepguide
