#include "deepguide/render/route_check_web_map.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/charts/enc_route_check.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/render/chart_web_map.hpp"
#include "deepguide/render/obstacle_web_layers.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace deepguide {

namespace {

using json = nlohmann::ordered_json;

json rounded(double v, double unit) { return std::round(v / unit) * unit; }

}  // namespace

WebMap route_check_web_map(const RouteFileCheckReport& report, const RouteFileCheckOptions& options) {
  WebMap map;
  map.title = std::filesystem::path(options.route).filename().string() + ": " + (report.safe ? "safe" : "unsafe");
  map.subtitle = report.why;
  const LocalFrame frame = report.obstacles_frame ? *report.obstacles_frame : report.enc->frame;
  const WebMapGeometry to{&frame};
  if (report.enc) map.layers.push_back(enc_no_go_layer(*report.enc, options.operating_depth_m));
  std::optional<ObstacleField> field;
  if (report.obstacles_frame) {
    map.layers.push_back(obstacle_web_layer(report.obstacles, to, "Obstacles"));
    map.layers.push_back(zone_web_layer(report.obstacles, to, options.margin_m, 0.05));
    field.emplace(report.obstacles, options.margin_m);
  }

  WebMapLayer legs;
  legs.id = "legs";
  legs.name = "Route legs (unsafe in red)";
  legs.stroke = "#f08c00";
  legs.fill_opacity = 0.0;
  legs.weight = 4.0;
  WebMapLayer points;
  points.id = "waypoints";
  points.name = "Waypoints";
  points.stroke = "#212529";
  points.fill = "#ffd43b";
  points.fill_opacity = 1.0;
  points.weight = 1.5;
  points.point_radius_px = 5.0;
  map.table.title = "Waypoints";
  map.table.columns = {"#", "name", "lon", "lat", "next leg (m)", "its least clearance (m)"};
  for (const RouteFilePart& part : report.parts) {
    for (const RouteFileWaypoint& w : part.points) {  // the page opens on the route
      LonLatExtent& f = map.focus;
      f.west = std::isnan(f.west) ? w.lonlat.x() : std::min(f.west, w.lonlat.x());
      f.east = std::isnan(f.east) ? w.lonlat.x() : std::max(f.east, w.lonlat.x());
      f.south = std::isnan(f.south) ? w.lonlat.y() : std::min(f.south, w.lonlat.y());
      f.north = std::isnan(f.north) ? w.lonlat.y() : std::max(f.north, w.lonlat.y());
    }
    std::vector<Vec2> xy;
    for (const RouteFileWaypoint& w : part.points) xy.push_back(frame.from_lonlat(w.lonlat.x(), w.lonlat.y()));
    for (std::size_t i = 0; i < xy.size(); ++i) {
      const json position = web_map_position(part.points[i].lonlat.x(), part.points[i].lonlat.y());
      json props{{"part", part.label}, {"waypoint", i + 1}};
      if (!part.points[i].name.empty()) props["name"] = part.points[i].name;
      props["lon"] = position[0], props["lat"] = position[1];
      points.features.push_back(web_map_feature({{"type", "Point"}, {"coordinates", position}}, std::move(props)));
      json clearance = nullptr, length = nullptr;
      if (i + 1 < xy.size()) {
        json leg{{"part", part.label}, {"leg", i + 1}};
        const Vec2 d = xy[i + 1] - xy[i];
        leg["length (m)"] = length = rounded(d.norm(), 0.01);
        leg["course (deg true)"] = rounded(frame.local_to_heading(std::atan2(d.y(), d.x()), xy[i]), 0.1);
        bool safe = true;
        if (field) {
          const RouteCheck check = check_route({xy[i], xy[i + 1]}, *field, kRouteFileTolerance_m);
          safe = check.safe;
          if (std::isfinite(check.min_clearance_m)) {
            leg["least clearance (m)"] = clearance = rounded(check.min_clearance_m, 0.01);
            leg["nearest obstacle"] = check.worst_obstacle;
          }
        }
        if (report.enc) {
          const Vec2 a = report.enc->frame.from_lonlat(part.points[i].lonlat.x(), part.points[i].lonlat.y());
          const Vec2 b = report.enc->frame.from_lonlat(part.points[i + 1].lonlat.x(), part.points[i + 1].lonlat.y());
          const ChartRouteCheck chart =
              check_route_on_chart({a, b}, *report.enc, options.margin_m, kRouteFileTolerance_m);
          safe = safe && chart.safe;
          leg["chart"] = chart.describe(report.enc->frame);
        }
        leg["safe"] = safe ? "yes" : "no";
        legs.features.push_back(web_map_feature(to.line({xy[i], xy[i + 1]}), std::move(leg),
                                                safe ? json(nullptr) : json{{"color", "#e03131"}}));
      }
      if (part.is_point) continue;
      map.table.rows.push_back({static_cast<int>(map.table.rows.size() + 1), part.points[i].name, position[0],
                                position[1], length, clearance});
    }
  }
  map.layers.push_back(std::move(legs));
  map.layers.push_back(std::move(points));
  if (!map.focus.empty()) {  // the frame's grid round the route
    Vec2 lo = frame.from_lonlat(map.focus.west, map.focus.south), hi = lo;
    for (const double lon : {map.focus.west, map.focus.east}) {
      for (const double lat : {map.focus.south, map.focus.north}) {
        const Vec2 p = frame.from_lonlat(lon, lat);
        lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      }
    }
    const Vec2 pad = Vec2::Constant(0.2 * std::max(hi.x() - lo.x(), hi.y() - lo.y()) + 100.0);
    map.layers.push_back(frame_grid_layer(frame, lo - pad, hi + pad));
  }
  return map;
}

}  // namespace deepguide
