#pragma once
// Safety zones as polygons, the input of the polygon-based graphs.
//
// Every zone is enclosed, never approximated from inside: an ellipse's zone by
// its support-function polygon (geometry/safety_zone.hpp); a polygon
// obstacle's zone, polygon (+) disc(d), by Boost.Geometry's buffer with round
// joins at the distance d / cos(pi / n): the joins' chords then stay outside
// the disc of radius d and the straight sides d (1 / cos(pi / n) - 1) <= tol
// farther out than needed (a margin over 50 times the polygon's size is grown
// in steps that share the tolerance: Boost's buffer takes a polygon far
// smaller than the distance for a point). Overlapping zones are merged (Boost.Geometry
// union; groups of more than 64 overlapping zones, a chart's coast with its
// hazards, through GEOS: world/no_go_union.hpp), so no vertex of one zone
// hides inside another.

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct ZoneOptions {
  double margin = 0.0;      ///< safety margin d >= 0 (m)
  double tolerance = 0.05;  ///< largest distance of a polygon vertex outside its zone (m), > 0
};

/// The enclosing polygon of one polygon obstacle's zone (several parts if it
/// has several after buffering; normally one).
BgMultiPolygon polygon_zone(const BgPolygon& footprint, const ZoneOptions& options);

/// Enclosing polygons of every obstacle's zone, overlapping ones merged.
BgMultiPolygon merged_zone_polygons(const ObstacleSet& obstacles, const ZoneOptions& options);

/// Adds zone polygons found later (a detection's) to merged ones: each is
/// united (GEOS, world/no_go_union.hpp) with the polygons it meets, and the
/// rest are left as they are, so `merged` stays a set of polygons that do
/// not overlap.
void add_zone_polygons(BgMultiPolygon& merged, const BgMultiPolygon& added);

}  // namespace deepguide
