#pragma once
// A planned route (planning/route_plan_report.hpp) into the route file its
// name asks for (.geojson, .gpx, .kml, .rtz, .csv, .plan, .bhv): waypoint
// speeds, times and ETAs, the margin, turning radius and safety depth, the
// report's properties; and a replay's repaired routes beside it.

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route_plan_report.hpp"

namespace DEEPGUIDE_API deepguide {

/// Writes each repaired route to its name in report.repair_files, then the
/// route to `path` (overwriting). Throws InputError for a name whose
/// extension is no route format, before anything is written.
void write_route_plan(const RoutePlanReport& report, const std::string& path);

}  // namespace deepguide
