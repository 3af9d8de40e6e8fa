// deepguide plan --graph octree: a route in depth over the sea floor of a
// bathymetry chart and the obstacles' tops (planning/depth_planning.hpp).

#include "plan_depth.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/planning/depth_planning.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/render/depth_profile.hpp"
#include "deepguide/render/route_scene.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/chart_info.hpp"
#include "deepguide/world/chart_obstacles.hpp"
#include "deepguide/world/enc_cells.hpp"
#include "deepguide/world/enc_sea_floor.hpp"

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
  const LocalFrame& frame = *c.frame;
  DepthPlanOptions options;
  options.margin = c.margin;
  options.search = parse_search(c.search);
  options.volume.vertical_clearance_m = c.vertical_clearance;
  if (!c.depth_band.empty()) std::tie(options.volume.min_depth_m, options.volume.max_depth_m) = parse_band(c.depth_band);
  options.octree.min_cell_m = c.min_cell;
  options.octree.smooth = c.smooth;
  if (std::isnan(c.max_dive)) {
    // The vehicle's steepest steady dive: its vertical speed at cruise.
    const VehicleParams vehicle = c.vehicle.empty() ? VehicleParams{} : read_vehicle_file(c.vehicle);
    if (!(vehicle.max_vertical_speed_mps < vehicle.cruise_speed_mps)) {
      throw InputError((c.vehicle.empty() ? std::string("the vehicle") : c.vehicle) +
                       ": max_vertical_speed_mps is not below the cruise speed, so it gives no dive angle; give "
                       "--max-dive");
    }
    options.octree.max_dive_deg = std::asin(vehicle.max_vertical_speed_mps / vehicle.cruise_speed_mps) * 180.0 / M_PI;
  } else {
    options.octree.max_dive_deg = c.max_dive;
  }
  validate(options.octree);
  const double from_depth = std::isnan(c.from_depth) ? c.depth : c.from_depth;
  const double to_depth = std::isnan(c.to_depth) ? c.depth : c.to_depth;
  if (std::isnan(from_depth) || std::isnan(to_depth)) {
    throw InputError("--graph octree: expected the start's and the goal's depth (--depth, or --from-depth and "
                     "--to-depth)");
  }
  const Vec3 start(c.start.x(), c.start.y(), from_depth), goal(c.goal.x(), c.goal.y(), to_depth);

  // Charts: one bathymetry raster is the sea floor; the others add obstacles with their tops.
  ObstacleSet obstacles = c.obstacles;
  std::shared_ptr<const SeaFloor> floor;
  std::vector<std::string> vector_charts, enc_charts;
  const auto [lo, hi] = depth_planning_area(c.start, c.goal, options);
  const double slope = std::tan(options.octree.max_dive_deg * M_PI / 180.0);
  const double spacing = options.octree.min_cell_m / std::min(1.0, slope);  // the smallest cell's width
  for (const std::string& path : c.charts) {
    if (names_enc(path)) {
      enc_charts.push_back(path);
      continue;
    }
    const ChartKind kind = chart_kind(path);
    if (kind == ChartKind::s57) {
      enc_charts.push_back(path);
      continue;
    }
    if (kind != ChartKind::raster) {
      vector_charts.push_back(path);
      continue;
    }
    if (floor) throw InputError(path + ": --graph octree: expected one bathymetry raster, got a second one");
    BathymetryOptions read;
    read.assumed_crs = c.src_crs;  // a grid without a CRS (--src-crs)
    floor = std::make_shared<const SeaFloor>(SeaFloor::from_raster(path, frame, lo, hi, spacing, read));
  }
  if (!enc_charts.empty()) {
    // S-57 cells: a floor never deeper than their depth areas, dangers and soundings (enc_sea_floor.hpp).
    if (floor) throw InputError(enc_charts.front() + ": --graph octree: expected one sea floor, got a raster and S-57 cells");
    floor = std::make_shared<const SeaFloor>(enc_sea_floor(enc_charts, frame, lo, hi, std::max(spacing, 5.0)));
  }
  if (!vector_charts.empty()) {
    ChartObstacleOptions chart_options;  // no depth: every hazard stays, with its top
    chart_options.clearance_m = c.vertical_clearance;
    chart_options.source_crs = c.src_crs;
    const ChartObstacles charted = chart_obstacles(vector_charts, frame, chart_options);
    obstacles.ellipses.insert(obstacles.ellipses.end(), charted.obstacles.ellipses.begin(), charted.obstacles.ellipses.end());
    obstacles.polygons.insert(obstacles.polygons.end(), charted.obstacles.polygons.begin(), charted.obstacles.polygons.end());
  }

  const DepthPlan plan = plan_in_depth(obstacles, floor, start, goal, options);
  if (!plan.result.found) throw NoRouteError(plan.result.message);
  if (!plan.check.safe) throw std::runtime_error("the planned route failed the 3-D check: " + plan.check.describe());
  const Route& route = plan.result.route;

  nlohmann::json summary = {{"length_m", route.length()},
                            {"waypoints", route.points.size()},
                            {"graph", "octree"},
                            {"search", c.search},
                            {"margin_m", c.margin},
                            {"vertical_clearance_m", c.vertical_clearance},
                            {"depth_band_m", {options.volume.min_depth_m, std::isfinite(options.volume.max_depth_m)
                                                                              ? nlohmann::json(options.volume.max_depth_m)
                                                                              : nlohmann::json()}},
                            {"max_dive_deg", options.octree.max_dive_deg},
                            {"steepest_deg", plan.check.steepest_deg},
                            {"min_cell_height_m", plan.min_cell.z()},
                            {"min_cell_width_m", plan.min_cell.x()},
                            {"cells", plan.cells},
                            {"free_cells", plan.free_cells},
                            {"octree_bytes", plan.memory_bytes},
                            {"expanded", plan.result.stats.expanded},
                            {"build_ms", plan.result.stats.build_ms},
                            {"query_ms", plan.result.stats.query_ms},
                            {"obstacles", obstacles.size()},
                            {"sea_floor", floor != nullptr},
                            {"crs", frame.id()}};
  if (std::isfinite(plan.check.min_floor_gap_m)) summary["min_floor_gap_m"] = plan.check.min_floor_gap_m;
  std::vector<nlohmann::json> waypoints;
  for (std::size_t i = 0; i < route.points.size(); ++i) {
    nlohmann::json w = {{"depth_m", route.depth_m[i]}};
    if (floor) w["floor_depth_m"] = floor->depth_at(route.points[i]);
    waypoints.push_back(w);
  }
  if (!c.output.empty()) {
    RouteExportSettings settings;
    settings.name = std::filesystem::path(c.output).stem().string();
    settings.margin_m = c.margin;
    ExportRoute exported =
        export_route(route, frame, c.vehicle.empty() ? VehicleParams{} : read_vehicle_file(c.vehicle), settings);
    exported.properties = summary;
    exported.waypoint_properties = waypoints;
    write_route_file(exported, c.output, route_file_format(c.output), {.overwrite = true});
  }
  if (!c.render.empty()) {
    RouteScene scene;
    scene.obstacles = &obstacles;
    scene.margin = c.margin;
    scene.route = route.points;
    scene.start = c.start;
    scene.goal = c.goal;
    scene.true_north_deg = true_north_deg(frame, c.start);
    scene.title = route_title("deepguide plan --graph octree", route, c.margin, frame);
    render_route(scene, c.render);
  }
  if (!c.render_profile.empty()) {
    render_depth_profile(plan, "Route in depth (octree, dive " + std::to_string(static_cast<int>(std::lround(options.octree.max_dive_deg))) + "\u00b0)", c.render_profile);
  }
  if (c.json) {
    std::cout << summary.dump(2) << "\n";
    return;
  }
  std::printf("length           %.2f m in depth, %zu waypoints\n", route.length(), route.points.size());
  char bottom[32] = "the floor";
  if (std::isfinite(options.volume.max_depth_m)) std::snprintf(bottom, sizeof bottom, "%.1f m", options.volume.max_depth_m);
  std::printf("depth            %.1f m to %.1f m; band %.1f m to %s; steepest leg %.1f deg (dive %.1f deg)\n",
              route.depth_m.front(), route.depth_m.back(), options.volume.min_depth_m, bottom, plan.check.steepest_deg,
              options.octree.max_dive_deg);
  if (std::isfinite(plan.check.min_floor_gap_m)) {
    std::printf("sea floor        at least %.2f m below the route (clearance %.2f m)\n", plan.check.min_floor_gap_m,
                c.vertical_clearance);
  }
  std::printf("octree           %zu cells (%zu free), smallest %.2f m high x %.2f m wide, %.1f MiB; %s expanded %zu\n",
              plan.cells, plan.free_cells, plan.min_cell.z(), plan.min_cell.x(),
              static_cast<double>(plan.memory_bytes) / (1024.0 * 1024.0), c.search.c_str(), plan.result.stats.expanded);
  std::printf("time             build %.2f ms, query %.2f ms\n", plan.result.stats.build_ms, plan.result.stats.query_ms);
  std::printf("check            %s\n", plan.check.describe().c_str());
  if (!c.output.empty()) std::printf("wrote            %s\n", c.output.c_str());
  if (!c.render.empty()) std::printf("rendered         %s\n", c.render.c_str());
  if (!c.render_profile.empty()) std::printf("rendered         %s (depth profile)\n", c.render_profile.c_str());
}

}  // namespace deepguide::app
