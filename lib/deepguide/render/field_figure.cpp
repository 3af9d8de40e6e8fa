#include "deepguide/render/field_figure.hpp"

#include <algorithm>
#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace deepguide {
namespace {

// Design units (at 1200 px wide).
constexpr double kSeedSpacing = 22.0;
constexpr double kArrowSpacing = 40.0;
constexpr double kStepPx = 0.5;
constexpr int kLegendColumns = 4;

bool inside_any(const std::vector<Ellipse>& objects, const Vec2& p) {
  return std::any_of(objects.begin(), objects.end(), [&](const Ellipse& e) { return e.contains(p); });
}

Rgba grey_arrow() { return rgb_hex(0x9aa4ae); }

void end_dot(Canvas& c, const Vec2& at, const Rgba& color, double u) {
  c.circle(at, 4.0 * u, color, Stroke{rgb_hex(0x000000), 1.3 * u, {}});
}

}  // namespace

FieldFigure field_figure_for(const Scenario& scenario, ReactiveMethod method) {
  FieldFigure f;
  f.method = method;
  f.params = scenario.reactive;
  f.map = reactive_map_for(scenario,
                           "Gradient lines of the " + std::string(to_string(method)) + " method: " + scenario.name);
  return f;
}

FieldFigureGeometry field_figure_geometry(const FieldFigure& figure) {
  validate(figure.params);
  if (figure.map.margin_m != figure.params.margin_m) {
    throw InputError("field figure: expected the map's margin to be the method's (" + general(figure.params.margin_m) +
                     " m), got " + general(figure.map.margin_m) + " m");
  }
  FieldFigureGeometry g;
  g.layout = reactive_map_layout(figure.map, WorldBox{}, figure.width_px, kLegendColumns, kLegendColumns);
  const double m_per_px = 1.0 / g.layout.view.scale();
  const WorldBox& area = g.layout.area;
  g.options.step_m = kStepPx * m_per_px;
  g.options.max_steps =
      static_cast<std::size_t>(std::ceil(4.0 * 2.0 * (area.width() + area.height()) / g.options.step_m));
  std::vector<Vec2> seeds =
      upstream_seeds(area, figure.map.start, figure.map.target, kSeedSpacing * g.layout.unit * m_per_px);
  // A seed inside rock has no meaningful line.
  std::erase_if(seeds, [&](const Vec2& p) { return inside_any(figure.map.objects, p); });
  // The start is the seed at offset 0: the one nearest to it.
  const auto nearest = std::min_element(seeds.begin(), seeds.end(), [&](const Vec2& a, const Vec2& b) {
    return (a - figure.map.start).squaredNorm() < (b - figure.map.start).squaredNorm();
  });
  g.start_line = static_cast<std::size_t>(nearest - seeds.begin());
  g.lines = gradient_lines(figure.method, figure.params, seeds, figure.map.target, figure.map.objects, area, g.options);
  std::vector<GradientLine> dividers = dividing_lines(figure.method, figure.params, seeds, g.lines, figure.map.target,
                                                      figure.map.objects, area, g.options);
  g.dividing = dividers.size();
  for (GradientLine& d : dividers) g.lines.push_back(std::move(d));
  return g;
}

FieldFigureGeometry render_field_figure(const FieldFigure& figure, const std::string& path) {
  image_format_for(path);  // the cheapest mistake first
  FieldFigureGeometry g;
  try {
    g = field_figure_geometry(figure);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  const ReactiveMapLayout& l = g.layout;
  const double u = l.unit;
  const Rgba color = method_color(figure.method);
  Canvas canvas(path, l.width, l.height);
  begin_reactive_map(canvas, figure.map, l);

  // The field's direction on a grid, under the lines.
  std::vector<std::pair<Vec2, Vec2>> arrows;
  const double spacing = kArrowSpacing * u;
  for (double y = l.plot.y + 0.5 * spacing; y < l.plot.y + l.plot.height; y += spacing) {
    for (double x = l.plot.x + 0.5 * spacing; x < l.plot.x + l.plot.width; x += spacing) {
      const Vec2 w = l.view.to_world(Vec2(x, y));
      if (inside_any(figure.map.objects, w)) continue;
      const Vec2 d = reactive_gradient(figure.method, figure.params, w, figure.map.target, figure.map.objects);
      if (d.squaredNorm() > 0.0) add_arrow(arrows, Vec2(x, y), d, 0.5 * spacing);
    }
  }
  canvas.stroke_segments(arrows, Stroke{grey_arrow(), 1.1 * u, {}});

  auto to_px = [&](const GradientLine& line) {
    std::vector<Vec2> pts;
    pts.reserve(line.points.size());
    for (const Vec2& p : line.points) pts.push_back(l.view.to_pixel(p));
    return pts;
  };
  for (std::size_t i = 0; i < g.lines.size(); ++i) {
    if (i != g.start_line) canvas.stroke_polyline(to_px(g.lines[i]), Stroke{color, 1.3 * u, {}});
  }
  if (!g.lines.empty()) {
    const std::vector<Vec2> start_line = to_px(g.lines[g.start_line]);
    canvas.stroke_polyline(start_line, Stroke{figure.map.style.background, 5.5 * u, {}});
    canvas.stroke_polyline(start_line, Stroke{color, 3.0 * u, {}});
  }
  for (const GradientLine& line : g.lines) {
    if (line.end == LineEnd::stalled) end_dot(canvas, l.view.to_pixel(line.points.back()), color, u);
  }

  std::vector<LegendEntry> legend{
      {"gradient line",
       [&](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, Stroke{color, 1.3 * u, {}});
       }},
      {"the line from the start",
       [&](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, Stroke{color, 3.0 * u, {}});
       }},
      {"field direction",
       [&](Canvas& c, const Vec2& m) {
         std::vector<std::pair<Vec2, Vec2>> a;
         add_arrow(a, m, Vec2(1.0, 0.0), 0.5 * spacing);
         c.stroke_segments(a, Stroke{grey_arrow(), 1.1 * u, {}});
       }},
  };
  if (std::any_of(g.lines.begin(), g.lines.end(),
                  [](const GradientLine& line) { return line.end == LineEnd::stalled; })) {
    legend.push_back({"line ends: field vanishes", [&](Canvas& c, const Vec2& m) { end_dot(c, m, color, u); }});
  }
  end_reactive_map(canvas, figure.map, l, legend);
  canvas.finish();
  return g;
}

}  // namespace deepguide
