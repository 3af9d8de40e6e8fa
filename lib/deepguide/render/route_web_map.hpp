#pragma once
// A planned route as a web map (render/web_map.hpp): `plan --html`.
//
// Layers, each switchable:
//  - no_go (on S-57 charts): the chart's no-go features at the depth, each
//    with the planner's reason (record id, cell, class, DRVAL1 or VALSOU
//    and the zone of confidence's allowance, a hazard's radius); a click
//    lists every one under it;
//  - obstacles: what the route was planned among (on charts the no-go
//    unioned into polygons, hazards' discs; obstacle files' footprints);
//  - zones: their safety zones at the margin, as the planner builds them;
//  - route: a feature per leg (its length, true course, least clearance and
//    the obstacle it is nearest to, by the independent checker);
//  - waypoints: a feature each (number, position, speed, time or ETA, turn
//    radius, depth).
// The table beside the map lists the waypoints as the route file has them.

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route_plan_report.hpp"
#include "deepguide/render/web_map.hpp"

namespace DEEPGUIDE_API deepguide {

WebMap route_web_map(const RoutePlanReport& report);

}  // namespace deepguide
