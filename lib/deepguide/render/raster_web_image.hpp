#pragma once
// A bathymetry raster's depth shading as a web map image
// (render/web_map.hpp): warped by GDAL into Web Mercator, the projection
// Leaflet draws in, so the image lies on the map cell for cell; shaded by
// depth in the web map's bands, land in its own colour, no data clear; kept
// in the page as a PNG (Cairo) in base64 (CPLBase64Encode).

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/render/web_map.hpp"

namespace DEEPGUIDE_API deepguide {

/// The raster at `path` (`source_crs` for one that carries none) as an image
/// at most `max_px` on its long side. Throws InputError naming the file.
WebMapImage raster_depth_image(const std::string& path, const std::string& source_crs, int max_px = 1600);

/// The fill of a depth (m, positive down) in the web map's bands, shallow to
/// deep (2, 5, 10, 20, 50, 100 m): the depth areas' and the rasters' shading.
const char* depth_band_fill(double depth_m);

}  // namespace deepguide
