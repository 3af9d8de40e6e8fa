#pragma once
// A mission plan as the files vehicles and ground stations read
// (docs/MISSIONS.md, "Export"). Every format but our own YAML carries the
// plan as waypoints (mission/route_export.hpp writes them): the basic
// manoeuvres' track with arcs as chords at most `arc_tolerance_m` inside
// them, each with its depth, speed, hold, turn radius, distance and time
// along. Our YAML keeps the basic manoeuvres themselves (lines, arcs, points;
// x, y in the mission's CRS), read back by read_plan_yaml.

#include <string>
#include <vector>

#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/mission/route_export.hpp"

namespace deepguide {

/// The plan's waypoints: the start, then each line's end, the chords' ends
/// along arcs (with the arc's radius), and each point (with its hold and depth).
std::vector<ExportWaypoint> export_waypoints(const Mission& mission, const MissionPlan& plan,
                                             double arc_tolerance_m = 0.5);

/// The plan as a route for write_route_file: its waypoints, the mission's
/// name, and the vehicle's turn radius, vertical and top speeds.
ExportRoute export_route(const Mission& mission, const MissionPlan& plan, double arc_tolerance_m = 0.5);

/// Writes the plan to `path` in `format`. Throws InputError naming the path
/// for an existing file without overwrite, a missing folder, or a failed write.
void export_plan(const Mission& mission, const MissionPlan& plan, const std::string& path, ExportFormat format,
                 const ExportOptions& options = {});

/// Reads a plan written as yaml (its basic manoeuvres; warnings are not kept).
/// Throws InputError naming the file and line for anything else.
MissionPlan read_plan_yaml(const std::string& path);

const char* role_name(BasicManoeuvre::Role role);

}  // namespace deepguide
