#pragma once
// A bathymetry raster read for pictures: the charts module opens the file and
// reads its cells, the render module only colours what it is given.
//  - raster_outline: points of the frame whose box holds the raster (its
//    corners when it is in the frame's CRS, else its lon/lat extent's edges
//    sampled), for a map's extent;
//  - sample_raster_depths: the depth under each of a picture's points, from
//    one decimated read of the window they span (nearest cells: half again
//    the picture's pixels, so no pixel misses a cell it would show);
//  - raster_depths_web_mercator: the raster warped by GDAL into Web Mercator
//    (bilinear), the projection Leaflet draws in, at most max_px a side.
// Depths are metres, positive down, in the raster's vertical sense
// (bathymetry.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/world/extent.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

std::vector<Vec2> raster_outline(const std::string& path, const BathymetryOptions& read, const BathymetryInfo& info,
                                 const LocalFrame& frame);

struct RasterDepths {
  enum class State : std::uint8_t { outside, no_data, depth };
  std::vector<State> state;     ///< per point
  std::vector<double> depth_m;  ///< per point, where state is depth
};

/// The depth under each point (frame coordinates) of a picture `width` x
/// `height` pixels (the points are its pixels, row by row). Throws InputError
/// naming the file for a raster it cannot read or a CRS PROJ cannot transform to the frame's.
RasterDepths sample_raster_depths(const std::string& path, const BathymetryOptions& read, const LocalFrame& frame,
                                  const std::vector<Vec2>& points, int width, int height);

struct WebMercatorDepths {
  int width = 0, height = 0;
  std::vector<double> depth_m;  ///< row by row from the north; NaN where there is no data
  LonLatExtent bounds;          ///< the grid's box in lon/lat (Web Mercator's corners)
};

/// The raster at `path` (`source_crs` for one that carries none) in Web
/// Mercator, at most `max_px` on its long side. Throws InputError naming the file.
WebMercatorDepths raster_depths_web_mercator(const std::string& path, const std::string& source_crs, int max_px);

}  // namespace deepguide
