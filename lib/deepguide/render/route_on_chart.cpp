#include "deepguide/render/route_on_chart.hpp"

#include <algorithm>

#include "deepguide/core/error.hpp"

namespace deepguide {

ChartLayout render_route_on_chart(const RouteOnChart& r, const std::string& path) {
  if (r.route.size() < 2) throw InputError("render: expected a route of at least two waypoints");
  ChartRenderOptions o = r.chart;
  WorldBox box;
  for (const Vec2& p : r.route) box.extend(p);
  o.extent = box.padded(std::max(1000.0, 0.2 * std::max(box.width(), box.height())));
  const Rgba route_color = rgb_hex(0x1864d6), start = rgb_hex(0x2f9e44), goal = rgb_hex(0xc92a2a);
  o.overlay = [&](Canvas& canvas, const ViewTransform& view, double u) {
    std::vector<Vec2> px;
    for (const Vec2& p : r.route) px.push_back(view.to_pixel(p));
    canvas.stroke_polyline(px, Stroke{Rgba{1.0, 1.0, 1.0, 0.9}, 5.0 * u, {}});  // a halo over the hatching
    canvas.stroke_polyline(px, Stroke{route_color, 2.6 * u, {}});
    for (std::size_t k = 1; k + 1 < px.size(); ++k)
      canvas.circle(px[k], 2.6 * u, Rgba{1.0, 1.0, 1.0, 1.0}, Stroke{route_color, 1.4 * u, {}});
    canvas.circle(px.front(), 6.0 * u, start, Stroke{Rgba{1.0, 1.0, 1.0, 1.0}, 1.5 * u, {}});
    canvas.circle(px.back(), 6.0 * u, goal, Stroke{Rgba{1.0, 1.0, 1.0, 1.0}, 1.5 * u, {}});
  };
  o.overlay_legend.push_back({route_color, 2.6, false, "route"});
  return render_chart(o, path);
}

}  // namespace deepguide
