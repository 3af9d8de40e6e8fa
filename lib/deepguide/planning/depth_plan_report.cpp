#include "deepguide/planning/depth_plan_report.hpp"
#include "deepguide/charts/raster_sea_floor.hpp"

#include <algorithm>
#include <stdexcept>

#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_sea_floor.hpp"
#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/planner.hpp"

namespace deepguide {
namespace {

// The vehicle's steepest steady dive: its vertical speed at cruise.
double vehicle_dive_deg(const VehicleParams& vehicle, const std::string& vehicle_file) {
  if (!(vehicle.max_vertical_speed_mps < vehicle.cruise_speed_mps)) {
    throw InputError((vehicle_file.empty() ? std::string("the vehicle") : vehicle_file) +
                     ": max_vertical_speed_mps is not below the cruise speed, so it gives no dive angle; give "
                     "the largest dive angle");
  }
  return rad_to_deg(std::asin(vehicle.max_vertical_speed_mps / vehicle.cruise_speed_mps));
}

// The octree's smallest cell is min_cell_m / tan(dive) wide, and the sea
// floor is sampled at that width: a shallow enough dive makes it wider than
// the voyage (1e-9 deg: 5.7e10 m), and the run then failed for reasons that
// were the resolution's (a raster "not covering the work area", land
// everywhere). At least eight cells from start to goal; any dive of 45 deg
// or more is accepted.
void require_resolving_dive(const OctreeOptions& o, double distance_m) {
  const double width = o.min_cell_m / std::min(1.0, std::tan(deg_to_rad(o.max_dive_deg)));
  const double widest = std::max(distance_m / 8.0, o.min_cell_m);
  if (width <= widest) return;
  throw InputError(printf_text(
      "`max_dive_deg`: %s deg makes the octree's smallest cell %s m wide (its %s m height over the dive's slope), "
      "more than an eighth of the %.0f m from start to goal, and the sea floor would be sampled that coarsely; give "
      "at least %.3g deg, or a smaller `min_cell_m`",
      general(o.max_dive_deg).c_str(), general(width).c_str(), general(o.min_cell_m).c_str(), distance_m,
      rad_to_deg(std::atan(o.min_cell_m / widest))));
}

// One bathymetry raster is the sea floor, or S-57 cells are; the other charts
// add obstacles with their tops to report.obstacles.
void read_charts(const LocalFrame& frame, const DepthPlanRequest& r, DepthPlanReport& report) {
  const auto [lo, hi] = depth_planning_area(r.start, r.goal, report.options);
  const double slope = std::tan(deg_to_rad(report.options.octree.max_dive_deg));
  const double spacing = report.options.octree.min_cell_m / std::min(1.0, slope);  // the smallest cell's width
  std::vector<std::string> vector_charts, enc_charts;
  for (const std::string& path : r.charts) {
    const ChartKind kind = names_enc(path) ? ChartKind::s57 : chart_kind(path);
    if (kind == ChartKind::s57) {
      enc_charts.push_back(path);
    } else if (kind != ChartKind::raster) {
      vector_charts.push_back(path);
    } else if (report.floor) {
      throw InputError(path + ": planning in depth: expected one bathymetry raster, got a second one");
    } else {
      BathymetryOptions read;
      read.assumed_crs = r.src_crs;  // a grid without a CRS
      report.floor = std::make_shared<const SeaFloor>(raster_sea_floor(path, frame, lo, hi, spacing, read));
    }
  }
  if (!enc_charts.empty()) {
    if (report.floor) {
      throw InputError(enc_charts.front() + ": planning in depth: expected one sea floor, got a raster and S-57 cells");
    }
    report.floor = std::make_shared<const SeaFloor>(
        enc_sea_floor(enc_charts, frame, lo, hi, std::max(spacing, 5.0), enc_options(r.chart)));
  }
  if (!vector_charts.empty()) {
    ChartObstacleOptions chart_options;  // no depth: every hazard stays, with its top
    chart_options.clearance_m = r.vertical_clearance_m;
    chart_options.source_crs = r.src_crs;
    const ChartObstacles charted = chart_obstacles(vector_charts, frame, chart_options);
    ObstacleSet& o = report.obstacles;
    o.ellipses.insert(o.ellipses.end(), charted.obstacles.ellipses.begin(), charted.obstacles.ellipses.end());
    o.polygons.insert(o.polygons.end(), charted.obstacles.polygons.begin(), charted.obstacles.polygons.end());
  }
}

}  // namespace

DepthPlanReport plan_depth_request(const LocalFrame& frame, const DepthPlanRequest& r) {
  DepthPlanReport report;
  DepthPlanOptions& options = report.options;
  options.margin = r.margin_m;
  options.search = r.search;
  options.volume.vertical_clearance_m = r.vertical_clearance_m;
  if (!std::isnan(r.band_top_m)) options.volume.min_depth_m = r.band_top_m;
  if (!std::isnan(r.band_bottom_m)) options.volume.max_depth_m = r.band_bottom_m;
  options.octree.min_cell_m = r.min_cell_m;
  options.octree.smooth = r.smooth;
  report.vehicle = r.vehicle.empty() ? VehicleParams{} : read_vehicle_file(r.vehicle);
  options.octree.max_dive_deg =
      std::isnan(r.max_dive_deg) ? vehicle_dive_deg(report.vehicle, r.vehicle) : r.max_dive_deg;
  validate(options.octree);
  require_resolving_dive(options.octree, (r.goal - r.start).norm());
  if (std::isnan(r.start_depth_m) || std::isnan(r.goal_depth_m)) {
    throw InputError("planning in depth: expected the start's and the goal's depth");
  }
  report.obstacles = r.obstacles;
  report.crs = frame.id();
  report.search = r.search;
  report.vertical_clearance_m = r.vertical_clearance_m;
  read_charts(frame, r, report);
  const Vec3 start(r.start.x(), r.start.y(), r.start_depth_m), goal(r.goal.x(), r.goal.y(), r.goal_depth_m);
  report.plan = plan_in_depth(report.obstacles, report.floor, start, goal, options);
  if (!report.plan.result.found) throw NoRouteError(report.plan.result.message);
  if (!report.plan.check.safe) {
    throw std::runtime_error("the planned route failed the 3-D check: " + report.plan.check.describe());
  }
  return report;
}

nlohmann::json DepthPlanReport::to_json() const {
  const Route& r = route();
  nlohmann::json j = {
      {"length_m", r.length()},
      {"waypoints", r.points.size()},
      {"graph", "octree"},
      {"search", to_string(search)},
      {"margin_m", options.margin},
      {"vertical_clearance_m", vertical_clearance_m},
      {"depth_band_m",
       {options.volume.min_depth_m,
        std::isfinite(options.volume.max_depth_m) ? nlohmann::json(options.volume.max_depth_m) : nlohmann::json()}},
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
      {"crs", crs}};
  if (std::isfinite(plan.check.min_floor_gap_m)) j["min_floor_gap_m"] = plan.check.min_floor_gap_m;
  return j;
}

std::vector<nlohmann::json> DepthPlanReport::waypoint_properties() const {
  std::vector<nlohmann::json> out;
  const Route& r = route();
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    nlohmann::json w = {{"depth_m", r.depth_m[i]}};
    if (floor) w["floor_depth_m"] = floor->depth_at(r.points[i]);
    out.push_back(w);
  }
  return out;
}

std::string DepthPlanReport::to_text() const {
  const Route& r = route();
  const VolumeOptions& v = options.volume;
  std::string text =
      report_line("length", fixed(r.length(), 2) + " m in depth, " + std::to_string(r.points.size()) + " waypoints");
  text += report_line("depth", fixed(r.depth_m.front(), 1) + " m to " + fixed(r.depth_m.back(), 1) + " m; band " +
                                   fixed(v.min_depth_m, 1) + " m to " +
                                   (std::isfinite(v.max_depth_m) ? fixed(v.max_depth_m, 1) + " m" : "the floor") +
                                   "; steepest leg " + fixed(plan.check.steepest_deg, 1) + " deg (dive " +
                                   fixed(options.octree.max_dive_deg, 1) + " deg)");
  if (std::isfinite(plan.check.min_floor_gap_m)) {
    text += report_line("sea floor", "at least " + fixed(plan.check.min_floor_gap_m, 2) +
                                         " m below the route (clearance " + fixed(vertical_clearance_m, 2) + " m)");
  }
  text += report_line("octree", std::to_string(plan.cells) + " cells (" + std::to_string(plan.free_cells) +
                                    " free), smallest " + fixed(plan.min_cell.z(), 2) + " m high x " +
                                    fixed(plan.min_cell.x(), 2) + " m wide, " +
                                    fixed(static_cast<double>(plan.memory_bytes) / (1024.0 * 1024.0), 1) + " MiB; " +
                                    to_string(search) + " expanded " + std::to_string(plan.result.stats.expanded));
  text += report_line("time", "build " + fixed(plan.result.stats.build_ms, 2) + " ms, query " +
                                  fixed(plan.result.stats.query_ms, 2) + " ms");
  text += report_line("check", plan.check.describe());
  return text;
}

}  // namespace deepguide
