#pragma once
// `plan --graph octree` as a library call: the sea floor and hazards read from
// the charts (one bathymetry raster, or S-57 cells, plus vector charts), the
// dive angle from the vehicle, the route in depth (depth_planning.hpp), and a
// report that prints itself as text or JSON and gives each waypoint's
// properties for the route file.

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/planning/depth_planning.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

struct DepthPlanRequest {
  ObstacleSet obstacles;  ///< in the local frame
  /// One bathymetry raster (the sea floor), or S-57 cells (a floor never
  /// deeper than their depth areas, dangers and soundings); vector charts add
  /// obstacles with their tops.
  std::vector<std::string> charts;
  std::string src_crs;  ///< CRS of a raster or vector chart that carries none
  ChartOptions chart;   ///< how S-57 cells are read
  Vec2 start{0.0, 0.0}, goal{0.0, 0.0};
  double start_depth_m = std::nan(""), goal_depth_m = std::nan("");  ///< both needed
  /// The depth band; NaN: VolumeOptions' top (2 m), and the floor as the bottom.
  double band_top_m = std::nan(""), band_bottom_m = std::nan("");
  double max_dive_deg = std::nan("");  ///< NaN: the vehicle's steepest steady dive
  std::string vehicle;                 ///< vehicle file ("": the default vehicle)
  double min_cell_m = 2.0;
  bool smooth = false;
  double margin_m = 5.0, vertical_clearance_m = 2.0;
  SearchAlgorithm search = SearchAlgorithm::astar;
};

struct DepthPlanReport {
  DepthPlan plan;
  DepthPlanOptions options;
  ObstacleSet obstacles;  ///< the request's and the charts'
  std::shared_ptr<const SeaFloor> floor;
  std::string crs;
  SearchAlgorithm search = SearchAlgorithm::astar;
  double vertical_clearance_m = 2.0;
  VehicleParams vehicle;  ///< the request's vehicle file, read once (what exports of the route use)

  const Route& route() const { return plan.result.route; }
  nlohmann::json to_json() const;
  /// Per waypoint: its depth, and the floor's depth below it where known.
  std::vector<nlohmann::json> waypoint_properties() const;
  /// Lines "label   value" from the length to the checker's verdict.
  std::string to_text() const;
};

/// Throws InputError for bad charts or options (one line), NoRouteError when
/// no route exists, std::runtime_error when the route fails the 3-D check.
/// Start, goal and obstacles are in `frame`, where the charts are read.
DepthPlanReport plan_depth_request(const LocalFrame& frame, const DepthPlanRequest& request);

}  // namespace deepguide
