#pragma once
// The no-go model of a bathymetry raster for an operating depth: where the sea
// floor plus a vertical clearance lies shallower than the operating depth the
// vehicle cannot go; land (elevation above the surface) is always no-go.
// The no-go cells become polygons in the local frame, simplified with a
// tolerance that never shrinks them, so planners can take them as polygonal
// obstacles.
//
// Decisions:
// - A cell is no-go iff its depth d (m, positive down, after the raster's sign
//   convention, bathymetry.hpp) satisfies d < operating_depth_m +
//   vertical_clearance_m, or d <= 0 (land, and the waterline itself), or it has
//   no data and nodata_is_no_go. At d == operating + clearance exactly the
//   vehicle keeps exactly the clearance: the cell is NOT no-go.
// - Polygons come from GDALPolygonize (4-connected cells) on a Byte mask that
//   is written window by window (a MEM raster for small rasters, a compressed
//   GeoTIFF in the temp folder for large ones); each polygon is the exact
//   outline of its cells (pixel edges), so before simplification every no-go
//   cell lies inside the union, and the union's area is the cells' area.
// - Outlines go to the frame through OSR. When the raster's CRS is not the
//   frame's (e.g. lon/lat grids), every outline edge is split at every cell
//   corner first, so each straight piece spans one cell; the true image of a
//   cell edge (a curve) then departs from its chord by at most L^2 k / 8 (L the
//   cell size, k the curvature of a parallel or meridian in the frame, about
//   tan(lat)/6.4e6 per m in UTM): under 1 mm for the 90 m cells of a 3"
//   grid, about 3 cm for 1 km cells at 60 deg latitude.
// - Simplification never shrinks the no-go area: each exact polygon P is
//   buffered outward by tol/2 (round joins, 16 points per circle), then
//   Douglas-Peucker simplified with 0.45 tol. Every chord DP keeps lies within
//   0.45 tol of the buffered boundary, which lies at least tol/2 cos(pi/16)
//   = 0.49 tol from P, so the chords stay outside P, holes included, and
//   every simplified point is within 0.95 tol of P. The result is checked
//   (valid, covers P); where the check fails the plain buffer is kept. Results
//   that overlap are merged (Boost.Geometry union), so the polygons returned
//   are disjoint. Tolerance 0 returns the exact outlines (disjoint interiors,
//   diagonal neighbours may touch at a corner).
// - Memory: the band is read in windows of whole rows of blocks and each
//   window's cache is dropped after use; the mask is polygonized line by line
//   and its cache dropped as it goes; each polygon is simplified as GDAL emits
//   it, so only simplified polygons are kept.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

struct NoGoOptions {
  /// Operating depth of the vehicle (m, positive down). Required (finite, >= 0).
  double operating_depth_m = std::numeric_limits<double>::quiet_NaN();
  /// Water kept between the vehicle and the sea floor (m, >= 0).
  double vertical_clearance_m = 2.0;
  /// Largest distance (m) the simplified boundary may lie OUTSIDE the exact
  /// cell boundary; it never lies inside it. 0 = no simplification.
  double simplify_tolerance_m = 5.0;
  /// Cells without data (NoData, NaN) are no-go: unknown water is not safe water.
  bool nodata_is_no_go = true;
  /// How to read the raster (sign convention, band, assumed CRS, window size).
  BathymetryOptions bathymetry;
};

struct NoGoArea {
  /// No-go polygons in the local frame (ids "nogo/N"); every no-go cell lies inside their union.
  std::vector<PolygonObstacle> polygons;
  std::size_t no_go_cells = 0;  ///< cells that are no-go (too shallow, land, or NoData if so chosen)
  std::size_t total_cells = 0;
  double area_m2 = 0;  ///< area of the polygons' union (after simplification)
  /// Distinct vertices (a ring's closing point is not counted): "before" counts the
  /// cells' outline corners as polygonized, "after" the polygons returned.
  std::size_t vertices_before_simplify = 0;
  std::size_t vertices_after_simplify = 0;
  double cell_area_m2 = 0;  ///< area of one cell in the frame, at the raster's centre
  BathymetryInfo raster;    ///< the raster's header (the scan fields are left empty)
};

/// The default local frame for a raster: the UTM zone of its centre (reads the header only).
/// Throws InputError as compute_no_go does for an unreadable raster or one without CRS.
LocalFrame raster_local_frame(const std::string& path, const BathymetryOptions& options = {});

/// The raster's coverage in `frame`: its outline (the cells' outer edges, in
/// its own CRS) sampled every few cells along each side and transformed, as a
/// polygon. Routes over a raster must stay inside it: outside the chart the
/// depth is not known (plan refuses such a route; docs/PLANNING.md).
BgPolygon raster_coverage(const std::string& path, const LocalFrame& frame, const BathymetryOptions& options = {});

/// Reads the raster at `path` window by window and returns its no-go polygons
/// in `frame`. Throws InputError (one line naming the file and the option)
/// for an unreadable raster, a raster without CRS, or bad options.
NoGoArea compute_no_go(const std::string& path, const LocalFrame& frame, const NoGoOptions& options);

/// The no-go polygons of a sea floor already in the frame (what the 3-D
/// checkers see, so a route planned around them passes those checkers): each
/// grid cell between four nodes takes the shallowest of them (a bilinear
/// patch is never shallower than its shallowest corner), and the cells go
/// through the same mask, polygonize and simplify as a raster file's (an
/// in-memory GeoTIFF in the frame's CRS; options.bathymetry is ignored).
/// Outside the grid there are no polygons. Throws InputError for bad options.
NoGoArea compute_no_go(const SeaFloor& floor, const LocalFrame& frame, const NoGoOptions& options);

}  // namespace deepguide
