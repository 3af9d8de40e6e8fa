// deepguide check route ROUTE (--obstacles FILE... | --chart CELL|FOLDER... --depth D) [--margin M] [--json]

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/enc_route_check.hpp"
#include "deepguide/world/prepared_chart.hpp"
#include "deepguide/world/obstacle_io.hpp"

namespace deepguide::app {
namespace {
struct CheckOptions {
  std::string route;
  std::vector<std::string> obstacles;
  std::vector<std::string> charts;
  FrameOptions frame;
  double margin = 5.0;
  double depth = std::nan("");
  double clearance = 2.0;
  bool restricted = false;
  bool no_zoc = false;
  bool json = false;
};

// The route against S-57 cells, feature by feature (enc_route_check.hpp).
nlohmann::json check_on_chart(const CheckOptions& o, bool& safe, std::string& why) {
  if (std::isnan(o.depth)) throw InputError("--depth: expected the operating depth (m) to check against S-57 charts");
  EncNoGoOptions opts;
  opts.operating_depth_m = o.depth;
  opts.vertical_clearance_m = o.clearance;
  opts.restricted_areas = o.restricted;
  opts.zone_of_confidence = !o.no_zoc;
  std::optional<LocalFrame> frame;
  if (!o.frame.crs.empty()) frame = LocalFrame::from_user_crs(o.frame.crs);
  const EncNoGo no_go = chart_no_go(o.charts, frame, opts);
  // Every line and point of the file; the verdict names the first part that crosses.
  const std::vector<RouteFilePart> parts = read_route_parts(o.route);
  nlohmann::json j = {{"margin_m", o.margin}, {"required_depth_m", no_go.required_depth_m}};
  std::size_t lines = 0, points = 0, crossed = 0;
  safe = true;
  for (const RouteFilePart& part : parts) {
    const Route route = route_in_frame(part.points, no_go.frame, o.route + ": " + part.label);
    if (part.is_point) {
      ++points;
      if (const EncNoGoFeature* f = no_go_feature_at(no_go, route.points.front(), o.margin, kRouteFileTolerance_m); f && safe) {
        safe = false;
        why = part.label + ": lies within " + fixed(o.margin, 2) + " m of " + f->id + (f->cell.empty() ? "" : " of " + f->cell) +
              " (" + f->reason + ")";
        j["first_crossing"] = {{"part", part.label}, {"feature", f->id}, {"cell", f->cell}, {"class", f->cls},
                               {"rcid", f->rcid}, {"reason", f->reason}};
      }
      continue;
    }
    if (lines++ == 0) j["waypoints"] = route.points.size(), j["length_m"] = route.length();
    const ChartRouteCheck check = check_route_on_chart(route.points, no_go, o.margin, kRouteFileTolerance_m);
    crossed += check.crossed_features;
    if (!check.safe && safe) {
      safe = false;
      why = (parts.size() > 1 ? part.label + ": " : std::string()) + check.describe(no_go.frame);
      const ChartCrossing& c = *check.first;
      const Vec2 ll = no_go.frame.to_lonlat(c.at);
      j["first_crossing"] = {{"part", part.label},          {"feature", c.feature->id}, {"cell", c.feature->cell},
                             {"class", c.feature->cls},     {"rcid", c.feature->rcid},  {"reason", c.feature->reason},
                             {"leg", c.leg + 1},            {"along_m", c.along_m},     {"lon", ll.x()},
                             {"lat", ll.y()}};
      if (std::isfinite(c.feature->charted_depth_m)) j["first_crossing"]["charted_depth_m"] = c.feature->charted_depth_m;
    } else if (safe) {
      why = check.describe(no_go.frame);
    }
  }
  j["safe"] = safe;
  j["crossed_features"] = crossed;
  j["lines"] = lines;
  j["points"] = points;
  return j;
}

}  // namespace

void register_check_route(CLI::App& check) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* cmd = check.add_subcommand(
      "route", "Check a route against obstacles (exact clearance) or S-57 charts at a depth (the first crossing "
               "named); exit 1 when the route is unsafe");
  cmd->add_option("ROUTE", o->route, "Route file: RTZ (an ECDIS's), GPX (OpenCPN's), GeoJSON, KML, ... with a line")
      ->required();
  cmd->add_option("--obstacles", o->obstacles, "Obstacle files")->expected(1, -1);
  cmd->add_option("--chart", o->charts,
                  "S-57 cells (*.000, updates beside them), folders of cells, or a prepared chart (.gpkg)")
      ->expected(1, -1);
  cmd->add_option("--depth", o->depth, "Operating depth (m, positive down), for --chart");
  cmd->add_option("--vertical-clearance", o->clearance, "Water kept under the vehicle (m), for --chart")
      ->capture_default_str();
  cmd->add_flag("--restricted", o->restricted, "--chart: restricted areas (RESTRN 7, 8, 14) are no-go too");
  cmd->add_flag("--no-zoc", o->no_zoc, "--chart: charted depths and positions as exact (no zone of confidence)");
  add_frame_options(*cmd, o->frame);
  cmd->add_option("--margin", o->margin, "Safety margin the route must keep (m)")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print the verdict as JSON");
  cmd->callback([o] {
    if (o->obstacles.empty() && o->charts.empty()) {
      throw CLI::ValidationError("check route", "give --obstacles FILE... or --chart CELL... (or both)");
    }
    if (!std::isfinite(o->margin) || o->margin < 0.0) {
      throw InputError("--margin: expected a safety margin >= 0 m, got " + std::to_string(o->margin));
    }
    nlohmann::json out = nlohmann::json::object();
    bool safe = true;
    std::string why;
    if (!o->obstacles.empty()) {
      const LoadedObstacles loaded = load_obstacles(o->obstacles, {o->frame.crs, o->frame.src_crs});
      // Every line and point of the file (a second line through an obstacle is not "safe").
      const std::vector<RouteFilePart> parts = read_route_parts(o->route);
      // Files without an obstacle fix no frame: the route's start does (its UTM zone).
      LocalFrame frame = loaded.frame;
      if (loaded.obstacles.empty() && o->frame.crs.empty()) {
        const Vec2 start = parts.front().points.front().lonlat;
        frame = LocalFrame::utm_for(start.x(), start.y());
      }
      const ObstacleField field(loaded.obstacles, o->margin);
      std::optional<RouteCheck> worst;
      std::string worst_part, first_line;  // the verdict names a part other than the route line
      std::size_t lines = 0, points = 0;
      for (const RouteFilePart& part : parts) {
        const Route route = route_in_frame(part.points, frame, o->route + ": " + part.label);
        if (part.is_point) ++points;
        if (!part.is_point && lines++ == 0) {
          out["waypoints"] = route.points.size(), out["length_m"] = route.length();
          first_line = part.label;
        }
        const RouteCheck check = check_route(route.points, field, kRouteFileTolerance_m);
        // The verdict: the first unsafe part, else the part that comes closest.
        const bool first_unsafe = !check.safe && (!worst || worst->safe);
        if (!worst || first_unsafe || (worst->safe && check.min_clearance_m < worst->min_clearance_m)) {
          worst = check;
          worst_part = part.label;
        }
      }
      out["safe"] = worst->safe;
      out["min_clearance_m"] = worst->min_clearance_m;
      out["worst_segment"] = worst->worst_segment;
      out["worst_obstacle"] = worst->worst_obstacle;
      out["worst_part"] = worst_part;
      out["margin_m"] = o->margin;
      out["lines"] = lines;
      out["points"] = points;
      out["crs"] = frame.id();
      safe = worst->safe;
      why = (worst_part != first_line ? worst_part + ": " : std::string()) + worst->describe();
    }
    if (!o->charts.empty()) {
      bool chart_safe = true;
      std::string chart_why;
      const nlohmann::json chart = check_on_chart(*o, chart_safe, chart_why);
      if (o->obstacles.empty()) {
        out = chart;
      } else {
        out["chart"] = chart;
        out["safe"] = safe && chart_safe;
      }
      if (safe && !chart_safe) why = chart_why;
      if (safe && chart_safe) why = o->obstacles.empty() ? chart_why : why + "; " + chart_why;
      safe = safe && chart_safe;
    }
    if (o->json) {
      std::cout << out.dump(2) << "\n";
    } else if (safe) {
      std::cout << "safe: " << why << " (" << out.value("waypoints", std::size_t{0}) << " waypoints, "
                << fixed(out.value("length_m", 0.0), 1) << " m)\n";
    }
    if (!safe) throw InputError(o->route + ": " + why);
  });
}

}  // namespace deepguide::app
