#pragma once
// One set of route writers for every file a route or a mission plan leaves in
// (docs/MISSIONS.md, "Export"): `plan -o`, `mission export` and anything else
// that writes waypoints. The format comes from the file's extension; each
// writer puts names, depths, speeds, holds and turn radii where its format
// has a conventional place for them:
//
//   geojson  the route line and one point per waypoint with every field
//            (planning/route_io.hpp), RFC 7946
//   gpx      a GPX 1.1 route: <rte><name>, each <rtept> with <ele> = -depth,
//            <name>, <desc>, and depth_m, speed_mps, hold_s, radius_m in
//            <extensions> (namespace https://deepguide.dev/gpx/1, prefix dg)
//   kml      the route as a LineString and one Placemark per waypoint, all
//            with <altitudeMode>absolute</altitudeMode> and altitude = -depth
//            (below sea level, as Google Earth draws it), the fields as
//            typed ExtendedData (SchemaData)
//   csv      one row per waypoint: WKT (POINT Z lon lat -depth, WGS 84, which
//            GDAL opens without options), name, lon, lat, x_m, y_m (the
//            frame named in the crs column), depth_m, speed_mps, hold_s,
//            radius_m, along_m, time_s, role, manoeuvre
//   plan     QGroundControl's plan file (ArduSub: depth as negative altitude)
//   moos     a pHelmIvP behaviour file (.bhv)
//   rtz      IEC 61174 RTZ 1.0 (see export_rtz.cpp)
// Writes are atomic (a temporary file beside the destination, then a rename)
// and refuse an existing file unless `overwrite`.

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

enum class ExportFormat { yaml, geojson, gpx, kml, csv, qgc_plan, moos, rtz };

/// "yaml", "geojson", "gpx", "kml", "csv", "plan", "moos", "rtz"; InputError otherwise.
ExportFormat parse_export_format(const std::string& name);
/// From the file's extension: .yaml/.yml, .geojson/.json, .gpx, .kml, .csv,
/// .plan, .bhv, .rtz; InputError (naming the path and the extensions) otherwise.
ExportFormat export_format_for(const std::string& path);
std::string to_string(ExportFormat format);
/// The format of a route file from its name: export_format_for, but not
/// .yaml (a mission's basic manoeuvres, not a route); InputError otherwise.
ExportFormat route_file_format(const std::string& path);

struct ExportWaypoint {
  Vec2 xy{0.0, 0.0};       ///< the route's frame
  Vec2 lonlat{0.0, 0.0};   ///< WGS 84 degrees
  std::string name;        ///< short and unique in the route ("001", ...)
  double depth_m = 0.0;    ///< on arrival
  double speed_mps = 0.0;  ///< of the leg arriving here (the first: of the first leg)
  double hold_s = 0.0;     ///< time held here
  double radius_m = 0.0;   ///< the turn here: an arc's radius; 0 = the route's turn radius
  double along_m = 0.0;
  double time_s = 0.0;           ///< on arrival, at the planned speeds and holds
  std::string role = "mission";  ///< mission, evasion or identification
  std::string manoeuvre;         ///< the complex manoeuvre's name (missions)
};

/// A route as the writers take it.
struct ExportRoute {
  std::string name;  ///< the route's or mission's name
  LocalFrame frame;  ///< the frame of the waypoints' xy
  std::vector<ExportWaypoint> waypoints = {};
  double length_m = 0.0;
  double turn_radius_m = 0.0;                            ///< the vehicle's smallest turn; 0 = not known
  double vertical_speed_mps = 0.5;                       ///< the vehicle's (the .bhv's depth changes)
  double max_speed_mps = 0.0;                            ///< the vehicle's; 0 = not known (RTZ speedMax)
  double xtd_m = NAN;                                    ///< allowed cross-track distance each side (the margin)
  double safety_depth_m = NAN;                           ///< the water depth the route needs (RTZ safetyDepth)
  std::optional<double> depart_utc_s = std::nullopt;     ///< for ETAs (RTZ schedules); none = times only
  nlohmann::json properties = nlohmann::json::object();  ///< more on the GeoJSON line
  std::vector<nlohmann::json> waypoint_properties = {};  ///< more on each GeoJSON point (when given, one each)
};

/// How a planned route becomes waypoints (export_route below).
struct RouteExportSettings {
  std::string name;                    ///< the route's name (GPX rte, KML, the .bhv header)
  double depth_m = 0.0;                ///< every waypoint's depth when the route has none of its own
  std::vector<double> leg_speeds_mps;  ///< through the water, leg i from waypoint i to i+1; empty = cruise
  std::vector<double> leg_times_s;     ///< leg i's time (in a current); empty = length / speed
  double margin_m = NAN;               ///< kept from every zone: the cross-track distance allowed
  double safety_depth_m = NAN;         ///< the water depth the route needs
  std::optional<double> depart_utc_s = std::nullopt;
  /// The route's least turn (m) when it was planned within one (plan
  /// --turn-radius); 0 = the vehicle's at its fastest leg. Every waypoint
  /// turns on it: an arc's polyline has its corners where the arc's tangent
  /// lines meet, and a turn of this radius at each corner is the arc itself.
  double turn_radius_m = 0.0;
};

/// A planned route as the writers take it: names "001"..., depths, each
/// waypoint's arriving leg speed and time along, and the vehicle's turn
/// radius at its fastest leg, vertical and top speeds.
ExportRoute export_route(const Route& route, const LocalFrame& frame, const VehicleParams& vehicle,
                         const RouteExportSettings& settings);

struct ExportOptions {
  double arc_tolerance_m = 0.5;  ///< missions: arcs as chords at most this far inside
  bool overwrite = false;
  std::string route_name = {};  ///< RTZ routeName; empty = the file's name without extension
};

/// Waypoint names "001", "002", ... (wider past 999), as OpenCPN numbers them.
std::string waypoint_name(std::size_t index, std::size_t count);

/// Writes the route to `path` in `format` (any but yaml, which is a mission's
/// basic manoeuvres). Throws InputError naming the path for an existing file
/// without overwrite, a missing folder, fewer than two waypoints, or a failed
/// write; nothing is left behind then.
void write_route_file(const ExportRoute& route, const std::string& path, ExportFormat format,
                      const ExportOptions& options = {});

}  // namespace deepguide
