#include "deepguide/render/route_web_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "deepguide/core/format.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "deepguide/render/chart_web_map.hpp"
#include "deepguide/render/reactive_map.hpp"  // ellipse_outline

namespace deepguide {

namespace {

using json = nlohmann::ordered_json;

using ToLonLat = WebMapGeometry;

// A number to the metre's hundredth (or what a value needs), for a popup.
json metres(double v) { return std::round(v * 100.0) / 100.0; }

WebMapLayer obstacles_layer(const ObstacleSet& obstacles, const ToLonLat& to, bool charted) {
  WebMapLayer layer;
  layer.id = "obstacles";
  layer.name = charted ? "No-go as planned (unioned) and obstacles" : "Obstacles";
  layer.stroke = "#862e9c";
  layer.fill = "#862e9c";
  layer.fill_opacity = 0.25;
  layer.weight = 1.0;
  const auto top = [](json& props, const std::optional<double>& top_depth_m) {
    if (top_depth_m) props["top depth (m)"] = metres(*top_depth_m);
  };
  for (const EllipticCylinder& e : obstacles.ellipses) {
    json props{{"obstacle", e.id}, {"shape", "ellipse"}};
    props["semi-axes (m)"] = fixed(e.footprint.a, 2) + " x " + fixed(e.footprint.b, 2);
    top(props, e.top_depth_m);
    json geometry = to.outline(ellipse_outline(e.footprint, 72));
    layer.features.push_back(web_map_feature(std::move(geometry), std::move(props)));
  }
  for (const PolygonObstacle& p : obstacles.polygons) {
    json props{{"obstacle", p.id}, {"shape", "polygon"}};
    top(props, p.top_depth_m);
    json geometry = to.polygon(p.footprint);
    layer.features.push_back(web_map_feature(std::move(geometry), std::move(props)));
  }
  return layer;
}

WebMapLayer zones_layer(const RoutePlanReport& report, const ToLonLat& to) {
  WebMapLayer layer;
  layer.id = "zones";
  layer.name = "Safety zones (margin " + general(report.request.margin_m) + " m)";
  layer.stroke = "#e8590c";
  layer.fill = "#e8590c";
  layer.fill_opacity = 0.04;
  layer.weight = 1.0;
  layer.dash = "5 4";
  const BgMultiPolygon zones =
      merged_zone_polygons(report.obstacles, {report.request.margin_m, report.request.tolerance_m});
  for (std::size_t i = 0; i < zones.size(); ++i) {
    json geometry = to.polygon(zones[i]);
    layer.features.push_back(web_map_feature(std::move(geometry), {{"safety zone", i + 1}}));
  }
  return layer;
}

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
  map.layers.push_back(obstacles_layer(report.obstacles, to, report.enc != nullptr));
  map.layers.push_back(zones_layer(report, to));

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
