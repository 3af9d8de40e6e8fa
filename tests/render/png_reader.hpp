#pragma once
// Reading PNGs back in the render tests: pixels as 0..255 RGB.

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "deepguide/geometry/vec2.hpp"
#include "deepguide/render/canvas.hpp"

namespace deepguide::test {

/// A decoded PNG, pixels read back as 0..255 RGB.
class Png {
 public:
  explicit Png(const std::string& path) : surface_(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Png() { cairo_surface_destroy(surface_); }
  Png(const Png&) = delete;
  Png& operator=(const Png&) = delete;
  bool ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }
  /// RGB of the pixel covering the continuous pixel position p.
  std::array<int, 3> at(const Vec2& p) const {
    const int x = static_cast<int>(std::floor(p.x()));
    const int y = static_cast<int>(std::floor(p.y()));
    const bool inside = x >= 0 && y >= 0 && x < width() && y < height();
    EXPECT_TRUE(inside) << "pixel " << x << "," << y << " is outside";
    if (!inside) return {-1000, -1000, -1000};  // matches no colour
    const unsigned char* row = cairo_image_surface_get_data(surface_) + y * cairo_image_surface_get_stride(surface_);
    std::uint32_t v;
    std::memcpy(&v, row + 4 * x, 4);
    return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff), static_cast<int>(v & 0xff)};
  }

 private:
  cairo_surface_t* surface_;
};

/// The largest difference of one channel (0..255) between a pixel and a colour.
inline int colour_distance(const std::array<int, 3>& got, const Rgba& want) {
  const double w[3] = {want.r, want.g, want.b};
  int worst = 0;
  for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(got[i] - static_cast<int>(std::lround(w[i] * 255))));
  return worst;
}

}  // namespace deepguide::test
