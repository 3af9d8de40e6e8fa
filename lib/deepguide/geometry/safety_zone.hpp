#pragma once
// The safety zone of an elliptical obstacle for a margin d: every point closer
// than d to the ellipse, i.e. the Minkowski sum ellipse (+) disc(d). Its
// boundary is the offset curve of the ellipse, which is NOT an ellipse: the
// ellipse with both semi-axes grown by d keeps only ~0.87 d of clearance at
// a = 10, b = 2, d = 5 (docs/PLANNING.md, "Safety zones"; tests/geometry/test_safety_zone.cpp).
//
// Enclosing polygon. The support function of a Minkowski sum is the sum of the
// support functions, h(u) = u.c + sqrt(u^T A u) + d, so every half-plane
// u.x <= h(u) contains the zone and their intersection over a set of normals
// encloses it, with each edge touching the zone. Vertices are intersections of
// consecutive lines. The normals are refined adaptively: an angular interval is
// split while its vertex lies farther than the tolerance outside the zone,
// measured exactly with the point-to-ellipse distance. Elongated ellipses thus
// get their vertices where the curvature is, not uniformly.

#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

struct SafetyZone {
  Ellipse ellipse;
  double margin = 0.0;  ///< d >= 0 (m)

  /// Support function of the zone for a unit vector u.
  double support(const Vec2& u) const;
  /// Distance from p to the zone's boundary, negative inside the zone.
  double signed_distance(const Vec2& p) const;
  /// True if p is closer than the margin to the ellipse (or inside it).
  bool contains(const Vec2& p) const;
};

struct ZonePolygonOptions {
  double tolerance = 0.05;  ///< largest allowed distance of a vertex outside the zone (m), > 0
  int max_vertices = 4096;  ///< refinement stops here even if the tolerance is not met
};

/// Vertices, counter-clockwise, of a convex polygon enclosing the zone whose
/// vertices lie at most `tolerance` outside it.
std::vector<Vec2> enclosing_polygon(const SafetyZone& zone, const ZonePolygonOptions& options = {});

/// The same polygon as a Boost.Geometry polygon (closed, clockwise ring).
BgPolygon enclosing_bg_polygon(const SafetyZone& zone, const ZonePolygonOptions& options = {});

}  // namespace deepguide
