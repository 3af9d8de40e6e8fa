#pragma once
// The union of a chart's no-go areas, robust and fast at the scale of a whole
// ENC cell (about 1,400 areas and 260,000 vertices, most of them on edges two
// no-go areas share).
//
// Why not Boost.Geometry's union: on US4MD81M at 7 m, Boost 1.74's cascaded
// union of the touching depth areas silently dropped a 14 km2 depth area
// (tests/charts/test_enc.cpp checks every feature is covered). GEOS's overlay
// (through OGR; GEOS 3.11's OverlayNG snaps and is robust) is used instead.
//
// Why it is fast: areas that tile the sea (S-57's "skin of the earth" of one
// cell: depth areas, land, unsurveyed areas, ... share their common edges
// vertex for vertex) need no overlay where two no-go areas meet. Every edge
// of the tiles is counted; an edge two no-go tiles share cancels, and the
// edges left bound the tiles' union. GEOS polygonizes them into faces; a
// face is kept when a point inside it lies in a tile (faces inside a
// free-water ring are holes). Only then are the other areas, which may
// overlap anything, joined by GEOS's cascaded union.
//
// Why it never fails on valid charts: at the scale of an exchange set, some
// of the areas GEOS is given are not valid polygons (Boost.Geometry's buffer
// of a 15,000-vertex coast, a difference along shared edges): GEOS then stops
// with a TopologyException ("side location conflict"). Every input GEOS finds
// invalid is repaired first (GEOS's MakeValid by its STRUCTURE method,
// polygonal parts kept: a ring over itself keeps what it covers twice), and a
// union that still fails is done again snap-rounded to a grid of
// kRepairGridM (GEOS's OverlayNG with a fixed precision, which is robust by
// construction). The result must also be valid for Boost.Geometry, which the
// planners and the obstacle reader use; where it is not (GEOS and Boost
// differ on a vertex a hair from an edge), it is snap-rounded too, which
// settles every case seen but two holes touching at a vertex that Boost
// still reads as crossing. Snap rounding moves an edge by at most
// kRepairGridM / sqrt(2) (0.7 mm); MakeValid keeps the area a ring encloses
// (a bow-tie's two lobes); callers that must lose none grow first.

#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

/// The grid (m) a repaired union is snap-rounded to.
inline constexpr double kRepairGridM = 1e-3;

/// Disjoint polygons, valid for GEOS and, where snap rounding makes them so,
/// for Boost.Geometry (a hole touching another at a vertex may stay that
/// Boost reads as crossing), covering every tile and every other area
/// (invalid ones as GEOS's MakeValid reads them).
/// `tiles` must not overlap one another (they may share edges and corners).
/// `grid_m` > 0 snap-rounds the whole union to that grid (vertices on it, no
/// vertex within half a cell of an edge it is not on: robust against the
/// round-off of a reprojection). Throws std::runtime_error when GDAL was
/// built without GEOS, or when even the snap-rounded union fails.
std::vector<BgPolygon> union_no_go(const std::vector<const BgPolygon*>& tiles,
                                   const std::vector<const BgPolygon*>& others, double grid_m = 0.0);

/// `area` less the union of `cuts` (keep_inside false), or the part of `area`
/// inside that union (keep_inside true), by GEOS's overlay with the same
/// repairs and snap-rounded retry as union_no_go. For where Boost.Geometry's
/// overlay of a depth area with the zones of confidence falls short (on
/// US4MD81M at 10 m, DEPARE/3863 less its eleven A1 zones: Boost lost the A1
/// water, and the whole area was taken as no-go, 950 m round free water).
/// Throws as union_no_go.
std::vector<BgPolygon> overlay_no_go(const BgMultiPolygon& area, const std::vector<const BgPolygon*>& cuts,
                                     bool keep_inside);

/// `polygon` (+) disc(`distance`) by GEOS's buffer (through OGR): round
/// joins whose vertices lie on the circle of `distance`, at most
/// 2 pi / `points_per_circle` apart (so the caller widens the distance for
/// chords that must stay outside a circle). For distances far beyond the
/// polygon's size, where Boost.Geometry's buffer fails. Throws
/// std::runtime_error when GDAL was built without GEOS or GEOS fails.
std::vector<BgPolygon> geos_buffer(const BgPolygon& polygon, double distance, int points_per_circle);

}  // namespace deepguide
