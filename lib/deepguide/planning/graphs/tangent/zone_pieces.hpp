#pragma once
// Convex pieces of the safety zones, for the exact tangent graph.
//
// An elliptical obstacle's zone is one convex piece, ellipse (+) disc(d). A
// polygon obstacle's zone is covered by one capsule per edge, segment (+)
// disc(d) (a plain segment when d = 0): their union is the zone less interior
// no route from outside can reach, and every piece is convex, so tangents and
// boundary arcs follow from support functions:
//   ellipse: h(u) = u.c + sqrt(u^T A u) + d     capsule: h(u) = max(u.a, u.b) + d
// The boundary is parametrised by the angle phi of its outward normal
// u = (cos phi, sin phi); arc lengths run anticlockwise in phi.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct ZonePiece {
  enum class Kind { ellipse, capsule };
  Kind kind = Kind::ellipse;
  Ellipse ellipse;  ///< kind == ellipse
  /// kind == ellipse: unit vector along the major axis, cached from
  /// ellipse.theta (support functions run millions of times per graph).
  /// Set by zone_pieces(); keep it in step when changing theta.
  Vec2 axis{1.0, 0.0};
  Vec2 a, b;                 ///< kind == capsule: the edge (a == b: a disc)
  double margin = 0;         ///< d
  std::size_t obstacle = 0;  ///< obstacle index: ellipses first, then polygons (ObstacleField numbering)

  double support(const Vec2& u) const;
  /// The support function h(u) and the boundary point p with outward normal u
  /// (unit), which is also h's gradient: d/dphi h(u(phi)) = p . u'(phi).
  struct Support {
    double h;
    Vec2 p;
  };
  Support support_at(const Vec2& u) const;
  /// Boundary point with outward normal angle phi (on a capsule's flat side, an end of the side).
  Vec2 point_at_normal(double phi) const;
  /// Length of the boundary from normal angle phi0 anticlockwise to phi1 (phi1 >= phi0, any number of turns).
  double arc_length(double phi0, double phi1) const;
  /// Normal angles in [0, 2 pi) where the boundary has a straight side (capsules: two; ellipses: none).
  std::vector<double> flat_normals() const;
  /// Largest radius of curvature of the boundary (m).
  double max_curvature_radius() const;
  /// A point inside the piece.
  Vec2 inner_point() const;
  /// Radius of a disc around inner_point() that holds the piece.
  double bounding_radius() const;
  /// Distance from p to the piece's core: the ellipse (0 inside it) or the capsule's edge.
  double core_distance(const Vec2& p) const;
};

/// True when the two zones' interiors share a point, by a sufficient test: the
/// disc the zone holds round a point of its core (an ellipse's centre, a
/// capsule's ends) reaches into the other zone. Such pieces have no inner
/// common tangent (h_p(u) + h_q(-u) > 0 for every u), which the tangent graph
/// otherwise learns only from a dense search for a sign change.
bool zones_overlap(const ZonePiece& p, const ZonePiece& q);

/// The pieces of every obstacle's zone for margin d.
std::vector<ZonePiece> zone_pieces(const ObstacleSet& obstacles, double margin);

}  // namespace deepguide
