#pragma once
// `check route` as a library call: every line and point of a route file
// against obstacle files (exact clearance, route_check.hpp) and/or S-57
// charts at an operating depth (the first crossing named, enc_route_check.hpp),
// returned as one report that prints itself as text or JSON.

#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct EncNoGo;  // charts/enc_no_go.hpp

struct RouteFileCheckOptions {
  std::string route;                        ///< the route file (RTZ, GPX, GeoJSON, KML, ...)
  std::vector<std::string> obstacles;       ///< obstacle files
  std::vector<std::string> charts;          ///< S-57 cells, folders of cells, prepared charts
  std::string crs;                          ///< the local frame ("" : from the inputs)
  std::string src_crs;                      ///< CRS of inputs that carry none
  double margin_m = 5.0;                    ///< clearance the route must keep, >= 0
  double operating_depth_m = std::nan("");  ///< needed with charts (m, positive down)
  double vertical_clearance_m = 2.0;        ///< water kept under the vehicle, with charts
  ChartOptions chart;                       ///< charts: zones of confidence, restricted areas
};

struct RouteFileCheckReport {
  bool safe = true;
  /// Why: the first crossing, or where the route comes closest (one line).
  std::string why;
  std::size_t waypoints = 0;  ///< of the file's first line
  double length_m = 0.0;      ///< of the file's first line
  /// On S-57 charts, the first line's quality (enc_route_quality.hpp) as report lines; "" otherwise.
  std::string chart_quality;
  /// The verdict's fields (the obstacles' verdict, with the chart's under
  /// "chart" when both were checked).
  nlohmann::json details = nlohmann::json::object();
  /// What was checked, for a drawing of the check (render/route_check_web_map.hpp):
  /// the file's parts, the obstacles in their frame, the cells' no-go.
  std::vector<RouteFilePart> parts;
  std::optional<LocalFrame> obstacles_frame;
  ObstacleSet obstacles;
  std::shared_ptr<const EncNoGo> enc;

  nlohmann::json to_json() const { return details; }
  /// "safe: WHY (N waypoints, L m)", then the chart quality's lines; or "unsafe: WHY".
  std::string to_text() const;
};

/// Throws InputError for unreadable or malformed inputs (one line), or when
/// neither obstacles nor charts are given, or charts without a depth.
RouteFileCheckReport check_route_file(const RouteFileCheckOptions& options);

}  // namespace deepguide
