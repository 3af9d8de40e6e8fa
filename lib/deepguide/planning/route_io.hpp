#pragma once
// Routes on disk (DESIGN.md): GeoJSON (RFC 7946, lon/lat) with the route line
// and one point per waypoint carrying its index and cumulative length (depth,
// speed, ETA and cost once the planners produce them). Reading accepts any
// OGR source with a LineString (GeoJSON, GPX routes/tracks, KML, ...).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deepguide/planning/route.hpp"
#include "deepguide/world/local_frame.hpp"

namespace deepguide {

/// Writes the route as GeoJSON; `properties` go onto the line feature
/// (summary values such as length_m, min_clearance_m), `waypoint_properties[i]`
/// (when given) onto waypoint i (speed, ETA, cost so far). Atomic.
void write_route_geojson(const std::string& path, const Route& route, const LocalFrame& frame,
                         const nlohmann::json& properties = nlohmann::json::object(),
                         const std::vector<nlohmann::json>& waypoint_properties = {});

/// Reads the first LineString of the file (layers in order) into the local
/// frame. Throws InputError naming the file when there is none or it is broken.
Route read_route(const std::string& path, const LocalFrame& frame);

}  // namespace deepguide
