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

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/mission/route_export.hpp"

namespace DEEPGUIDE_API deepguide {

/// The plan's waypoints: the start, then each line's end, the chords' ends
/// along arcs (with the arc's radius), and each point (with its hold and depth).
std::vector<ExportWaypoint> export_waypoints(const Mission& mission, const MissionPlan& plan,
                                             double arc_tolerance_m = 0.5);

/// The plan's waypoints for a reader that turns at each waypoint on its
/// radius (an ECDIS with RTZ): each arc, cut into pieces of at most 90
/// degrees, is one waypoint per piece where the piece's tangents meet, at
/// R / cos(phi / 2) from the centre with the arc's radius R, and a turn of R
/// there is the arc itself (tangent points R tan(phi / 2) either side, on the
/// arc). A line that ends where an arc begins leaves its end to the arc's
/// corner; other line ends, and the plan's start and end, are waypoints as in
/// export_waypoints, holds on the waypoint where they are. A corner's along_m
/// and time_s are those of its piece's middle.
std::vector<ExportWaypoint> export_corner_waypoints(const Mission& mission, const MissionPlan& plan);

/// The plan as a route for write_route_file: its waypoints, the mission's
/// name, and the vehicle's turn radius, vertical and top speeds. `corners`:
/// export_corner_waypoints instead of chords.
ExportRoute export_route(const Mission& mission, const MissionPlan& plan, double arc_tolerance_m = 0.5,
                         bool corners = false);

/// Writes the plan to `path` in `format`. Throws InputError naming the path
/// for an existing file without overwrite, a missing folder, or a failed write.
void export_plan(const Mission& mission, const MissionPlan& plan, const std::string& path, ExportFormat format,
                 const ExportOptions& options = {});

/// Reads a plan written as yaml (its basic manoeuvres; warnings are not kept).
/// Throws InputError naming the file and line for anything else.
MissionPlan read_plan_yaml(const std::string& path);

const char* role_name(BasicManoeuvre::Role role);

}  // namespace deepguide
