#pragma once
// Library-internal (uses GDAL types; nothing public includes it): an opened
// bathymetry raster with everything bathymetry.hpp decides before a scan
// (band, CRS rules, geotransform, NoData, sign convention), and the window
// geometry of the block-wise scan. Shared by inspect_bathymetry and the no-go
// model so both read rasters by the same rules.

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <limits>
#include <memory>
#include <string>

#include "deepguide/charts/bathymetry.hpp"

namespace deepguide::detail {

struct OpenedBathymetry {
  GDALDatasetUniquePtr dataset;
  GDALRasterBand* band = nullptr;
  /// Header fields filled (path, driver, size, pixel size, extent, CRS, NoData,
  /// sense); the scan fields (depth range, valid cells, windows) are left empty.
  BathymetryInfo info;
  std::unique_ptr<OGRSpatialReference> srs;  ///< the CRS used, traditional GIS axis order
  double geotransform[6] = {0, 1, 0, 0, 0, 1};
  double to_depth = -1.0;  ///< cell value * to_depth = depth (m, positive down)
  GDALDataType type = GDT_Float64;

  /// NaN, or the band's NoData value compared at the band's precision.
  bool is_nodata(double value) const;

  /// The values the file says its cells hold (CF actual_range, valid_range,
  /// valid_min/valid_max, read where the band is not packed); infinite when
  /// it says nothing.
  double stated_min = -std::numeric_limits<double>::infinity();
  double stated_max = std::numeric_limits<double>::infinity();
  std::string stated_from;    ///< the attribute the range came from
  double unpack_scale = 1.0;  ///< the band's scale and offset (a packed band's raw value * scale + offset)
  double unpack_offset = 0.0;
  /// InputError naming the cell when a valid cell's value cannot be true: off
  /// the file's own stated range, or a depth no sea has (deeper than 11 100 m,
  /// higher than 9000 m). A flipped byte in uncompressed data shows only so.
  void require_plausible(double value, std::size_t column, std::size_t row) const;
};

/// Opens and checks the raster as inspect_bathymetry does (same InputErrors).
/// The caller holds a gdal::QuietErrors while it uses the result.
OpenedBathymetry open_bathymetry(const std::string& path, const BathymetryOptions& options);

/// Size of the scan windows: whole natural blocks, at most max_cells cells
/// (at least one block). With whole_rows, every window spans the full width
/// (for writers whose output strips must be written whole).
struct WindowSize {
  int width = 0;
  int height = 0;
};
WindowSize scan_window(GDALRasterBand& band, int raster_width, int raster_height, std::size_t max_cells,
                       bool whole_rows = false);

}  // namespace deepguide::detail
