#include "deepguide/render/route_web_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "deepguide/core/format.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/render/chart_web_map.hpp"
#include "deepguide/render/obstacle_web_layers.hpp"

namespace deepguide {

namespace {

using json = nlohmann::ordered_json;

using ToLonLat = WebMapGeometry;

// A number to the metre's hundredth (or what a value needs), for a popup.
json metres(double v) { return std::round(v * 100.0) / 100.0; }

}  // namespace

WebMap route_web_map(const RoutePlanReport& report) {
  const LocalFrame& frame = report.frame;
  const ToLonLat to{&frame};
  const RoutePlanRequest& r = report.request;
  const std::vector<Vec2>& points = report.route.points;
  WebMap map;
  map.title =
      "Route: " + fixed(report.route.length() / 1000.0, 2) + " km, " + std::to_string(points.size()) + " waypoints";
  map.subtitle = "graph " + to_string(report.options.graph) + ", margin " + general(r.margin_m) + " m" +
                 (std::isnan(r.depth_m) ? std::string() : ", depth " + general(r.depth_m) + " m") + ", frame " +
                 frame.id();
  if (report.enc) map.layers.push_back(enc_no_go_layer(*report.enc, r.depth_m));
  map.layers.push_back(
      obstacle_web_layer(report.obstacles, to, report.enc ? "No-go as planned (unioned) and obstacles" : "Obstacles"));
  map.layers.push_back(zone_web_layer(report.obstacles, to, r.margin_m, r.tolerance_m));

  WebMapLayer legs;
  legs.id = "route";
  legs.name = "Route legs";
  legs.stroke = "#f08c00";
  legs.weight = 4.0;
  legs.fill_opacity = 0.0;
  const ObstacleField& field = report.plan.planner->field();
  std::vector<double> courses;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec2 d = points[i + 1] - points[i];
    courses.push_back(frame.local_to_heading(std::atan2(d.y(), d.x()), points[i]));
    const RouteCheck check = check_route({points[i], points[i + 1]}, field);
    json props{{"leg", i + 1}, {"from waypoint", i + 1}, {"to waypoint", i + 2}};
    props["length (m)"] = metres(d.norm());
    props["course (deg true)"] = std::round(courses.back() * 10.0) / 10.0;
    if (std::isfinite(check.min_clearance_m)) {
      props["least clearance (m)"] = metres(check.min_clearance_m);
      props["nearest obstacle"] = check.worst_obstacle;
    }
    json geometry = to.line({points[i], points[i + 1]});
    legs.features.push_back(web_map_feature(std::move(geometry), std::move(props)));
  }
  map.layers.push_back(std::move(legs));

  WebMapLayer waypoints;
  waypoints.id = "waypoints";
  waypoints.name = "Waypoints";
  waypoints.stroke = "#212529";
  waypoints.fill = "#ffd43b";
  waypoints.fill_opacity = 1.0;
  waypoints.weight = 1.5;
  waypoints.point_radius_px = 5.0;
  const std::vector<nlohmann::json> timing = report.waypoint_properties();
  map.table.title = "Waypoints";
  map.table.columns = {"#", "lon", "lat", "leg (m)", "course (deg true)", report.timed ? "ETA" : "time (s)"};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const json position = to.position(points[i]);
    json props{{"waypoint", i + 1}, {"lon", position[0]}, {"lat", position[1]}};
    const nlohmann::json& t = timing[i];
    if (t.contains("speed_mps")) props["speed (m/s)"] = std::round(t["speed_mps"].get<double>() * 1000.0) / 1000.0;
    json when = nullptr;
    if (t.contains("eta")) {
      when = t["eta"].get<std::string>();
      props["ETA"] = when;
    } else if (t.contains("cum_time_s")) {
      when = std::round(t["cum_time_s"].get<double>() * 10.0) / 10.0;
      props["time (s)"] = when;
    }
    if (report.options.turn_radius_m > 0.0) props["turn radius (m)"] = metres(report.options.turn_radius_m);
    if (!std::isnan(r.depth_m)) props["depth (m)"] = r.depth_m;
    json geometry = to.point(points[i]);
    waypoints.features.push_back(web_map_feature(std::move(geometry), std::move(props)));
    map.table.rows.push_back({static_cast<int>(i + 1), position[0], position[1],
                              i == 0 ? json(nullptr) : metres((points[i] - points[i - 1]).norm()),
                              i + 1 < points.size() ? json(std::round(courses[i] * 10.0) / 10.0) : json(nullptr),
                              when});
  }
  map.layers.push_back(std::move(waypoints));

  {  // The frame's grid round the route.
    Vec2 lo = points.front(), hi = points.front();
    for (const Vec2& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Vec2 pad = Vec2::Constant(0.2 * std::max(hi.x() - lo.x(), hi.y() - lo.y()) + 100.0);
    map.layers.push_back(frame_grid_layer(frame, lo - pad, hi + pad));
  }
  // First the route, with a margin round it.
  LonLatExtent& f = map.focus;
  for (const Vec2& p : points) {
    const Vec2 ll = frame.to_lonlat(p);
    f.west = std::isnan(f.west) ? ll.x() : std::min(f.west, ll.x());
    f.east = std::isnan(f.east) ? ll.x() : std::max(f.east, ll.x());
    f.south = std::isnan(f.south) ? ll.y() : std::min(f.south, ll.y());
    f.north = std::isnan(f.north) ? ll.y() : std::max(f.north, ll.y());
  }
  return map;
}

}  // namespace deepguide
