#pragma once
// `plan` on the 2-D graphs as a library call: the charts' hazards merged with
// the obstacles, the cost model (vehicle, current, departure), one query over
// the obstacles that can matter (single_query.hpp), the route checked against
// every obstacle and the rasters' coverage, priced leg by leg and compared
// with the shortest route, and sonar detections replayed (replanning.hpp).
// The report prints itself as text or JSON and gives the route file its
// properties; mission/route_plan_export.hpp writes the files, and
// render/route_plan_figure.hpp draws it.

#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/charts/enc_route_quality.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/replanning.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

struct ChartObstacles;  // charts/chart_obstacles.hpp
struct EncNoGo;         // charts/enc_no_go.hpp

struct RoutePlanRequest {
  ObstacleSet obstacles;  ///< in the local frame
  /// Bathymetry rasters (no-go shallower than depth_m + vertical_clearance_m),
  /// S-57 cells and hazard files; read into the frame.
  std::vector<std::string> charts;
  std::string src_crs;  ///< CRS of charts that carry none
  /// The charts already read (chart_obstacles) into the frame planned in, at
  /// depth_m and vertical_clearance_m with src_crs and `chart`: taken instead
  /// of reading `charts` again, which then only name them. Null: read them.
  std::shared_ptr<const ChartObstacles> charted;
  ChartOptions chart;       ///< how S-57 charts are read (zones of confidence, restricted areas)
  PlanningProblem problem;  ///< start, goal, their headings (local) and escape
  double margin_m = 5.0;
  double tolerance_m = PlannerOptions{}.tolerance;
  /// None: the radius the vehicle can follow at the planned speed in the
  /// strongest current when a vehicle file is given (not for the quadtree's
  /// unsmoothed cell steps), else 0.
  std::optional<double> turn_radius_m;
  double depth_m = std::nan("");  ///< operating depth; NaN: every obstacle and charted hazard counts
  double vertical_clearance_m = 2.0;
  GraphKind graph = GraphKind::visibility;
  SearchAlgorithm search = SearchAlgorithm::astar;
  double min_cell_m = QuadtreeOptions{}.min_cell_m;  ///< quadtree
  bool smooth = false;                               ///< quadtree: pull the cell route taut
  bool refine = true;                                ///< time and energy routes: refine off the vertices
  std::optional<double> waypoint_grid_m;             ///< open-water vertices this far apart
  std::size_t max_expansions = 0;                    ///< the search's budget of vertices (0: none)
  CostKind cost = CostKind::length;
  std::string vehicle;           ///< vehicle file ("": the default vehicle)
  std::string speed = "cruise";  ///< cruise, optimal (least energy per leg) or m/s
  /// A current field's file (NetCDF u/v, or a two-band raster), read at
  /// depth_m (src_crs for a raster without a CRS); or the field itself.
  std::string current_file;
  std::shared_ptr<const CurrentField> current;  ///< null and no file: still water
  std::string current_source;      ///< how the report names a field given as such (default: the file's name)
  std::optional<double> depart_s;  ///< UTC seconds; none: the current's first time (or 0 in steady water)
  std::string replan_events;       ///< quadtree: detections to replay (an obstacle file with detected_at_m)
  /// The route file the caller writes ("" none): the repairs' files are named after it.
  std::string route_file;
};

struct RoutePlanReport {
  explicit RoutePlanReport(LocalFrame frame) : frame(std::move(frame)) {}

  LocalFrame frame;
  RoutePlanRequest request;  ///< as given, but for the obstacles (below)
  ObstacleSet obstacles;     ///< the request's and the charts' (what the route was planned among)
  bool enc_charts = false;   ///< the charts held S-57 cells
  /// The S-57 cells' no-go, feature by feature (null without cells): what a
  /// drawing or a web map explains the no-go with.
  std::shared_ptr<const EncNoGo> enc;
  /// On S-57 charts: the cells, least depth, zones and nearest no-go along the route.
  std::optional<RouteQuality> chart_quality;
  std::size_t passed_over = 0;  ///< obstacles and hazards deeper than the band
  PlannerOptions options;       ///< as planned (turn radius and cost resolved)
  std::shared_ptr<const CostModel> model;
  VehicleParams vehicle;  ///< the request's vehicle file, read once
  SingleQueryPlan plan;
  Route route;                   ///< what is written: the plan's, or D* Lite's first route when replaying
  double min_clearance_m = 0.0;  ///< of the lines and arcs where the graph gives them, else of the polyline
  RoutePricing priced;
  std::optional<RoutePricing> shortest;  ///< weighed by time or energy: the shortest route, priced alike
  bool timed = false;                    ///< the route has clock times (a changing current or a departure)
  std::optional<Replay> replay;
  std::vector<ReplanEvent> detections;
  std::vector<std::string> repair_files;  ///< per repair: its file name, "" when none is written

  /// Flat keys (a GeoJSON feature's properties hold no nested objects).
  nlohmann::json route_properties() const;
  /// route_properties with the legs, and the repairs of a replay.
  nlohmann::json to_json() const;
  /// Per waypoint: the speed of the leg it starts, time and energy so far, and its ETA when timed.
  std::vector<nlohmann::json> waypoint_properties() const;
  /// Lines "label   value" from the length to the repairs.
  std::string to_text() const;
  /// Things to say that are not errors (the current beating the vehicle on a leg).
  std::vector<std::string> warnings() const;
  /// Why the replayed vehicle stopped short of the goal, or none.
  std::optional<std::string> stop_reason() const;
};

/// Throws InputError for bad charts or options (one line), NoRouteError when
/// no route exists or the route leaves a raster's coverage, std::runtime_error
/// when the route fails the independent check. Obstacles, start and goal are
/// in `frame`, where the charts are read.
RoutePlanReport plan_route_request(const LocalFrame& frame, const RoutePlanRequest& request);

/// The graph `plan` takes when none is named: the tangent graph when a
/// heading is asked for (the one graph with Dubins ends); the navmesh for a
/// route by length on S-57 charts (cells, exchange sets or a prepared chart:
/// the exact shortest route, from the prepared chart's mesh when it keeps
/// one) without a waypoint grid; else the reduced visibility graph (time and
/// energy, rasters and obstacle files, which it plans in focused rounds).
GraphKind default_plan_graph(const std::vector<std::string>& charts, CostKind cost, bool waypoint_grid, bool heading);

/// ROUTE.gpx -> ROUTE_repair_K.gpx
std::string repair_file_name(const std::string& route_file, std::size_t k);

}  // namespace deepguide
