#include "deepguide/render/plot_furniture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth

namespace deepguide {

void add_arrow(std::vector<std::pair<Vec2, Vec2>>& segments, const Vec2& c, const Vec2& d, double length) {
  const Vec2 dir(d.x(), -d.y());  // rows grow southwards
  const Vec2 tail = c - 0.5 * length * dir;
  const Vec2 tip = c + 0.5 * length * dir;
  const Vec2 side(-dir.y(), dir.x());
  const double head = 0.32 * length;
  segments.emplace_back(tail, tip);
  segments.emplace_back(tip, tip - head * (0.9 * dir + 0.45 * side));
  segments.emplace_back(tip, tip - head * (0.9 * dir - 0.45 * side));
}

void check_figure_width(int width_px) {
  if (width_px < kMinImageWidth || width_px > kMaxImageWidth) {
    throw InputError("image width: expected " + std::to_string(kMinImageWidth) + " to " +
                     std::to_string(kMaxImageWidth) + " pixels, got " + std::to_string(width_px));
  }
}

void draw_figure_title(Canvas& canvas, const std::string& title, int width_px, double u, const Rgba& color,
                       double size_units, double baseline) {
  constexpr double kSide = 24.0;  // design units
  const double room = width_px - 2.0 * kSide * u;
  double size = size_units * u;
  if (const double w = canvas.text_width(title, size, true); w > room) size *= room / w;
  canvas.text({kSide * u, baseline * u}, title, size, color, TextAlign::left, true);
}

double nice_tick_step(double span, int max_ticks) {
  if (!(span > 0.0) || !std::isfinite(span) || max_ticks < 2) {
    throw InputError("plot axis: expected a positive finite range and at least 2 ticks, got range " + general(span) +
                     " and " + std::to_string(max_ticks) + " ticks");
  }
  // k ticks cover (k - 1) steps: the step must be at least span / (max_ticks - 1).
  const double raw = span / (max_ticks - 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double f : {1.0, 2.0, 5.0, 10.0}) {
    if (f * decade >= raw * (1.0 - 1e-12)) return f * decade;
  }
  return 10.0 * decade;  // unreachable: 10 decade > raw
}

std::vector<double> nice_ticks(double lo, double hi, int max_ticks) {
  const double step = nice_tick_step(hi - lo, max_ticks);
  std::vector<double> ticks;
  const double eps = 1e-9 * step;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < eps ? 0.0 : v);  // no "-0"
  }
  return ticks;
}

std::string format_tick(double value, double step) {
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 9);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

void draw_axes(Canvas& canvas, const PixelRect& plot, const PlotAxis& x, const PlotAxis& y, const AxesOptions& options,
               double u, const AxesStyle& style) {
  const std::vector<double> xt = options.x_ticks ? nice_ticks(x.lo, x.hi, options.max_x_ticks) : std::vector<double>{};
  const std::vector<double> yt = nice_ticks(y.lo, y.hi, options.max_y_ticks);
  const double x_step = nice_tick_step(x.hi - x.lo, options.max_x_ticks);
  const double y_step = nice_tick_step(y.hi - y.lo, options.max_y_ticks);
  const double left = plot.x, right = plot.x + plot.width;
  const double top = plot.y, bottom = plot.y + plot.height;

  if (style.grid.a > 0.0) {
    std::vector<std::pair<Vec2, Vec2>> grid;
    for (const double v : xt) grid.emplace_back(Vec2(x.to_px(v), top), Vec2(x.to_px(v), bottom));
    for (const double v : yt) grid.emplace_back(Vec2(left, y.to_px(v)), Vec2(right, y.to_px(v)));
    canvas.stroke_segments(grid, Stroke{style.grid, 1.0 * u, {}});
  }
  canvas.stroke_rect(plot, Stroke{style.frame, 1.0 * u, {}});

  const double tick = 5.0 * u;
  const double size = 13.0 * u;
  std::vector<std::pair<Vec2, Vec2>> marks;
  for (const double v : xt) marks.emplace_back(Vec2(x.to_px(v), bottom), Vec2(x.to_px(v), bottom + tick));
  for (const double v : yt) marks.emplace_back(Vec2(left - tick, y.to_px(v)), Vec2(left, y.to_px(v)));
  canvas.stroke_segments(marks, Stroke{style.frame, 1.0 * u, {}});
  if (options.x_labels) {
    for (const double v : xt) {
      canvas.text({x.to_px(v), bottom + tick + 15.0 * u}, format_tick(v, x_step), size, style.text, TextAlign::centre);
    }
    canvas.text({right, bottom + tick + 36.0 * u}, options.x_title, size, style.text, TextAlign::right);
  }
  for (const double v : yt) {
    const std::string label = options.y_label ? options.y_label(v, y_step) : format_tick(v, y_step);
    canvas.text({left - tick - 4.0 * u, y.to_px(v) + 4.5 * u}, label, size, style.text, TextAlign::right);
  }
  canvas.text({left, top - 9.0 * u}, options.y_title, size, style.text, TextAlign::left);
}

namespace {
constexpr double kLegendRow = 26.0;  // design units per row
constexpr double kSwatchWidth = 30.0;
constexpr double kLabelGap = 8.0;
constexpr double kLegendFont = 14.0;
}  // namespace

double legend_height(std::size_t entries, int columns, double u) {
  const std::size_t rows =
      (entries + static_cast<std::size_t>(std::max(1, columns)) - 1) / static_cast<std::size_t>(std::max(1, columns));
  return static_cast<double>(rows) * kLegendRow * u;
}

void draw_legend(Canvas& canvas, const std::vector<LegendEntry>& entries, const PixelRect& rect, int columns, double u,
                 const Rgba& text) {
  columns = std::max(1, columns);
  const double column_width = rect.width / columns;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto row = static_cast<double>(i / static_cast<std::size_t>(columns));
    const auto col = static_cast<double>(i % static_cast<std::size_t>(columns));
    const double x = rect.x + col * column_width;
    const double y = rect.y + (row + 0.5) * kLegendRow * u;  // row centre
    entries[i].swatch(canvas, Vec2(x + 0.5 * kSwatchWidth * u, y));
    const double room = column_width - (kSwatchWidth + kLabelGap + 10.0) * u;
    double size = kLegendFont * u;
    const double w = canvas.text_width(entries[i].label, size);
    if (w > room && room > 0.0) size *= room / w;
    canvas.text({x + (kSwatchWidth + kLabelGap) * u, y + 0.36 * size}, entries[i].label, size, text);
  }
}

}  // namespace deepguide
