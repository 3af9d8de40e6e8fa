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

#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

/// Disjoint polygons covering every tile and every other area. `tiles` must
/// not overlap one another (they may share edges and corners). Throws
/// std::runtime_error when GEOS is unavailable or fails.
std::vector<BgPolygon> union_no_go(const std::vector<const BgPolygon*>& tiles,
                                   const std::vector<const BgPolygon*>& others);

}  // namespace deepguide
