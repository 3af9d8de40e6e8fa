#pragma once
// Routes on disk: GeoJSON (RFC 7946, lon/lat) with the route line
// and one point per waypoint carrying its index and cumulative length (depth,
// speed, ETA and cost once the planners produce them). Reading accepts any
// OGR source with a LineString (GeoJSON, GPX routes/tracks, KML, ...).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

/// Writes the route as GeoJSON; `properties` go onto the line feature
/// (summary values such as length_m, min_clearance_m), `waypoint_properties[i]`
/// (when given) onto waypoint i (speed, ETA, cost so far). Atomic.
void write_route_geojson(const std::string& path, const Route& route, const LocalFrame& frame,
                         const nlohmann::json& properties = nlohmann::json::object(),
                         const std::vector<nlohmann::json>& waypoint_properties = {});

/// What a route read back from a file may lose to rounding and still be
/// judged by the margin it was planned to: 1 mm. Files round positions (RTZ
/// keeps nine decimals of a degree, 0.1 mm; others fewer), and a route planned
/// to touch the margin comes back a hair inside it; "crosses land" for 0.1 mm
/// would be untrue. Charts and sonar are not metre-exact, so 1 mm hides nothing.
inline constexpr double kRouteFileTolerance_m = 1e-3;

/// A route file's waypoint as the file gives it.
struct RouteFileWaypoint {
  Vec2 lonlat{0.0, 0.0};  ///< WGS 84 degrees
  std::string name;       ///< RTZ waypoint names; empty where the file has none
};

/// The waypoints of a route file in WGS 84: an RTZ route (IEC 61174, any
/// version and namespace, read with libxml2: `waypoints/waypoint/position`),
/// or the first line of any OGR source (layers in order: GeoJSON, a
/// GPX route or track from OpenCPN or a plotter, KML, ...). Throws InputError
/// naming the file, and the feature or waypoint, for one that is missing,
/// broken, or has fewer than 2 points.
std::vector<RouteFileWaypoint> read_route_waypoints(const std::string& path);

/// A line or a point of a route file, with where it is in the file ("route
/// feature 3", "tracks feature 0 part 2"): what `check route` checks, all of them.
struct RouteFilePart {
  std::string label;
  std::vector<RouteFileWaypoint> points;  ///< one for a point, at least two for a line
  bool is_point = false;
};

/// Every line and point of the file in order (an RTZ file: its route). A file
/// of points and no line (a CSV of waypoints) is one line through its points
/// in file order. Throws as read_route_waypoints, and for a file with neither.
std::vector<RouteFilePart> read_route_parts(const std::string& path);

/// Waypoints in the local frame; `where` names them in the error for one
/// outside the frame's area of use ("route.rtz: route").
Route route_in_frame(const std::vector<RouteFileWaypoint>& waypoints, const LocalFrame& frame,
                     const std::string& where);

/// read_route_waypoints in the local frame. Throws InputError naming the
/// waypoint for one outside the frame's area of use.
Route read_route(const std::string& path, const LocalFrame& frame);

}  // namespace deepguide
