#include "deepguide/render/raster_web_image.hpp"

#include <cairo.h>
#include <cpl_conv.h>
#include <cpl_string.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "deepguide/charts/raster_depths.hpp"
#include "deepguide/core/error.hpp"

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
  const WebMercatorDepths grid = raster_depths_web_mercator(path, source_crs, max_px);
  const int W = grid.width, H = grid.height;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, W, H);
  const int stride = cairo_image_surface_get_stride(surface);
  unsigned char* pixels = cairo_image_surface_get_data(surface);
  cairo_surface_flush(surface);
  const std::uint32_t land = argb("#f1e3c6");
  for (int y = 0; y < H; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(pixels + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < W; ++x) {
      const double depth =
          grid.depth_m[static_cast<std::size_t>(y) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x)];
      if (std::isnan(depth)) {
        row[x] = 0;  // no data: clear
        continue;
      }
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
  image.bounds = grid.bounds;
  image.id = "depth_shading:" + std::filesystem::path(path).filename().string();
  image.name = "Depth shading of " + std::filesystem::path(path).filename().string();
  return image;
}

}  // namespace deepguide
