#pragma once
// The sea chart figure: depth shading of bathymetry rasters, land, hazards
// from hazard files and S-57 cells, further obstacles, and the no-go area for
// an operating depth; with a title, a scale bar, a north arrow pointing to
// TRUE north, and a legend of the depth bands.
//
// Decisions:
// - Depth shading in bands, shallow light to deep dark, as paper charts tint
//   their depth areas: about seven bands of a round step (1, 2, 2.5 or 5 x
//   10^k m) over the rasters' water depths. Land (depth <= 0) is beige, cells
//   without data light grey.
// - Rasters are read once, decimated by GDAL to about the map's size in
//   pixels (RasterIO with a smaller buffer), never whole; each map pixel then
//   takes the nearest buffer cell, through the CRS transform when the raster
//   is not in the local frame. Later rasters cover earlier ones.
// - The map is north-up in the local frame (grid north); the arrow is turned
//   by the meridian convergence so that it points to true north.
// - No-go (with depth_m): the rasters' no-go polygons (compute_no_go: too
//   shallow for depth + clearance, land, no data) in translucent red; hazards
//   the vehicle cannot pass over get a red danger line, the others a grey one.
// - Layout as the route chart's: title band | map | footer (scale bar, legend,
//   north arrow); sizes scale with width_px / 1200.

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/render/canvas.hpp"

namespace DEEPGUIDE_API deepguide {

struct ChartStyle {
  Rgba background = rgb_hex(0xffffff);
  Rgba shallow = rgb_hex(0xe3f2fd);  ///< the shallowest depth band
  Rgba deep = rgb_hex(0x2f6eaa);     ///< the deepest depth band
  Rgba land = rgb_hex(0xf0e2bd);
  Rgba nodata = rgb_hex(0xd9d9d9);
  Rgba sea = rgb_hex(0xeef4f9);       ///< map area outside every raster
  Rgba hazard = rgb_hex(0x2b2d31);    ///< footprints of chart hazards
  Rgba obstacle = rgb_hex(0x862e9c);  ///< footprints of further obstacles
  Rgba no_go = rgb_hex(0xe03131);     ///< no-go polygons (translucent, under land) and blocking hazards' danger lines
  Rgba passable = rgb_hex(0x6c757d);  ///< danger lines of hazards the vehicle passes over
  Rgba text = rgb_hex(0x212529);
  Rgba frame = rgb_hex(0x8a96a3);
};

struct ChartRenderOptions {
  std::vector<std::string> charts;     ///< bathymetry rasters, S-57 cells, hazard files
  std::vector<std::string> obstacles;  ///< further obstacle files (e.g. sonar contacts)
  /// Operating depth (m, positive down) for the no-go area; NaN = none.
  double depth_m = std::numeric_limits<double>::quiet_NaN();
  double clearance_m = 2.0;    ///< vertical clearance (m, >= 0)
  ChartOptions chart_options;  ///< how S-57 cells are read (zones of confidence, restricted areas)
  std::string local_crs;       ///< empty = UTM zone of the first chart's centre
  std::string source_crs;      ///< CRS of rasters that carry none (e.g. "EPSG:4326"); empty = they are an error
  std::string title;           ///< empty = the files' names and the depth
  int width_px = 1200;
  ChartStyle style;
  /// The part of the local frame to show; empty = everything the charts hold.
  WorldBox extent;
  /// Drawn on the map after the chart, clipped to it (a mission, routes,
  /// tracks: render/mission_figure.hpp); `unit` = width_px / 1200.
  std::function<void(Canvas&, const ViewTransform&, double unit)> overlay;
  /// The overlay's legend: a line in a colour (dashed or not) and its label,
  /// one row under the chart's own entries.
  struct LegendLine {
    Rgba color;
    double width_px = 2.0;
    bool dashed = false;
    std::string label;
  };
  std::vector<LegendLine> overlay_legend;
};

/// Where everything went, for callers and tests.
struct ChartLayout {
  int width = 0;
  int height = 0;
  double unit = 1.0;
  PixelRect map;
  PixelRect footer;
  WorldBox extent;                 ///< local frame (m)
  ViewTransform view;              ///< local frame -> pixels
  std::string frame_id;            ///< the local frame, e.g. "EPSG:32632"
  std::vector<double> band_edges;  ///< depth band edges (m), shallow to deep; empty without rasters
  std::vector<Rgba> band_colors;   ///< one per band (edges.size() - 1)
  double true_north_deg = 0.0;     ///< clockwise from the map's up to true north, at the centre
  std::size_t no_go_polygons = 0;
  std::size_t hazards = 0;
};

/// The colour of depth band i of n (0 = shallowest).
Rgba depth_band_color(const ChartStyle& style, std::size_t i, std::size_t n);

/// Draws the charts to `path` (.png or .svg). Atomic: a failure leaves no
/// file. Throws InputError (one line naming the file or option) for bad input.
ChartLayout render_chart(const ChartRenderOptions& options, const std::string& path);

}  // namespace deepguide
