#include "deepguide/charts/raster_sea_floor.hpp"

#include <gdal_utils.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "deepguide/charts/bathymetry_raster.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace {

// Coordinates for GDAL's argument list, to the last bit.
std::string exact(double v) { return general(v, 17); }

}  // namespace

SeaFloor raster_sea_floor(const std::string& path, const LocalFrame& frame, const Vec2& area_min, const Vec2& area_max,
                          double spacing, const BathymetryOptions& options) {
  if (!(spacing >= 0.0) || !std::isfinite(spacing)) {
    throw InputError(path + ": sea floor node spacing: expected > 0 m (or 0: the raster's own), got " +
                     general(spacing));
  }
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  detail::OpenedBathymetry raster = detail::open_bathymetry(path, options);
  if (spacing == 0.0) {
    // The raster's own cell, in metres (a degree of latitude is 111.32 km).
    spacing = std::min(std::abs(raster.geotransform[1]), std::abs(raster.geotransform[5]));
    if (raster.srs->IsGeographic()) spacing *= 111320.0;
    if (!(spacing > 0.0)) throw InputError(path + ": sea floor: expected a raster with a cell size, got none");
  }
  const Vec2 extent = area_max - area_min;
  if (!area_min.allFinite() || !area_max.allFinite() || !(extent.minCoeff() > 0.0)) {
    throw InputError(path + ": sea floor: expected an area with a positive, finite extent");
  }
  const double nxd = std::ceil(extent.x() / spacing) + 1.0, nyd = std::ceil(extent.y() / spacing) + 1.0;
  if (nxd * nyd > 1e8) {
    throw InputError(path + ": sea floor: " + general(spacing) + " m nodes over this area make more than 1e8 nodes; " +
                     "give a larger spacing");
  }
  const auto nx = static_cast<std::size_t>(nxd), ny = static_cast<std::size_t>(nyd);
  // Warped so that pixel centres fall on the nodes: node (i, j) is the centre
  // of column i, row ny - 1 - j (rows run north to south).
  const double h = 0.5 * spacing;
  std::vector<std::string> args = {"-of",
                                   "MEM",
                                   "-s_srs",
                                   raster.info.crs_wkt,
                                   "-t_srs",
                                   frame.wkt(),
                                   "-te",
                                   exact(area_min.x() - h),
                                   exact(area_min.y() - h),
                                   exact(area_min.x() + (nxd - 0.5) * spacing),
                                   exact(area_min.y() + (nyd - 0.5) * spacing),
                                   "-ts",
                                   std::to_string(nx),
                                   std::to_string(ny),
                                   "-r",
                                   raster.to_depth < 0.0 ? "max" : "min",
                                   "-ot",
                                   "Float64",
                                   "-dstnodata",
                                   "nan"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALWarpAppOptions* warp_options = GDALWarpAppOptionsNew(argv.data(), nullptr);
  if (warp_options == nullptr) {
    throw InputError(path + ": sea floor: GDAL refused the warp options: " + gdal::QuietErrors::last_message());
  }
  GDALDatasetH source = GDALDataset::ToHandle(raster.dataset.get());
  int usage_error = 0;
  // gdalwarp warps every band (GDAL 3.6 has no -b): another band than the
  // first is picked out into a VRT first.
  GDALDatasetUniquePtr one_band;
  if (options.band != 1) {
    std::string band = std::to_string(options.band);
    char of[] = "-of", vrt[] = "VRT", b[] = "-b";
    char* targs[] = {of, vrt, b, band.data(), nullptr};
    GDALTranslateOptions* translate = GDALTranslateOptionsNew(targs, nullptr);
    one_band.reset(GDALDataset::FromHandle(GDALTranslate("", source, translate, &usage_error)));
    GDALTranslateOptionsFree(translate);
    if (!one_band) throw InputError(path + ": sea floor: band " + band + ": " + gdal::QuietErrors::last_message());
    source = GDALDataset::ToHandle(one_band.get());
  }
  GDALDatasetUniquePtr warped(GDALDataset::FromHandle(GDALWarp("", nullptr, 1, &source, warp_options, &usage_error)));
  GDALWarpAppOptionsFree(warp_options);
  if (!warped) {
    throw InputError(path + ": sea floor: expected a raster GDAL can warp into " + frame.id() +
                     ", got: " + gdal::QuietErrors::last_message());
  }
  std::vector<double> rows(nx * ny);
  if (warped->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, static_cast<int>(nx), static_cast<int>(ny), rows.data(),
                                         static_cast<int>(nx), static_cast<int>(ny), GDT_Float64, 0, 0,
                                         nullptr) != CE_None) {
    throw InputError(path + ": sea floor: reading the warped raster failed: " + gdal::QuietErrors::last_message());
  }
  // Each node first holds the shallowest chart value in its own cell (the
  // warp's max of elevations, min of depths), then the shallowest of its 3 x 3
  // neighbourhood: a bilinear patch mixes its four corners, so each corner
  // must be no deeper than the chart anywhere in the patches around it.
  // The floor is then never deeper than the chart (a pinnacle narrower than
  // a node spacing stays), at the price of shoals a node spacing wider.
  std::vector<double> cell(nx * ny);
  std::size_t valid = 0;
  for (std::size_t r = 0; r < ny; ++r) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double v = rows[r * nx + i];
      const bool ok = std::isfinite(v) && !raster.is_nodata(v);
      valid += ok;
      cell[(ny - 1 - r) * nx + i] = ok ? v * raster.to_depth : 0.0;  // no data: depth 0
    }
  }
  if (valid == 0) {
    throw InputError(path +
                     ": sea floor: expected a raster that covers the work area, got one that does not "
                     "reach it (or has no data there)");
  }
  std::vector<double> depths(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      double d = cell[j * nx + i];
      for (std::size_t jj = j > 0 ? j - 1 : 0; jj <= std::min(j + 1, ny - 1); ++jj) {
        for (std::size_t ii = i > 0 ? i - 1 : 0; ii <= std::min(i + 1, nx - 1); ++ii)
          d = std::min(d, cell[jj * nx + ii]);
      }
      depths[j * nx + i] = d;
    }
  }
  return SeaFloor(area_min, spacing, nx, ny, std::move(depths));
}

}  // namespace deepguide
