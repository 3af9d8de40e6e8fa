#pragma once
// A planned route (planning/route_plan_report.hpp) drawn as `plan --render`
// draws it: over S-57 cells as an ECDIS shows them, or over the obstacles
// and their zones, with the current and each leg's speed, time and energy,
// a replay's detections, repairs and track, and optionally the zone
// polygons, the planning graph and the quadtree's cells.

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route_plan_report.hpp"

namespace DEEPGUIDE_API deepguide {

/// Writes the figure (.png or .svg). `draw_graph`: the zone polygons, the
/// graph's edges and the quadtree's cells too (not over S-57 cells).
void render_route_plan(const RoutePlanReport& report, const std::string& path, bool draw_graph = false);

}  // namespace deepguide
