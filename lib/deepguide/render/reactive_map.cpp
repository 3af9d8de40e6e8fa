#include "deepguide/render/reactive_map.hpp"

#include <algorithm>
#include <cmath>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace deepguide {
namespace {

// Design units (at 1200 px wide).
constexpr double kTitleBand = 52.0;
constexpr double kYTitle = 24.0;
constexpr double kLeft = 80.0;
constexpr double kRight = 24.0;
constexpr double kXNumbers = 52.0;
constexpr double kBottom = 10.0;
constexpr int kMapLegendColumns = 4;  // obstacle, zone, start, target

bool finite(const Vec2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

/// The ellipse's bounding box from its support function.
WorldBox ellipse_box(const Ellipse& e) {
  WorldBox box;
  box.extend(Vec2(-e.support(Vec2(-1.0, 0.0)), -e.support(Vec2(0.0, -1.0))));
  box.extend(Vec2(e.support(Vec2(1.0, 0.0)), e.support(Vec2(0.0, 1.0))));
  return box;
}

std::vector<Ellipse> zones(const ReactiveMap& map) {
  std::vector<Ellipse> out;
  if (map.margin_m <= 0.0) return out;
  for (const Ellipse& e : map.objects) out.push_back(security_ellipse(e, map.margin_m));
  return out;
}

int outline_points(const Ellipse& e, double scale) {
  return std::clamp(static_cast<int>(std::ceil(2.0 * kPi * e.a * scale / 3.0)), 72, 2048);
}

Rgba with_alpha(Rgba c, double a) {
  c.a = a;
  return c;
}

Stroke zone_stroke(const ReactiveMapStyle& s, double u) { return {s.zone, 1.4 * u, {6.0 * u, 4.0 * u}}; }

void start_marker(Canvas& c, const Vec2& at, const ReactiveMapStyle& s, double u) {
  c.circle(at, 6.5 * u, s.background, Stroke{s.text, 2.2 * u, {}});
}

void target_marker(Canvas& c, const Vec2& at, const ReactiveMapStyle& s, double u) {
  const double r = 8.5 * u;
  c.shape({at + Vec2(0, -r), at + Vec2(r, 0), at + Vec2(0, r), at + Vec2(-r, 0)}, s.text,
          Stroke{s.background, 1.5 * u, {}});
}

}  // namespace

Rgba method_color(const ReactiveMethod& method) { return rgb_hex(reactive_method_entry(method).colour); }

ReactiveMap reactive_map_for(const Scenario& scenario, const std::string& title) {
  ReactiveMap map;
  for (const EllipticCylinder& c : scenario.obstacles) map.objects.push_back(c.footprint);
  map.margin_m = scenario.reactive.margin_m;
  map.start = scenario.start;
  map.target = scenario.target;
  map.title = title;
  return map;
}

std::vector<Vec2> ellipse_outline(const Ellipse& e, int n) {
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out.push_back(e.point_at(2.0 * kPi * i / n));
  return out;
}

ReactiveMapLayout reactive_map_layout(const ReactiveMap& map, const WorldBox& extra, int width_px,
                                      std::size_t legend_entries, int legend_columns) {
  check_figure_width(width_px);
  if (!finite(map.start) || !finite(map.target) || !std::isfinite(map.margin_m)) {
    throw InputError("reactive map: expected a finite start, target and margin");
  }
  WorldBox content;
  content.extend(map.start);
  content.extend(map.target);
  for (const Ellipse& e : map.objects) {
    if (!finite(e.centre) || !(e.a > 0.0) || !(e.b > 0.0) || !std::isfinite(e.a) || !std::isfinite(e.theta)) {
      throw InputError("reactive map: expected obstacles with a finite centre and positive finite axes");
    }
    content.extend(ellipse_box(e));
  }
  for (const Ellipse& z : zones(map)) content.extend(ellipse_box(z));
  if (!extra.empty()) {
    if (!finite(extra.min) || !finite(extra.max)) throw InputError("reactive map: expected finite content");
    content.extend(extra);
  }
  const double span = std::max(content.width(), content.height());
  ReactiveMapLayout l;
  l.width = width_px;
  l.unit = width_px / 1200.0;
  const double u = l.unit;
  const WorldBox padded = content.padded(span > 0.0 ? 0.06 * span : 20.0);
  l.plot.x = kLeft * u;
  l.plot.y = (kTitleBand + kYTitle) * u;
  l.plot.width = width_px - (kLeft + kRight) * u;
  l.plot.height = std::round(l.plot.width * std::clamp(padded.height() / padded.width(), 0.45, 1.1));
  l.view = ViewTransform(padded, l.plot);
  // The world box the whole plot shows: the padded content, centred, plus the
  // slack along the looser axis.
  l.area.extend(l.view.to_world(Vec2(l.plot.x, l.plot.y + l.plot.height)));
  l.area.extend(l.view.to_world(Vec2(l.plot.x + l.plot.width, l.plot.y)));
  l.x = {l.area.min.x(), l.area.max.x(), l.plot.x, l.plot.x + l.plot.width};
  l.y = {l.area.min.y(), l.area.max.y(), l.plot.y + l.plot.height, l.plot.y};
  l.legend_entries = legend_entries;
  l.legend_columns = std::max(1, legend_columns);
  const double legend_h =
      legend_height(kMapLegendColumns, kMapLegendColumns, u) + legend_height(legend_entries, l.legend_columns, u);
  l.legend = {l.plot.x, l.plot.y + l.plot.height + kXNumbers * u, l.plot.width, legend_h};
  l.height = static_cast<int>(std::ceil(l.legend.y + legend_h + kBottom * u));
  return l;
}

void begin_reactive_map(Canvas& canvas, const ReactiveMap& map, const ReactiveMapLayout& l) {
  const ReactiveMapStyle& s = map.style;
  const double u = l.unit;
  canvas.fill_rect({0.0, 0.0, static_cast<double>(l.width), static_cast<double>(l.height)}, s.background);
  draw_figure_title(canvas, map.title.empty() ? std::string("deepguide reactive level") : map.title, l.width, u,
                    s.text);

  canvas.fill_rect(l.plot, s.sea);
  canvas.clip(l.plot);
  auto px = [&](const Vec2& w) { return l.view.to_pixel(w); };
  auto outline_px = [&](const Ellipse& e) {
    std::vector<Vec2> pts = ellipse_outline(e, outline_points(e, l.view.scale()));
    for (Vec2& p : pts) p = px(p);
    return pts;
  };
  for (const Ellipse& z : zones(map)) {
    const std::vector<Vec2> ring = outline_px(z);
    canvas.fill_rings({ring}, with_alpha(s.zone, 0.16));
    canvas.stroke_polyline(ring, zone_stroke(s, u), true);
  }
  for (const Ellipse& e : map.objects) canvas.fill_rings({outline_px(e)}, s.obstacle);
}

void end_reactive_map(Canvas& canvas, const ReactiveMap& map, const ReactiveMapLayout& l,
                      const std::vector<LegendEntry>& entries) {
  const ReactiveMapStyle& s = map.style;
  const double u = l.unit;
  const Vec2 start = l.view.to_pixel(map.start);
  const Vec2 target = l.view.to_pixel(map.target);
  start_marker(canvas, start, s, u);
  target_marker(canvas, target, s, u);
  canvas.text_with_halo(start + Vec2(0.0, -13.0 * u), "start", 14.0 * u, s.text, s.sea, 2.5 * u, TextAlign::centre);
  canvas.text_with_halo(target + Vec2(0.0, -15.0 * u), map.target_label, 14.0 * u, s.text, s.sea, 2.5 * u,
                        TextAlign::centre);
  canvas.unclip();
  draw_axes(canvas, l.plot, l.x, l.y, {"x, east (m)", "y, north (m)", 12, 8, true}, u,
            {s.text, s.frame, with_alpha(s.grid, 0.0)});

  std::vector<LegendEntry> own;
  own.push_back({"obstacle (true footprint)", [&s, u](Canvas& c, const Vec2& m) {
                   c.fill_rect({m.x() - 11.0 * u, m.y() - 6.0 * u, 22.0 * u, 12.0 * u}, s.obstacle);
                 }});
  if (map.margin_m > 0.0) {
    own.push_back({"security zone (" + general(map.margin_m) + " m)", [&s, u](Canvas& c, const Vec2& m) {
                     const std::vector<Vec2> box{m + Vec2(-15 * u, -8 * u), m + Vec2(15 * u, -8 * u),
                                                 m + Vec2(15 * u, 8 * u), m + Vec2(-15 * u, 8 * u)};
                     c.fill_rings({box}, with_alpha(s.zone, 0.16));
                     c.stroke_polyline(box, zone_stroke(s, u), true);
                   }});
  }
  own.push_back({"start", [&s, u](Canvas& c, const Vec2& m) { start_marker(c, m, s, u); }});
  own.push_back({map.target_label, [&s, u](Canvas& c, const Vec2& m) { target_marker(c, m, s, u); }});
  const PixelRect first{l.legend.x, l.legend.y, l.legend.width, legend_height(1, 1, u)};
  draw_legend(canvas, own, first, kMapLegendColumns, u, s.text);
  const PixelRect rest{l.legend.x, first.y + first.height, l.legend.width, l.legend.height - first.height};
  draw_legend(canvas, entries, rest, l.legend_columns, u, s.text);
}

}  // namespace deepguide
