#include "deepguide/render/map_furniture.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {

std::string format_length(double metres) {
  return metres >= 1000.0 ? general(metres / 1000.0) + " km" : general(metres) + " m";
}

double nice_scale_length(double max_length_m) {
  if (!(max_length_m > 0.0) || !std::isfinite(max_length_m)) {
    throw InputError("scale bar: expected a positive finite length, got " + general(max_length_m));
  }
  const double decade = std::pow(10.0, std::floor(std::log10(max_length_m)));
  // The relative tolerance keeps 100 from becoming 50 through log10 rounding.
  for (const double f : {5.0, 2.0, 1.0}) {
    if (f * decade <= max_length_m * (1.0 + 1e-12)) return f * decade;
  }
  return decade / 2.0;  // unreachable: max_length_m >= decade (up to rounding)
}

void draw_scale_bar(Canvas& canvas, double scale, double x0, double y, double max_px, double u,
                    const FurnitureColors& c) {
  const double length_m = nice_scale_length(max_px / scale);
  const double length_px = length_m * scale;
  const double h = 7.0 * u;
  constexpr int kParts = 4;
  for (int i = 0; i < kParts; ++i) {
    const PixelRect part{x0 + length_px * i / kParts, y, length_px / kParts, h};
    canvas.fill_rect(part, i % 2 == 0 ? c.text : c.background);
  }
  canvas.stroke_rect({x0, y, length_px, h}, Stroke{c.text, 1.0 * u, {}});
  const double size = 13.0 * u;
  canvas.text({x0, y - 6.0 * u}, "0", size, c.text, TextAlign::centre);
  canvas.text({x0 + length_px / 2.0, y - 6.0 * u}, format_length(length_m / 2.0), size, c.text, TextAlign::centre);
  canvas.text({x0 + length_px, y - 6.0 * u}, format_length(length_m), size, c.text, TextAlign::centre);
  canvas.text({x0, y + h + 18.0 * u}, "scale  1 px = " + general(std::round(1000.0 / scale) / 1000.0) + " m", 11.5 * u,
              c.muted, TextAlign::left);
}

void draw_north_arrow(Canvas& canvas, double cx, double top, double u, double rotate_deg, const std::string& note,
                      double note_right_x, const FurnitureColors& c) {
  const double bottom = top + 40.0 * u;
  const double half = 9.0 * u;
  // Turned about the arrow's middle; rows grow downwards, so clockwise is +angle.
  const Vec2 pivot(cx, 0.5 * (top + bottom));
  const double a = rotate_deg * std::numbers::pi / 180.0;
  const double ca = std::cos(a), sa = std::sin(a);
  auto turn = [&](const Vec2& p) {
    if (rotate_deg == 0.0) return p;
    const Vec2 d = p - pivot;
    return Vec2(pivot.x() + ca * d.x() - sa * d.y(), pivot.y() + sa * d.x() + ca * d.y());
  };
  const Vec2 tip = turn({cx, top});
  const Vec2 base = turn({cx, bottom - 10.0 * u});
  const Vec2 left = turn({cx - half, bottom});
  const Vec2 right = turn({cx + half, bottom});
  canvas.shape({tip, left, base}, c.background, Stroke{c.text, 1.2 * u, {}});
  canvas.shape({tip, base, right}, c.text, Stroke{c.text, 1.2 * u, {}});
  canvas.text(tip + 5.0 * u * Vec2(sa, -ca), "N", 15.0 * u, c.text, TextAlign::centre, true);
  canvas.text({note_right_x, bottom + 18.0 * u}, note, 11.5 * u, c.muted, TextAlign::right);
}

}  // namespace deepguide
