#pragma once
// A planned route drawn over its charts (the chart figure, chart_scene.hpp,
// with the route as overlay): what `plan --render` draws when the charts are
// S-57 cells or a prepared chart, so the route is seen against depth areas,
// the no-go hatching and the safety contour rather than against bare
// obstacle outlines. The map shows the route's box, widened by a fifth of its
// size (at least 1 km) on every side.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/render/chart_scene.hpp"

namespace DEEPGUIDE_API deepguide {

struct RouteOnChart {
  /// The charts, depth (NaN, the default: no no-go layer), clearance, frame
  /// (local_crs: the route's coordinates are in it), title and width. The
  /// extent and overlay are set from the route; its legend line is added to
  /// overlay_legend.
  ChartRenderOptions chart;
  std::vector<Vec2> route;
};

/// Writes the figure (.png or .svg). Throws what render_chart throws.
ChartLayout render_route_on_chart(const RouteOnChart& r, const std::string& path);

}  // namespace deepguide
