// deepguide plan --graph octree: a route in depth over the sea floor of a
// bathymetry chart and the obstacles' tops (planning/depth_planning.hpp).

#include "plan_depth.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/depth_plan_report.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/render/depth_profile.hpp"
#include "deepguide/render/route_scene.hpp"

namespace deepguide::app {
namespace {

// "TOP,BOTTOM" in metres, depths positive down; the checks on the values are the volume's.
std::pair<double, double> parse_band(const std::string& text) {
  double top = 0.0, bottom = 0.0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &top, &bottom, &tail) != 2) {
    throw InputError("--depth-band: expected TOP,BOTTOM in metres (depths, positive down), got '" + text + "'");
  }
  return {top, bottom};
}

}  // namespace

void run_plan_in_depth(const DepthCommand& c) {
  DepthPlanRequest r;
  r.obstacles = c.obstacles;
  r.charts = c.charts;
  r.src_crs = c.src_crs;
  r.start = c.start;
  r.goal = c.goal;
  r.start_depth_m = std::isnan(c.from_depth) ? c.depth : c.from_depth;
  r.goal_depth_m = std::isnan(c.to_depth) ? c.depth : c.to_depth;
  if (std::isnan(r.start_depth_m) || std::isnan(r.goal_depth_m)) {
    throw InputError("--graph octree: expected the start's and the goal's depth (--depth, or --from-depth and "
                     "--to-depth)");
  }
  if (!c.depth_band.empty()) std::tie(r.band_top_m, r.band_bottom_m) = parse_band(c.depth_band);
  r.max_dive_deg = c.max_dive;
  r.vehicle = c.vehicle;
  r.min_cell_m = c.min_cell;
  r.smooth = c.smooth;
  r.margin_m = c.margin;
  r.vertical_clearance_m = c.vertical_clearance;
  r.search = parse_search(c.search);
  const DepthPlanReport report = plan_depth_request(*c.frame, r);
  const Route& route = report.route();
  if (!c.output.empty()) {
    RouteExportSettings settings;
    settings.name = std::filesystem::path(c.output).stem().string();
    settings.margin_m = c.margin;
    ExportRoute exported = export_route(route, *c.frame, report.vehicle, settings);
    exported.properties = report.to_json();
    exported.waypoint_properties = report.waypoint_properties();
    write_route_file(exported, c.output, route_file_format(c.output), {.overwrite = true});
  }
  if (!c.render.empty()) {
    RouteScene scene;
    scene.obstacles = &report.obstacles;
    scene.margin = c.margin;
    scene.route = route.points;
    scene.start = c.start;
    scene.goal = c.goal;
    scene.true_north_deg = true_north_deg(*c.frame, c.start);
    scene.title = route_title("deepguide plan --graph octree", route, c.margin, *c.frame);
    render_route(scene, c.render);
  }
  if (!c.render_profile.empty()) {
    const long dive = std::lround(report.options.octree.max_dive_deg);
    render_depth_profile(report.plan, "Route in depth (octree, dive " + std::to_string(dive) + "\u00b0)",
                         c.render_profile);
  }
  if (c.json) {
    std::cout << report.to_json().dump(2) << "\n";
    return;
  }
  std::cout << report.to_text();
  if (!c.output.empty()) std::cout << report_line("wrote", c.output);
  if (!c.render.empty()) std::cout << report_line("rendered", c.render);
  if (!c.render_profile.empty()) std::cout << report_line("rendered", c.render_profile + " (depth profile)");
}

}  // namespace deepguide::app
