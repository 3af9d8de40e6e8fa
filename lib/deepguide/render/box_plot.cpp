#include "deepguide/render/box_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deepguide/core/error.hpp"
#include "deepguide/render/plot_furniture.hpp"

namespace deepguide {

namespace {

const Rgba kText = rgb_hex(0x212529);
const Rgba kFrame = rgb_hex(0x5c636a);
const Rgba kGrid = rgb_hex(0xe3e7ec);

double rank(const std::vector<double>& sorted, double q) {
  const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(k, 1, sorted.size()) - 1];
}

}  // namespace

void render_box_plot(const BoxPlot& plot, const std::string& path) {
  image_format_for(path);
  if (plot.groups.empty()) throw InputError(path + ": expected at least one group to plot");
  if (plot.width_px < 300 || plot.width_px > 8000 || plot.height_px < 200 || plot.height_px > 8000) {
    throw InputError(path + ": expected a size of 300 .. 8000 x 200 .. 8000 px");
  }
  // The values as drawn (log10 on a log axis), sorted.
  std::vector<std::vector<double>> data;
  std::vector<std::size_t> left_out;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const BoxGroup& g : plot.groups) {
    std::vector<double> v;
    std::size_t out = 0;
    for (double x : g.values) {
      if (!std::isfinite(x) || (plot.log_y && x <= 0.0)) {
        ++out;
        continue;
      }
      v.push_back(plot.log_y ? std::log10(x) : x);
    }
    std::sort(v.begin(), v.end());
    if (!v.empty()) {
      lo = std::min(lo, v.front());
      hi = std::max(hi, v.back());
    }
    data.push_back(std::move(v));
    left_out.push_back(out);
  }
  if (!std::isfinite(lo)) throw InputError(path + ": expected values to plot, got none");
  if (plot.log_y) {
    lo = std::floor(lo);
    hi = std::max(std::ceil(hi), lo + 1.0);
  } else {
    const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1.0, std::abs(hi) * 0.1);
    lo -= pad;
    hi += pad;
  }

  const double u = plot.width_px / 1000.0;
  const PixelRect area{90.0 * u, 70.0 * u, plot.width_px - 120.0 * u, plot.height_px - 70.0 * u - 64.0 * u};
  const PlotAxis y{lo, hi, area.y + area.height, area.y};
  const PlotAxis x{0.0, static_cast<double>(plot.groups.size()), area.x, area.x + area.width};

  Canvas canvas(path, plot.width_px, plot.height_px);
  canvas.fill_rect({0.0, 0.0, static_cast<double>(plot.width_px), static_cast<double>(plot.height_px)},
                   rgb_hex(0xffffff));
  draw_figure_title(canvas, plot.title, plot.width_px, u, kText);
  AxesOptions axes{"", plot.y_title, 2, 8, false, false};  // the x axis is the groups, labelled below
  if (plot.log_y) {
    axes.y_title += " (log scale)";
    axes.max_y_ticks = std::max(2, static_cast<int>(hi - lo) + 1);  // one tick per decade
    axes.y_label = [](double v, double) {
      const double value = std::pow(10.0, std::round(v));
      return format_tick(value, std::min(value, 1.0));
    };
  }
  draw_axes(canvas, area, x, y, axes, u, {kText, kFrame, kGrid});

  const double slot = area.width / static_cast<double>(plot.groups.size());
  const double box_w = std::min(0.5 * slot, 110.0 * u);
  for (std::size_t i = 0; i < plot.groups.size(); ++i) {
    const BoxGroup& g = plot.groups[i];
    const std::vector<double>& v = data[i];
    const double cx = area.x + (static_cast<double>(i) + 0.5) * slot;
    canvas.text({cx, area.y + area.height + 24.0 * u}, g.label, 15.0 * u, kText, TextAlign::centre, true);
    std::string count = "n = " + std::to_string(v.size());
    if (left_out[i] > 0) count += " (+" + std::to_string(left_out[i]) + " not drawn)";
    canvas.text({cx, area.y + area.height + 44.0 * u}, count, 12.0 * u, kFrame, TextAlign::centre);
    if (v.empty()) continue;
    const double q1 = rank(v, 0.25), med = rank(v, 0.5), q3 = rank(v, 0.75), p5 = rank(v, 0.05), p95 = rank(v, 0.95);
    const Stroke line{g.color, 1.6 * u, {}};
    Rgba fill = g.color;
    fill.a = 0.25;
    canvas.stroke_segments({{{cx, y.to_px(p5)}, {cx, y.to_px(q1)}},
                            {{cx, y.to_px(q3)}, {cx, y.to_px(p95)}},
                            {{cx - 0.25 * box_w, y.to_px(p5)}, {cx + 0.25 * box_w, y.to_px(p5)}},
                            {{cx - 0.25 * box_w, y.to_px(p95)}, {cx + 0.25 * box_w, y.to_px(p95)}}},
                           line);
    const double top = y.to_px(q3), bottom = y.to_px(q1);
    canvas.shape({{cx - box_w / 2, top}, {cx + box_w / 2, top}, {cx + box_w / 2, bottom}, {cx - box_w / 2, bottom}},
                 fill, line);
    canvas.stroke_polyline({{cx - box_w / 2, y.to_px(med)}, {cx + box_w / 2, y.to_px(med)}},
                           Stroke{g.color, 3.0 * u, {}});
    Rgba dot = g.color;
    dot.a = 0.5;
    for (double value : v) {
      if (value < p5 || value > p95) canvas.circle({cx, y.to_px(value)}, 2.2 * u, dot, std::nullopt);
    }
  }
  canvas.finish();
}

}  // namespace deepguide
