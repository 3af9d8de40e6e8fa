#pragma once
// A mission plan as the files vehicles and ground stations read
// (docs/MISSIONS.md, "Export"). Every format but our own YAML carries the
// plan as waypoints: the basic manoeuvres' track with arcs as chords at most
// `arc_tolerance_m` inside them, each with its depth, speed, hold, distance
// and time along. GDAL writes what it writes (GeoJSON, GPX, KML, CSV);
// nlohmann/json the QGroundControl plan, libxml2 the RTZ route, yaml-cpp our
// YAML; the MOOS-IvP behaviour file is plain text.
//
//   yaml      the basic manoeuvres themselves (lines, arcs, points; x, y in the
//             mission's CRS), read back by read_plan_yaml
//   geojson   the route line and one point per waypoint (planning/route_io.hpp)
//   gpx       a GPX 1.1 route (rte/rtept), elevation = -depth
//   kml       the route as a LineString (altitude = -depth; GDAL writes no
//             altitudeMode, so viewers draw it clamped to the ground) and the waypoints
//   csv       one row per waypoint: lon, lat, x, y, depth, speed, hold, along, time, role
//   plan      QGroundControl's plan file: MAV_CMD_NAV_WAYPOINT (16) items in
//             MAV_FRAME_GLOBAL_RELATIVE_ALT (3) with depth as negative
//             altitude (as ArduSub reads them; the surface as 1 cm deep, since
//             ArduSub reads 0 as "keep the depth"), hold in param 1; speed changes
//             as MAV_CMD_DO_CHANGE_SPEED (178); vehicle type submarine
//   moos      a pHelmIvP behaviour file: per leg of one depth and speed a
//             BHV_Waypoint (`points = x,y : ...` in local coordinates: metres
//             east and north of the origin in its UTM zone, as MOOSGeodesy's
//             LatLong2LocalUTM) and a BHV_ConstantDepth, holds as
//             BHV_StationKeep, legs chained by DG_LEG; the origin (the start)
//             is in the header for the .moos file's LatOrigin/LongOrigin; a
//             leg holds the shallower depth of its two ends
//   rtz       IEC 61174 RTZ 1.0: waypoints with lat/lon and their legs'
//             speed (knots); depth and hold in a deepguide extension
// Writes are atomic (a temporary file beside the destination, then a rename)
// and refuse an existing file unless `overwrite`.

#include <string>
#include <vector>

#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/mission.hpp"

namespace deepguide {

enum class ExportFormat { yaml, geojson, gpx, kml, csv, qgc_plan, moos, rtz };

/// "yaml", "geojson", "gpx", "kml", "csv", "plan", "moos", "rtz"; InputError otherwise.
ExportFormat parse_export_format(const std::string& name);
/// From the file's extension: .yaml/.yml, .geojson/.json, .gpx, .kml, .csv,
/// .plan, .bhv, .rtz; InputError (naming the path and the extensions) otherwise.
ExportFormat export_format_for(const std::string& path);
std::string to_string(ExportFormat format);

struct ExportWaypoint {
  Vec2 xy{0.0, 0.0};      ///< the mission's frame
  Vec2 lonlat{0.0, 0.0};  ///< WGS 84 degrees
  double depth_m = 0.0;   ///< on arrival
  double speed_mps = 0.0; ///< of the leg arriving here (the first: of the first manoeuvre)
  double hold_s = 0.0;    ///< time held here
  double along_m = 0.0;
  double time_s = 0.0;    ///< on arrival, at the planned speeds and holds
  BasicManoeuvre::Role role = BasicManoeuvre::Role::mission;
  std::string manoeuvre;  ///< the complex manoeuvre's name
};

struct ExportOptions {
  double arc_tolerance_m = 0.5;
  bool overwrite = false;
};

/// The plan's waypoints (the header): the start, then each line's end, the
/// chords' ends along arcs, and each point (with its hold and depth).
std::vector<ExportWaypoint> export_waypoints(const Mission& mission, const MissionPlan& plan,
                                             double arc_tolerance_m = 0.5);

/// Writes the plan to `path` in `format`. Throws InputError naming the path
/// for an existing file without overwrite, a missing folder, or a failed write.
void export_plan(const Mission& mission, const MissionPlan& plan, const std::string& path, ExportFormat format,
                 const ExportOptions& options = {});

/// Reads a plan written as yaml (its basic manoeuvres; warnings are not kept).
/// Throws InputError naming the file and line for anything else.
MissionPlan read_plan_yaml(const std::string& path);

const char* role_name(BasicManoeuvre::Role role);

}  // namespace deepguide
