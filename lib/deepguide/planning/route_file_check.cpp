#include "deepguide/planning/route_file_check.hpp"

#include <memory>
#include <optional>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/enc_route_check.hpp"
#include "deepguide/charts/enc_route_quality.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/frame_scale.hpp"

namespace deepguide {
namespace {

// The route against obstacle files: the verdict is the first unsafe part, else
// the part that comes closest.
RouteFileCheckReport check_on_obstacles(const RouteFileCheckOptions& o, const std::vector<RouteFilePart>& parts) {
  // The check never takes the frame a route was planned in (a route file
  // does not say it): it chooses one over the route and the obstacles, or
  // takes the user's, which must keep true metres over both (frame_scale.hpp).
  ObstacleReadOptions read{o.crs, o.src_crs};
  for (const RouteFilePart& part : parts)
    for (const RouteFileWaypoint& w : part.points) read.work_area_lonlat.push_back(w.lonlat);
  const LoadedObstacles loaded = load_obstacles(o.obstacles, read);
  const LocalFrame& frame = loaded.frame;
  const ObstacleField field(loaded.obstacles, o.margin_m);
  RouteFileCheckReport r;
  std::optional<RouteCheck> worst;
  std::string worst_part, first_line;  // the verdict names a part other than the route line
  std::size_t lines = 0, points = 0;
  for (const RouteFilePart& part : parts) {
    const Route route = route_in_frame(part.points, frame, o.route + ": " + part.label);
    if (part.is_point) ++points;
    if (!part.is_point && lines++ == 0) {
      r.waypoints = route.points.size();
      r.length_m = route.length();
      r.details["waypoints"] = r.waypoints, r.details["length_m"] = r.length_m;
      first_line = part.label;
    }
    const RouteCheck check = check_route(route.points, field, kRouteFileTolerance_m);
    const bool first_unsafe = !check.safe && (!worst || worst->safe);
    if (!worst || first_unsafe || (worst->safe && check.min_clearance_m < worst->min_clearance_m)) {
      worst = check;
      worst_part = part.label;
    }
  }
  r.safe = worst->safe;
  r.why = (worst_part != first_line ? worst_part + ": " : std::string()) + worst->describe();
  r.details["safe"] = worst->safe;
  r.details["min_clearance_m"] = worst->min_clearance_m;
  r.details["worst_segment"] = worst->worst_segment;
  r.details["worst_obstacle"] = worst->worst_obstacle;
  r.details["worst_part"] = worst_part;
  r.details["margin_m"] = o.margin_m;
  r.details["lines"] = lines;
  r.details["points"] = points;
  r.details["crs"] = frame.id();
  r.obstacles_frame = frame;
  r.obstacles = loaded.obstacles;
  return r;
}

// The route against S-57 cells, feature by feature: the verdict names the
// first part that crosses.
RouteFileCheckReport check_on_charts(const RouteFileCheckOptions& o, const std::vector<RouteFilePart>& parts) {
  if (std::isnan(o.operating_depth_m)) {
    throw InputError("operating depth: expected the depth (m) to check the route against S-57 charts at");
  }
  const EncNoGoOptions opts = enc_options(o.chart, o.operating_depth_m, o.vertical_clearance_m);
  std::optional<LocalFrame> frame;
  if (!o.crs.empty()) frame = LocalFrame::from_user_crs(o.crs);
  const auto read = std::make_shared<const EncNoGo>(chart_no_go(o.charts, frame, opts));
  const EncNoGo& no_go = *read;
  RouteFileCheckReport r;
  r.enc = read;
  nlohmann::json& j = r.details;
  j = {{"margin_m", o.margin_m}, {"required_depth_m", no_go.required_depth_m}};
  std::size_t lines = 0, points = 0, crossed = 0;
  std::vector<Vec2> lonlat;
  for (const RouteFilePart& part : parts)
    for (const RouteFileWaypoint& w : part.points) lonlat.push_back(w.lonlat);
  require_true_scale(no_go.frame, lonlat, o.route);
  for (const RouteFilePart& part : parts) {
    const Route route = route_in_frame(part.points, no_go.frame, o.route + ": " + part.label);
    if (part.is_point) {
      ++points;
      const EncNoGoFeature* f = no_go_feature_at(no_go, route.points.front(), o.margin_m, kRouteFileTolerance_m);
      if (f != nullptr && r.safe) {
        r.safe = false;
        r.why = part.label + ": lies within " + fixed(o.margin_m, 2) + " m of " + f->id +
                (f->cell.empty() ? "" : " of " + f->cell) + " (" + f->reason + ")";
        j["first_crossing"] = {{"part", part.label}, {"feature", f->id}, {"cell", f->cell},
                               {"class", f->cls},    {"rcid", f->rcid},  {"reason", f->reason}};
      }
      continue;
    }
    if (lines++ == 0) {
      r.waypoints = route.points.size();
      r.length_m = route.length();
      j["waypoints"] = r.waypoints, j["length_m"] = r.length_m;
      if (route.points.size() >= 2) {
        const RouteQuality quality = route_quality(route.points, no_go);
        j["chart_quality"] = quality.to_json(no_go.frame);
        r.chart_quality = quality.to_text(no_go.frame);
      }
    }
    const ChartRouteCheck check = check_route_on_chart(route.points, no_go, o.margin_m, kRouteFileTolerance_m);
    crossed += check.crossed_features;
    if (!check.safe && r.safe) {
      r.safe = false;
      r.why = (parts.size() > 1 ? part.label + ": " : std::string()) + check.describe(no_go.frame);
      const ChartCrossing& c = *check.first;
      const Vec2 ll = no_go.frame.to_lonlat(c.at);
      j["first_crossing"] = {{"part", part.label},      {"feature", c.feature->id},
                             {"cell", c.feature->cell}, {"class", c.feature->cls},
                             {"rcid", c.feature->rcid}, {"reason", c.feature->reason},
                             {"leg", c.leg + 1},        {"along_m", c.along_m},
                             {"lon", ll.x()},           {"lat", ll.y()}};
      if (std::isfinite(c.feature->charted_depth_m))
        j["first_crossing"]["charted_depth_m"] = c.feature->charted_depth_m;
    } else if (r.safe) {
      r.why = check.describe(no_go.frame);
    }
  }
  j["safe"] = r.safe;
  j["crossed_features"] = crossed;
  j["lines"] = lines;
  j["points"] = points;
  return r;
}

}  // namespace

std::string RouteFileCheckReport::to_text() const {
  if (!safe) return "unsafe: " + why;
  std::string t = "safe: " + why + " (" + std::to_string(waypoints) + " waypoints, " + fixed(length_m, 1) + " m)";
  if (!chart_quality.empty()) t += "\n" + chart_quality.substr(0, chart_quality.size() - 1);
  return t;
}

RouteFileCheckReport check_route_file(const RouteFileCheckOptions& o) {
  if (o.obstacles.empty() && o.charts.empty()) {
    throw InputError(o.route + ": expected obstacle files or charts to check the route against");
  }
  if (!std::isfinite(o.margin_m) || o.margin_m < 0.0) {
    throw InputError("margin: expected a safety margin >= 0 m, got " + general(o.margin_m));
  }
  // Every line and point of the file (a second line through an obstacle is not "safe").
  const std::vector<RouteFilePart> parts = read_route_parts(o.route);
  if (o.obstacles.empty()) {
    RouteFileCheckReport r = check_on_charts(o, parts);
    r.parts = parts;
    return r;
  }
  RouteFileCheckReport r = check_on_obstacles(o, parts);
  r.parts = parts;
  if (o.charts.empty()) return r;
  RouteFileCheckReport chart = check_on_charts(o, parts);
  r.enc = std::move(chart.enc);
  r.details["chart"] = chart.details;
  r.details["safe"] = r.safe && chart.safe;
  if (r.safe && !chart.safe) r.why = chart.why;
  if (r.safe && chart.safe) r.why += "; " + chart.why;
  r.safe = r.safe && chart.safe;
  r.chart_quality = chart.chart_quality;
  return r;
}

}  // namespace deepguide
