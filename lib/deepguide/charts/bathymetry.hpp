#pragma once
// Bathymetry rasters read through GDAL: GeoTIFF, BAG, NetCDF/GMT grids, ESRI
// ASCII grids, and whatever else GDAL opens as a raster.
//
// Decisions (to be mirrored in docs/FORMATS.md):
// - Depth is positive down (README.md, "Conventions"). A file holds either
//   elevation (up positive, the sea floor negative: GDAL, GMT, NOAA, BAG) or
//   depth (down positive). VerticalSense::automatic looks where the file says:
//   a "positive" attribute (CF/NetCDF: up or down), the BAG driver (elevation
//   by the BAG specification), then the band's description, long_name or
//   variable name ("depth" vs "elevation", "height", "topography", "z");
//   without any of these it assumes elevation and says so in sense_reason.
//   Under the elevation convention depth = -elevation.
// - NoData cells (the band's NoData value, compared at the band's precision)
//   and NaN cells are not valid and are skipped.
// - A raster must have a CRS, from the file, from CF lon/lat axes
//   (units degrees_east / degrees_north, taken as EPSG:4326), or from
//   BathymetryOptions::assumed_crs; otherwise the read fails, naming the file.
// - Rasters larger than memory: the band is never read whole. It is scanned in
//   windows aligned to the band's natural blocks (GetBlockSize) holding at most
//   BathymetryOptions::max_window_cells cells.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/world/extent.hpp"

namespace DEEPGUIDE_API deepguide {

enum class VerticalSense {
  elevation,  ///< up positive: the sea floor is negative
  depth,      ///< down positive
  automatic,  ///< from the file's metadata, else elevation (see the header comment)
};

struct BathymetryOptions {
  VerticalSense sense = VerticalSense::automatic;
  /// CRS for rasters without one, e.g. "EPSG:4326"; empty = such a raster is an error.
  std::string assumed_crs;
  /// 1-based band holding the heights.
  int band = 1;
  /// GDAL open options, e.g. {"MODE=RESAMPLED_GRID"} for a variable-resolution BAG.
  std::vector<std::string> open_options;
  /// Largest window read at once (cells); windows are whole blocks, at least one.
  std::size_t max_window_cells = std::size_t{1} << 22;
};

struct BathymetryInfo {
  std::string path;
  std::string driver;      ///< GDAL short name, e.g. "GTiff", "BAG", "netCDF", "AAIGrid"
  std::string crs;         ///< "EPSG:n" or the CRS's name
  std::string crs_wkt;     ///< the CRS used, as WKT
  std::string crs_source;  ///< "file", "CF lon/lat axes" or "assumed (option)"
  int width = 0;
  int height = 0;
  double pixel_x = 0;   ///< geotransform pixel size, x (CRS units)
  double pixel_y = 0;   ///< geotransform pixel size, y (negative for north-up rasters)
  LonLatExtent extent;  ///< of the raster's outer edges, WGS 84 lon/lat
  bool has_nodata = false;
  double nodata = std::numeric_limits<double>::quiet_NaN();
  /// Range of the valid cells as DEPTH (m, positive down) after the sign convention; NaN if none.
  double min_depth_m = std::numeric_limits<double>::quiet_NaN();
  double max_depth_m = std::numeric_limits<double>::quiet_NaN();
  std::size_t valid_cells = 0;
  double valid_fraction = 0;  ///< valid cells / all cells
  std::size_t windows_read = 0;
  VerticalSense sense_used = VerticalSense::elevation;
  std::string sense_reason;
};

/// Opens the raster at `path` and scans band `options.band` window by window
/// (never the whole raster at once). Throws InputError (one line naming the
/// file) for a missing file, a file GDAL cannot open as a raster, a missing
/// band, a raster without CRS and no assumed_crs, or a read failure.
BathymetryInfo inspect_bathymetry(const std::string& path, const BathymetryOptions& options = {});

/// "elevation", "depth" or "automatic".
const char* to_string(VerticalSense sense);

}  // namespace deepguide
