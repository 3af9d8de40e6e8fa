// deepguide plan --graph octree: a route in depth over the sea floor of a
// bathymetry chart and the obstacles' tops (planning/depth_planning.hpp).

#include "plan_command.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/planning/depth_plan_report.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/render/canvas.hpp"
#include "deepguide/render/depth_profile.hpp"
#include "deepguide/render/route_scene.hpp"

namespace deepguide::app {
namespace {

// "TOP,BOTTOM" in metres, depths positive down; the checks on the values are the volume's.
std::pair<double, double> parse_band(const std::string& text) {
  const std::size_t comma = text.find(',');
  const std::optional<double> top = comma == std::string::npos ? std::nullopt : finite_number(text.substr(0, comma));
  const std::optional<double> bottom =
      comma == std::string::npos ? std::nullopt : finite_number(text.substr(comma + 1));
  if (!top || !bottom) {
    throw InputError("--depth-band: expected TOP,BOTTOM in metres (depths, positive down), got '" + printable(text) +
                     "'");
  }
  return {*top, *bottom};
}

}  // namespace

void add_depth_flags(CLI::App& cmd, DepthFlags& f) {
  cmd.add_option("--from-depth", f.from_depth, "Octree: the start's depth (m); default --depth");
  cmd.add_option("--to-depth", f.to_depth, "Octree: the goal's depth (m); default --depth");
  cmd.add_option("--depth-band", f.depth_band,
                 "Octree: TOP,BOTTOM depths (m) the route keeps within; default 2 m below the surface down to the "
                 "sea floor");
  cmd.add_option("--max-dive", f.max_dive,
                 "Octree: the steepest dive or climb (deg); default the vehicle's vertical speed at cruise");
  cmd.add_option("--render-profile", f.render_profile,
                 "Octree: draw the route's depth profile with the sea floor, obstacles and cells (.png or .svg)");
}

void check_depth_flags(bool in_depth, const DepthFlags& f, bool flags_2d) {
  if (!in_depth && (!std::isnan(f.from_depth) || !std::isnan(f.to_depth) || !f.depth_band.empty() ||
                    !std::isnan(f.max_dive) || !f.render_profile.empty())) {
    throw InputError(
        "--from-depth, --to-depth, --depth-band, --max-dive and --render-profile: expected "
        "--graph octree");
  }
  if (in_depth && flags_2d) {
    throw InputError(
        "--graph octree: plans by length; --cost, --current, --waypoint-grid, --escape, "
        "--replan-events, --depart, --render-graph, --html and the headings are for the 2-D graphs (Dubins "
        "ends: --graph tangent)");
  }
  if (!f.render_profile.empty()) image_format_for(f.render_profile);  // before the work, not after
  if (!f.depth_band.empty()) parse_band(f.depth_band);
}

void run_plan_in_depth(const LocalFrame& frame, const RoutePlanRequest& shared, const DepthFlags& f,
                       const PlanOutputs& out) {
  DepthPlanRequest r;
  r.obstacles = shared.obstacles;
  r.charts = shared.charts;
  r.src_crs = shared.src_crs;
  r.chart = shared.chart;
  r.start = shared.problem.start;
  r.goal = shared.problem.goal;
  r.start_depth_m = std::isnan(f.from_depth) ? shared.depth_m : f.from_depth;
  r.goal_depth_m = std::isnan(f.to_depth) ? shared.depth_m : f.to_depth;
  if (std::isnan(r.start_depth_m) || std::isnan(r.goal_depth_m)) {
    throw InputError(
        "--graph octree: expected the start's and the goal's depth (--depth, or --from-depth and "
        "--to-depth)");
  }
  if (!f.depth_band.empty()) std::tie(r.band_top_m, r.band_bottom_m) = parse_band(f.depth_band);
  r.max_dive_deg = f.max_dive;
  r.vehicle = shared.vehicle;
  r.min_cell_m = shared.min_cell_m;
  r.smooth = shared.smooth;
  r.margin_m = shared.margin_m;
  r.vertical_clearance_m = shared.vertical_clearance_m;
  r.search = shared.search;
  const DepthPlanReport report = plan_depth_request(frame, r);
  const Route& route = report.route();
  if (!out.route_file.empty()) {
    RouteExportSettings settings;
    settings.name = std::filesystem::path(out.route_file).stem().string();
    settings.margin_m = r.margin_m;
    ExportRoute exported = export_route(route, frame, report.vehicle, settings);
    exported.properties = report.to_json();
    exported.waypoint_properties = report.waypoint_properties();
    write_route_file(exported, out.route_file, route_file_format(out.route_file), {.overwrite = true});
  }
  if (!out.render.empty()) {
    RouteScene scene;
    scene.obstacles = &report.obstacles;
    scene.margin = r.margin_m;
    scene.route = route.points;
    scene.start = r.start;
    scene.goal = r.goal;
    scene.true_north_deg = true_north_deg(frame, r.start);
    scene.title = route_title("deepguide plan --graph octree", route, r.margin_m, frame);
    render_route(scene, out.render);
  }
  if (!f.render_profile.empty()) {
    const long dive = std::lround(report.options.octree.max_dive_deg);
    render_depth_profile(report.plan, "Route in depth (octree, dive " + std::to_string(dive) + "\u00b0)",
                         f.render_profile);
  }
  if (out.json) {
    std::cout << report.to_json().dump(2) << "\n";
    return;
  }
  std::cout << report.to_text();
  if (!out.route_file.empty()) std::cout << report_line("wrote", out.route_file);
  if (!out.render.empty()) std::cout << report_line("rendered", out.render);
  if (!f.render_profile.empty()) std::cout << report_line("rendered", f.render_profile + " (depth profile)");
}

}  // namespace deepguide::app
