#pragma once
// Polygon operations that never shrink an area: what a no-go area may be
// turned into before planners see it (raster no-go, ENC no-go).
//
// simplify_outward(P, tol): P buffered outward by tol/2 (round joins, 16
// points per circle), then Douglas-Peucker simplified with 0.45 tol. Every
// chord DP keeps lies within 0.45 tol of the buffered boundary, which lies at
// least tol/2 cos(pi/16) = 0.49 tol from P, so the chords stay outside P,
// holes included, and every simplified point is within 0.95 tol of P. The
// result is checked (valid, covers P); where the check fails the plain buffer
// is kept.
//
// merge_overlapping: polygons whose envelopes overlap are joined by a
// cascaded (pairwise, balanced) Boost.Geometry union, so the result is
// disjoint; polygons far from all others pass untouched.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

/// Contains `exact`, lies within 0.95 tol of it (tol > 0).
BgMultiPolygon simplify_outward(const BgPolygon& exact, double tol);

/// The union of `polys` as disjoint polygons.
std::vector<BgPolygon> merge_overlapping(std::vector<BgPolygon> polys);

/// Distinct vertices of a polygon (a ring's closing point not counted).
std::size_t distinct_vertices(const BgPolygon& p);

}  // namespace deepguide
