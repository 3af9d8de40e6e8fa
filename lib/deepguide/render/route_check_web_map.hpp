#pragma once
// A route file's check as a web map (render/web_map.hpp): `check route --html`.
//
// Layers, each switchable: the cells' no-go by feature (on S-57 charts; a
// click says why), the obstacle files' obstacles (named by a click) and
// their safety zones, the route's legs (each with its length, true course,
// least clearance and nearest obstacle, and on charts what it crosses or
// passes too close to; unsafe legs in red), and the file's waypoints. The
// verdict heads the page; the table lists the waypoints.

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route_file_check.hpp"
#include "deepguide/render/web_map.hpp"

namespace DEEPGUIDE_API deepguide {

/// The map of a check_route_file report made with `options`.
WebMap route_check_web_map(const RouteFileCheckReport& report, const RouteFileCheckOptions& options);

}  // namespace deepguide
