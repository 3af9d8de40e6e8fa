#include "deepguide/render/raster_web_image.hpp"

#include <cairo.h>
#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/world/bathymetry.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {

namespace {

constexpr std::array<double, 6> kBandEdges{2.0, 5.0, 10.0, 20.0, 50.0, 100.0};
constexpr std::array<const char*, 7> kBandFills{"#c7e4f5", "#a9d3ee", "#8cc2e6", "#6fb0dd",
                                                "#5198cc", "#3b7fb8", "#2a6399"};

std::uint32_t argb(const char* hex) {
  return 0xff000000u | static_cast<std::uint32_t>(std::stoul(std::string(hex + 1), nullptr, 16));
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

const char* depth_band_fill(double depth_m) {
  std::size_t i = 0;
  while (i < kBandEdges.size() && depth_m >= kBandEdges[i]) ++i;
  return kBandFills[i];
}

WebMapImage raster_depth_image(const std::string& path, const std::string& source_crs, int max_px) {
  BathymetryOptions read;
  read.assumed_crs = source_crs;
  const BathymetryInfo info = inspect_bathymetry(path, read);  // the file's checks, its CRS and vertical sense
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr src = gdal::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_READONLY);
  if (!src) throw InputError(path + ": expected a raster GDAL can open");
  const double aspect = static_cast<double>(info.width) / std::max(1, info.height);
  const int w = aspect >= 1.0 ? max_px : std::max(1, static_cast<int>(max_px * aspect));
  const int h = aspect >= 1.0 ? std::max(1, static_cast<int>(max_px / aspect)) : max_px;
  const int out_w = std::min(w, std::max(info.width, 2)), out_h = std::min(h, std::max(info.height, 2));
  std::vector<std::string> args{"-of",
                                "MEM",
                                "-t_srs",
                                "EPSG:3857",
                                "-s_srs",
                                info.crs_wkt,
                                "-r",
                                "bilinear",
                                "-ts",
                                std::to_string(out_w),
                                std::to_string(out_h),
                                "-dstnodata",
                                "nan",
                                "-ot",
                                "Float64"};
  if (info.has_nodata) args.insert(args.end(), {"-srcnodata", std::to_string(info.nodata)});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(argv.data(), nullptr);
  GDALDatasetH in = GDALDataset::ToHandle(src.get());
  int failed = 0;
  const GDALDatasetUniquePtr warped(GDALDataset::FromHandle(GDALWarp("", nullptr, 1, &in, options, &failed)));
  GDALWarpAppOptionsFree(options);
  if (!warped || failed)
    throw InputError(path + ": could not warp the raster into Web Mercator (" + gdal::QuietErrors::last_message() +
                     ")");
  const int W = warped->GetRasterXSize(), H = warped->GetRasterYSize();
  std::vector<double> z(static_cast<std::size_t>(W) * static_cast<std::size_t>(H));
  if (warped->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, W, H, z.data(), W, H, GDT_Float64, 0, 0) != CE_None) {
    throw InputError(path + ": could not read the warped raster");
  }
  const bool elevation = info.sense_used == VerticalSense::elevation;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, W, H);
  const int stride = cairo_image_surface_get_stride(surface);
  unsigned char* pixels = cairo_image_surface_get_data(surface);
  cairo_surface_flush(surface);
  const std::uint32_t land = argb("#f1e3c6");
  for (int y = 0; y < H; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(pixels + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < W; ++x) {
      const double v = z[static_cast<std::size_t>(y) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x)];
      if (!std::isfinite(v) || (info.has_nodata && v == info.nodata)) {
        row[x] = 0;  // clear
        continue;
      }
      const double depth = elevation ? -v : v;
      row[x] = depth <= 0.0 ? land : argb(depth_band_fill(depth));
    }
  }
  cairo_surface_mark_dirty(surface);
  std::string png;
  const cairo_status_t written = cairo_surface_write_to_png_stream(surface, append, &png);
  cairo_surface_destroy(surface);
  if (written != CAIRO_STATUS_SUCCESS) throw InputError(path + ": could not make the depth image");
  char* base64 = CPLBase64Encode(static_cast<int>(png.size()), reinterpret_cast<const GByte*>(png.data()));
  WebMapImage image;
  image.png_base64 = base64;
  CPLFree(base64);
  // The corners of Web Mercator's box, in lon/lat: where Leaflet puts the image.
  std::array<double, 6> gt{};
  warped->GetGeoTransform(gt.data());
  const auto mercator = gdal::srs_from_user_input("EPSG:3857");
  const auto lonlat = gdal::wgs84();
  const std::unique_ptr<OGRCoordinateTransformation> to(
      OGRCreateCoordinateTransformation(mercator.get(), lonlat.get()));
  std::array<double, 2> xs{gt[0], gt[0] + gt[1] * W}, ys{gt[3] + gt[5] * H, gt[3]};
  if (!to || !to->Transform(2, xs.data(), ys.data())) throw InputError(path + ": could not place the depth image");
  image.bounds = {xs[0], xs[1], ys[0], ys[1]};
  image.id = "depth_shading:" + std::filesystem::path(path).filename().string();
  image.name = "Depth shading of " + std::filesystem::path(path).filename().string();
  return image;
}

}  // namespace deepguide
