// deepguide plan --obstacles FILE... --from X,Y --to X,Y [--cost length|time|energy]
//                [--current FILE | --current-const SPEED,DIR] [...] -o ROUTE.geojson|gpx|kml|rtz|csv|plan|bhv [--json]

#include <cmath>
#include <limits>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "plan_depth.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/replanning.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/render/route_on_chart.hpp"
#include "deepguide/render/route_scene.hpp"
#include "deepguide/world/chart_obstacles.hpp"
#include "deepguide/world/enc_route_check.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/current_field.hpp"
#include "deepguide/world/obstacle_io.hpp"

namespace deepguide::app {
namespace {

struct PlanOptions {
  std::vector<std::string> obstacles;
  std::vector<std::string> charts;
  std::string from, to, output;
  FrameOptions frame;
  double margin = 5.0;
  double tolerance = PlannerOptions{}.tolerance;
  std::optional<double> turn_radius;
  std::optional<double> from_heading, to_heading;  ///< deg, clockwise from true north
  double depth = std::nan("");
  double vertical_clearance = 2.0;
  std::string graph = "visibility";
  std::string search = "astar";
  bool json = false;
  std::string render;         ///< --render: chart to draw (.png or .svg)
  bool render_graph = false;  ///< --render-graph: draw the zone polygons and the graph too
  bool escape = false;
  std::string cost = "length";
  std::string current_file;
  std::string current_const;
  std::string vehicle;
  std::string speed = "cruise";
  std::string depart;
  std::optional<double> waypoint_grid;
  double min_cell = QuadtreeOptions{}.min_cell_m;
  bool smooth = false;
  bool no_refine = false;
  std::string replan_events;
  // --graph octree (plan_depth.cpp)
  double from_depth = std::nan("");
  double to_depth = std::nan("");
  std::string depth_band;
  double max_dive = std::nan("");
  std::string render_profile;
};

// ROUTE.gpx -> ROUTE_repair_K.gpx
std::string repair_path(const std::string& output, std::size_t k) {
  const std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + "_repair_" + std::to_string(k) + p.extension().string())).string();
}

// The cost model the options ask for: the vehicle's speeds and energy, the
// current bound to the frame over the start-goal box, the departure time.
VehicleParams vehicle_of(const PlanOptions& o) { return o.vehicle.empty() ? VehicleParams{} : read_vehicle_file(o.vehicle); }

CostModel cost_model_of(const PlanOptions& o, const LocalFrame& frame, const PlanningProblem& problem) {
  const VehicleParams vehicle = vehicle_of(o);
  CostModel m;
  m.kind = parse_cost_kind(o.cost);
  m.leg.energy = vehicle.energy;
  m.min_speed_mps = vehicle.min_speed_mps;
  m.max_speed_mps = vehicle.max_speed_mps;
  m.speed_mps = vehicle.cruise_speed_mps;
  if (o.speed == "optimal") {
    m.economical = true;
  } else if (o.speed != "cruise") {
    try {
      std::size_t used = 0;
      m.speed_mps = std::stod(o.speed, &used);
      if (used != o.speed.size()) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw InputError("--speed: expected cruise, optimal or a speed in m/s, got '" + o.speed + "'");
    }
  }
  std::shared_ptr<const CurrentField> field;
  if (!o.current_file.empty()) {
    CurrentOptions copts;
    if (!std::isnan(o.depth)) copts.depth_m = o.depth;
    if (!o.frame.src_crs.empty()) copts.assumed_crs = o.frame.src_crs;
    field = std::make_shared<const CurrentField>(load_current_field(o.current_file, copts));
  } else if (!o.current_const.empty()) {
    field = std::make_shared<const CurrentField>(parse_constant_current(o.current_const, "--current-const"));
  }
  if (field) {
    const Vec2 lo = problem.start.cwiseMin(problem.goal), hi = problem.start.cwiseMax(problem.goal);
    attach_current(m, field, frame, lo, hi);
  }
  if (!o.depart.empty()) m.depart_s = parse_utc(o.depart, "--depart");
  else if (!m.steady) m.depart_s = m.time_first_s;  // the start of the forecast
  validate(m);
  return m;
}

}  // namespace

void register_plan(CLI::App& app) {
  auto o = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand("plan", "Plan a safe shortest route around the obstacles");
  cmd->add_option("--obstacles", o->obstacles, "Obstacle files (GeoJSON, GeoPackage, Shapefile, CSV, ...)")
      ->expected(1, -1);
  cmd->add_option("--chart", o->charts,
                  "Charts: bathymetry rasters (no-go at --depth), S-57 cells, hazard files (GeoPackage, ...)")
      ->expected(1, -1);
  cmd->add_option("--from", o->from, "Start: lon,lat, or x,y in the --crs frame")->required();
  cmd->add_option("--to", o->to, "Goal: lon,lat, or x,y in the --crs frame")->required();
  cmd->add_option("-o,--output", o->output, "Route file to write; its extension picks the format: .geojson, .gpx, .kml, .rtz, .csv, .plan, .bhv");
  add_frame_options(*cmd, o->frame);
  cmd->add_option("--margin", o->margin, "Safety margin to every obstacle (m)")->capture_default_str();
  cmd->add_option("--turn-radius", o->turn_radius,
                  "The vehicle's least turning radius (m): every arc of the route is at least this wide "
                  "(--graph quadtree needs --smooth; default with --vehicle: what the vehicle can follow at the planned speed)");
  cmd->add_option("--from-heading", o->from_heading,
                  "The vehicle's heading at the start (deg, clockwise from true north): the route leaves along it, "
                  "turning no tighter than the turning radius (Dubins ends; the tangent graph)");
  cmd->add_option("--to-heading", o->to_heading,
                  "The heading the route reaches the goal on (deg, clockwise from true north; as --from-heading)");
  cmd->add_option("--tolerance", o->tolerance, "How far zone polygons may reach beyond the zones (m)")
      ->capture_default_str();
  cmd->add_option("--depth", o->depth,
                  "Operating depth (m); obstacles whose top_depth_m lies deeper than depth + "
                  "--vertical-clearance are passed over");
  cmd->add_option("--vertical-clearance", o->vertical_clearance, "Vertical clearance above obstacle tops (m)")
      ->capture_default_str();
  CLI::Option* graph_option = cmd->add_option("--graph", o->graph,
                  "visibility (reduced polygon graph), visibility-full (the seed's), tangent (exact, curved), "
                  "quadtree (free cells' centres, the seed's Fig. 7), or octree (a route in depth over the sea floor)")
      ->capture_default_str();
  cmd->add_option("--search", o->search, "astar or dijkstra")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print the summary as JSON");
  cmd->add_flag("--escape", o->escape, "A start inside a safety zone first leaves it the shortest way");
  cmd->add_option("--render", o->render, "Also draw the route chart (obstacles, zones, route) as .png or .svg");
  cmd->add_flag("--render-graph", o->render_graph, "With --render: draw the zone polygons and the planning graph");
  cmd->add_option("--cost", o->cost, "What the route minimises: length, time or energy (in the current)")
      ->capture_default_str();
  auto* current = cmd->add_option("--current", o->current_file,
                                  "Sea-current field (NetCDF u/v, possibly with a time axis; or a two-band raster)");
  cmd->add_option("--current-const", o->current_const,
                  "A uniform current SPEED_MPS,DIR_DEG (direction it sets towards, clockwise from north)")
      ->excludes(current);
  cmd->add_option("--vehicle", o->vehicle, "Vehicle file (speeds, energy model; data/vehicles/deepc.yaml)");
  cmd->add_option("--speed", o->speed,
                  "Speed through the water: cruise (the vehicle's), optimal (least energy per leg), or m/s")
      ->capture_default_str();
  cmd->add_option("--waypoint-grid", o->waypoint_grid,
                  "Open-water vertices SPACING_M apart around start and goal, so time and energy routes can bend "
                  "where the current changes (visibility graphs)");
  cmd->add_flag("--no-refine", o->no_refine,
               "Time and energy routes: keep the graph's route instead of refining it to the continuous optimum "
               "near it (docs/PLANNING.md)");
  cmd->add_option("--min-cell", o->min_cell,
                  "Quadtree: the smallest cell side (m); octree: the smallest cell's height (its width follows the "
                  "dive angle)")
      ->capture_default_str();
  cmd->add_flag("--smooth", o->smooth,
                "Quadtree, octree: shortcut the cell-centre route where the straight line is free (and flyable)");
  cmd->add_option("--from-depth", o->from_depth, "Octree: the start's depth (m); default --depth");
  cmd->add_option("--to-depth", o->to_depth, "Octree: the goal's depth (m); default --depth");
  cmd->add_option("--depth-band", o->depth_band,
                  "Octree: TOP,BOTTOM depths (m) the route keeps within; default 2 m below the surface down to the "
                  "sea floor");
  cmd->add_option("--max-dive", o->max_dive,
                  "Octree: the steepest dive or climb (deg); default the vehicle's vertical speed at cruise");
  cmd->add_option("--render-profile", o->render_profile,
                  "Octree: draw the route's depth profile with the sea floor, obstacles and cells (.png or .svg)");
  cmd->add_option("--replan-events", o->replan_events,
                  "Quadtree: replay sonar detections (an obstacle file with detected_at_m) with D* Lite and write "
                  "each repaired route (ROUTE_repair_K.geojson)");
  cmd->add_option("--depart", o->depart,
                  "Departure time (UTC, e.g. 2019-03-07T15:00:00Z); default: the current field's first time");
  cmd->callback([o, graph_option] {
    const bool headings = o->from_heading || o->to_heading;
    // Dubins ends are planned by the tangent graph alone (planner.hpp): it is the default then.
    if (headings && graph_option->count() == 0) o->graph = "tangent";
    if (headings) {
      for (const auto& [flag, deg] : {std::pair{"--from-heading", o->from_heading}, {"--to-heading", o->to_heading}}) {
        if (deg && !std::isfinite(*deg)) {
          throw InputError(std::string(flag) + ": expected a heading in degrees, got " + general(*deg));
        }
      }
      const char* which = o->from_heading ? "--from-heading" : "--to-heading";
      if (o->graph != "tangent") {
        throw InputError(std::string(which) + ": expected --graph tangent (the graph that plans Dubins ends), got " +
                         o->graph);
      }
      if (!o->turn_radius && o->vehicle.empty()) {
        throw InputError(std::string(which) + ": expected --turn-radius or --vehicle (the radius the route turns on)");
      }
    }
    const bool in_depth = o->graph == "octree";
    if (!in_depth && (!std::isnan(o->from_depth) || !std::isnan(o->to_depth) || !o->depth_band.empty() ||
                      !std::isnan(o->max_dive) || !o->render_profile.empty())) {
      throw InputError("--from-depth, --to-depth, --depth-band, --max-dive and --render-profile: expected "
                       "--graph octree");
    }
    if (in_depth && (o->cost != "length" || !o->current_file.empty() || !o->current_const.empty() ||
                     o->waypoint_grid || o->escape || !o->replan_events.empty() || !o->depart.empty() ||
                     o->render_graph)) {
      throw InputError("--graph octree: plans by length; --cost, --current, --waypoint-grid, --escape, "
                       "--replan-events, --depart and --render-graph are for the 2-D graphs");
    }
    for (const std::string& f : {o->render, o->render_profile}) {
      if (!f.empty()) image_format_for(f);  // before the work, not after
    }
    {
      std::vector<NamedPath> inputs;
      for (const std::string& f : o->obstacles) inputs.push_back({"--obstacles", f});
      for (const std::string& f : o->charts) inputs.push_back({"--chart", f});
      inputs.push_back({"--current", o->current_file});
      inputs.push_back({"--vehicle", o->vehicle});
      inputs.push_back({"--replan-events", o->replan_events});
      check_outputs_apart(inputs, {{"-o", o->output}, {"--render", o->render}, {"--render-profile", o->render_profile}});
    }
    // The route file's format from its name, before the work (a mission's .yaml is not a route).
    const std::optional<ExportFormat> out_format =
        o->output.empty() ? std::nullopt : std::optional<ExportFormat>(route_file_format(o->output));
    PlannerOptions options;
    options.margin = o->margin;
    options.tolerance = o->tolerance;
    if (o->turn_radius) {
      if (!std::isfinite(*o->turn_radius) || *o->turn_radius <= 0.0) {
        throw InputError("--turn-radius: expected a radius > 0 m, got " + general(*o->turn_radius));
      }
      options.turn_radius_m = *o->turn_radius;
    }
    options.graph = in_depth ? GraphKind::quadtree : parse_graph_kind(o->graph);
    options.search = parse_search(o->search);
    options.quadtree.min_cell_m = o->min_cell;
    options.quadtree.smooth = o->smooth;
    if (!o->replan_events.empty() &&
        (options.graph != GraphKind::quadtree || o->cost != "length" || o->smooth || o->escape)) {
      throw InputError("--replan-events: expected --graph quadtree with --cost length, and neither --smooth nor "
                       "--escape (D* Lite repairs the cell route by length from a start outside every zone)");
    }
    if (o->smooth && options.graph != GraphKind::quadtree && !in_depth) {
      throw InputError("--smooth: expected --graph quadtree (the other graphs' routes are taut already)");
    }
    if (o->obstacles.empty() && o->charts.empty()) {
      throw CLI::ValidationError("plan", "give --obstacles FILE... or --chart FILE... (or both)");
    }
    // The local frame: --crs, else the UTM zone of the obstacles (when there are any), else of the start.
    std::optional<LocalFrame> frame_in_use;
    if (!o->frame.crs.empty()) frame_in_use = LocalFrame::from_user_crs(o->frame.crs);
    ObstacleSet obstacles;
    if (!o->obstacles.empty()) {
      LoadedObstacles loaded = load_obstacles(o->obstacles, {o->frame.crs, o->frame.src_crs});
      // Files without an obstacle fix no frame: the start's zone does (below).
      if (!loaded.obstacles.empty() || !o->frame.crs.empty()) frame_in_use = loaded.frame;
      obstacles = std::move(loaded.obstacles);
    }
    if (!frame_in_use) {
      // --from is lon,lat here: it picks the zone.
      const Eigen::Vector2d from = parse_lonlat(o->from, "--from");
      frame_in_use = LocalFrame::utm_for(from.x(), from.y());
    }
    const LocalFrame& frame = *frame_in_use;
    PlanningProblem problem{parse_position(o->from, "--from", frame, !o->frame.crs.empty()),
                            parse_position(o->to, "--to", frame, !o->frame.crs.empty()), o->escape};
    if (o->from_heading) problem.start_heading = frame.heading_to_local(*o->from_heading, problem.start);
    if (o->to_heading) problem.goal_heading = frame.heading_to_local(*o->to_heading, problem.goal);
    if (in_depth) {
      DepthCommand c;
      c.frame = &frame;
      c.obstacles = std::move(obstacles);
      c.charts = o->charts;
      c.src_crs = o->frame.src_crs;
      c.start = problem.start;
      c.goal = problem.goal;
      c.depth = o->depth;
      c.from_depth = o->from_depth;
      c.to_depth = o->to_depth;
      c.depth_band = o->depth_band;
      c.max_dive = o->max_dive;
      c.vehicle = o->vehicle;
      c.min_cell = o->min_cell;
      c.smooth = o->smooth;
      c.margin = o->margin;
      c.vertical_clearance = o->vertical_clearance;
      c.search = o->search;
      c.output = o->output;
      c.render = o->render;
      c.render_profile = o->render_profile;
      c.json = o->json;
      run_plan_in_depth(c);
      return;
    }
    std::size_t passed_over = 0;
    if (!std::isnan(o->depth)) passed_over = remove_passable(obstacles, o->depth, o->vertical_clearance);
    ChartObstacles charted;
    if (!o->charts.empty()) {
      ChartObstacleOptions chart_options;
      chart_options.depth_m = o->depth;
      chart_options.clearance_m = o->vertical_clearance;
      chart_options.source_crs = o->frame.src_crs;
      charted = chart_obstacles(o->charts, frame, chart_options);
      for (const ChartFileObstacles& f : charted.files) passed_over += f.passed_over;
      obstacles.ellipses.insert(obstacles.ellipses.end(), charted.obstacles.ellipses.begin(),
                                charted.obstacles.ellipses.end());
      obstacles.polygons.insert(obstacles.polygons.end(), charted.obstacles.polygons.begin(),
                                charted.obstacles.polygons.end());
    }
    if (charted.enc) {
      // Name the charted feature, not the merged no-go polygon the planner would.
      auto refuse_inside = [&](const Vec2& p, const char* which) {
        if (const EncNoGoFeature* f = no_go_feature_at(*charted.enc, p, o->margin)) {
          throw NoRouteError(std::string("the ") + which + " lies within " + fixed(o->margin, 2) +
                             " m of " + f->id + (f->cell.empty() ? "" : " of " + f->cell) + " (" + f->reason +
                             ")" + (which[0] == 's' ? "; --escape leaves it by the shortest way" : ""));
        }
      };
      if (!problem.escape) refuse_inside(problem.start, "start");
      refuse_inside(problem.goal, "goal");
    }
    const auto model = std::make_shared<const CostModel>(cost_model_of(*o, frame, problem));
    if (model->kind != CostKind::length) options.cost = model;
    // A vehicle given: routes it can follow at the planned speed in the
    // strongest current (route_turn_radius), unless --turn-radius says
    // otherwise; the quadtree's cell-to-cell steps only when --smooth pulls them taut.
    if (!o->turn_radius && !o->vehicle.empty() && (options.graph != GraphKind::quadtree || o->smooth)) {
      options.turn_radius_m = route_turn_radius(vehicle_of(*o), model->speed_mps, model->max_current_mps);
    }
    if (o->waypoint_grid) options.grid = waypoint_grid_for(problem.start, problem.goal, *o->waypoint_grid);
    options.refine = !o->no_refine;
    // One query: the graph only over the obstacles that can matter (single_query.hpp).
    const SingleQueryPlan plan = plan_single_query(obstacles, problem, options);
    const PlanOutcome& out = plan.outcome;
    if (!out.result.found) throw NoRouteError(out.result.message);
    if (!out.check.safe) {
      throw std::runtime_error("the planned route failed the independent check: " + out.check.describe());
    }
    // Replanning: the detections replayed along the route, each repair written and listed. The route
    // written is D* Lite's first (of equal length to A*'s, but on a cell grid ties abound): the one
    // the vehicle sails and detected_at_m is measured along.
    nlohmann::json repairs = nlohmann::json::array();
    std::optional<Replay> replay;
    std::vector<Detection> detections;
    if (!o->replan_events.empty()) {
      detections = load_detections(o->replan_events, frame, o->frame.src_crs);
      replay = replay_detections(*plan.planner->quadtree(), problem, detections, o->margin);
      for (std::size_t k = 0; k < replay->repairs.size(); ++k) {
        const Repair& r = replay->repairs[k];
        nlohmann::json row = {{"repair", k + 1},        {"along_m", r.along_m},   {"blocked_edges", r.blocked_edges},
                              {"found", r.found},       {"expanded", r.expanded}, {"repair_ms", r.repair_ms}};
        if (r.found) row["length_m"] = r.cost;
        if (r.found && !o->output.empty()) {
          row["file"] = repair_path(o->output, k + 1);
          RouteExportSettings settings;
          settings.name = std::filesystem::path(row["file"].get<std::string>()).stem().string();
          settings.margin_m = o->margin;
          ExportRoute exported = export_route(Route{r.route}, frame, vehicle_of(*o), settings);
          exported.properties = {{"repair", k + 1}, {"along_m", r.along_m}, {"length_m", r.cost}};
          write_route_file(exported, row["file"], *out_format, {.overwrite = true});
        }
        repairs.push_back(row);
      }
    }

    const Route route = replay ? Route{replay->initial_route} : out.result.route;
    const RouteCheck check = replay ? check_route(route.points, plan.planner->field()) : out.check;
    if (!check.safe) throw std::runtime_error("the replanned route failed the independent check: " + check.describe());
    if (out.legs_check && !out.legs_check->safe) {
      throw std::runtime_error("the route's lines and arcs failed the independent check: " + out.legs_check->describe());
    }
    // What the vehicle sails: the lines and arcs where the planner gives them
    // (a polygon route's fillets lie inside its corners), else the polyline.
    const double min_clearance = out.legs_check && !replay ? out.legs_check->min_clearance_m : check.min_clearance_m;
    // Outside a bathymetry raster the depth is not known: a route that leaves it is not safe.
    if (const auto exit = route_leaves_coverage(route.points, charted.raster_coverage)) {
      const Vec2 ll = frame.to_lonlat(exit->at);
      const std::string charts = charted.raster_paths.front() +
                                 (charted.raster_paths.size() > 1 ? " and the other rasters" : std::string());
      const bool start = exit->leg == 0 && (exit->at - route.points.front()).norm() < 1e-9;
      throw NoRouteError((start ? "the start lies outside the coverage of " + charts
                                : "the route leaves the coverage of " + charts + " on leg " + std::to_string(exit->leg + 1)) +
                         " at " + fixed(ll.x(), 6) + "," + fixed(ll.y(), 6) +
                         ": the depth there is not known (give a chart that covers the way)");
    }
    // Time and energy of the route as planned, leg by leg (also for a length route).
    const RoutePricing priced = price_route(*model, route.points);
    const bool timed = !model->steady || !o->depart.empty();
    // Weighed by time or energy: what the shortest route would cost, for comparison.
    std::optional<RoutePricing> shortest;
    if (model->kind != CostKind::length) {
      PlannerOptions by_length = options;
      by_length.cost = nullptr;
      by_length.grid = {};
      const SingleQueryPlan plain = plan_single_query(obstacles, problem, by_length);
      if (plain.outcome.result.found) shortest = price_route(*model, plain.outcome.result.route.points);
    }
    if (!priced.feasible) {
      std::fprintf(stderr, "warning: the current beats the vehicle on part of this %s route; plan with --cost time "
                   "or energy to avoid it\n", o->cost.c_str());
    }
    nlohmann::json summary = {
        {"length_m", route.length()},
        {"waypoints", route.points.size()},
        {"min_clearance_m", min_clearance},
        {"margin_m", o->margin},
        {"graph", o->graph},
        {"search", o->search},
        {"graph_vertices", out.result.stats.graph_vertices},
        {"graph_edges", out.result.stats.graph_edges},
        {"open_water_vertices", out.result.stats.open_water_vertices},
        {"refine_sweeps", out.result.stats.refine_sweeps},
        {"refine_gain", out.result.stats.refine_gain},
        {"refine_ms", out.result.stats.refine_ms},
        {"expanded", out.result.stats.expanded},
        {"build_ms", plan.build_ms},
        {"query_ms", plan.query_ms},
        {"obstacles", plan.obstacles_total},
        {"obstacles_in_graph", plan.obstacles_used},
        {"rounds", plan.rounds},
        {"passed_over", passed_over},
        {"crs", frame.id()}};
    summary["cost"] = o->cost;
    summary["speed"] = o->speed;
    summary["feasible"] = priced.feasible;
    summary["time_s"] = priced.feasible ? nlohmann::json(priced.time_s) : nlohmann::json();
    summary["energy_j"] = priced.feasible ? nlohmann::json(priced.energy_j) : nlohmann::json();
    if (model->current) {
      summary["max_current_mps"] = model->max_current_mps;
      summary["unknown_current_m"] = priced.unknown_current_m;
      summary["current"] = !o->current_file.empty() ? o->current_file : "--current-const " + o->current_const;
    }
    if (shortest) {  // flat keys: the GeoJSON's properties hold no nested objects
      summary["shortest_length_m"] = shortest->length_m;
      summary["shortest_feasible"] = shortest->feasible;
      if (shortest->feasible) summary["shortest_time_s"] = shortest->time_s;
      if (shortest->feasible) summary["shortest_energy_j"] = shortest->energy_j;
    }
    if (timed) {
      summary["depart"] = format_utc(model->depart_s);
      if (priced.feasible) summary["arrive"] = format_utc(model->depart_s + priced.time_s);
    }
    if (!out.escaped_from.empty()) summary["escaped_from"] = out.escaped_from;
    if (!out.result.legs.empty()) {
      summary["exact_length_m"] = out.result.exact_length_m;
      std::size_t arcs = 0;
      for (const RouteLeg& leg : out.result.legs) arcs += leg.kind == RouteLeg::Kind::arc;
      summary["arcs"] = arcs;
      summary["lines"] = out.result.legs.size() - arcs;
      double tightest = std::numeric_limits<double>::infinity();
      for (const RouteLeg& leg : out.result.legs) tightest = std::min(tightest, min_turn_radius(leg));
      if (arcs > 0) summary["min_turn_radius_m"] = tightest;
      if (options.turn_radius_m > 0.0) summary["turn_radius_m"] = options.turn_radius_m;
      if (o->from_heading) summary["from_heading_deg"] = frame.local_to_heading(*problem.start_heading, problem.start);
      if (o->to_heading) summary["to_heading_deg"] = frame.local_to_heading(*problem.goal_heading, problem.goal);
    }
    // Per waypoint: the speed of the leg it starts, and time and energy so far.
    std::vector<nlohmann::json> waypoints(route.points.size(), nlohmann::json::object());
    nlohmann::json legs = nlohmann::json::array();
    double cum_time = 0.0, cum_energy = 0.0;
    for (std::size_t i = 0; i < priced.legs.size(); ++i) {
      const PricedLeg& leg = priced.legs[i];
      waypoints[i]["speed_mps"] = leg.cost.speed_mps;
      nlohmann::json row = {{"leg", i + 1},
                            {"length_m", leg.cost.length_m},
                            {"speed_mps", leg.cost.speed_mps},
                            {"feasible", leg.cost.feasible}};
      if (leg.cost.feasible) row["time_s"] = leg.cost.time_s, row["energy_j"] = leg.cost.energy_j;
      if (timed && leg.cost.feasible) row["arrive"] = format_utc(leg.arrive_s);
      legs.push_back(row);
    }
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
      if (i > 0) cum_time += priced.legs[i - 1].cost.time_s, cum_energy += priced.legs[i - 1].cost.energy_j;
      if (!priced.feasible) continue;
      waypoints[i]["cum_time_s"] = cum_time;
      waypoints[i]["cum_energy_j"] = cum_energy;
      if (timed) waypoints[i]["eta"] = format_utc(model->depart_s + cum_time);
    }
    if (out_format) {
      RouteExportSettings settings;
      settings.name = std::filesystem::path(o->output).stem().string();
      settings.depth_m = std::isnan(o->depth) ? 0.0 : o->depth;
      for (const PricedLeg& leg : priced.legs) settings.leg_speeds_mps.push_back(leg.cost.speed_mps);
      if (priced.feasible) {
        for (const PricedLeg& leg : priced.legs) settings.leg_times_s.push_back(leg.cost.time_s);
      }
      settings.margin_m = o->margin;
      settings.turn_radius_m = options.turn_radius_m;
      if (!std::isnan(o->depth)) settings.safety_depth_m = o->depth + o->vertical_clearance;
      if (timed) settings.depart_utc_s = model->depart_s;
      ExportRoute exported = export_route(route, frame, vehicle_of(*o), settings);
      exported.properties = summary;
      exported.waypoint_properties = waypoints;
      write_route_file(exported, o->output, *out_format, {.overwrite = true});
    }
    summary["legs"] = legs;
    if (replay) {
      summary["repairs"] = repairs;
      summary["reached_goal"] = replay->reached_goal;
    }
    if (!o->render.empty() && charted.enc) {
      // S-57 charts: the route over the chart as an ECDIS draws it.
      RouteOnChart figure;
      figure.charts = o->charts;
      figure.depth_m = o->depth;
      figure.clearance_m = o->vertical_clearance;
      figure.local_crs = frame.id();
      figure.route = route.points;
      figure.title = route_title("deepguide plan", route, o->margin, frame);
      render_route_on_chart(figure, o->render);
    } else if (!o->render.empty()) {
      RouteScene scene;
      scene.obstacles = &obstacles;
      scene.margin = o->margin;
      scene.route = route.points;
      scene.start = problem.start;
      scene.goal = problem.goal;
      scene.true_north_deg = true_north_deg(frame, problem.start);
      scene.title = route_title("deepguide plan", route, o->margin, frame);
      if (model->current) {
        scene.current = [model](const Vec2& p) { return model->current(p, model->depart_s); };
        char label[96];
        std::snprintf(label, sizeof label, "current%s (fastest %.2f m/s)", timed ? " at departure" : "",
                      model->max_current_mps);
        scene.current_label = label;
      }
      if (model->current || model->economical) {
        for (const PricedLeg& leg : priced.legs) {
          char text[96];
          if (leg.cost.feasible) {
            std::snprintf(text, sizeof text, "%.2f m/s, %s, %.0f kJ", leg.cost.speed_mps, clock_text(leg.cost.time_s).c_str(),
                          leg.cost.energy_j / 1e3);
          } else {
            std::snprintf(text, sizeof text, "%.2f m/s: the current wins", leg.cost.speed_mps);
          }
          scene.leg_labels.push_back(text);
        }
      }
      ObstacleSet reported;
      if (replay) {
        for (const Detection& d : detections) {
          reported.ellipses.insert(reported.ellipses.end(), d.obstacles.ellipses.begin(), d.obstacles.ellipses.end());
          reported.polygons.insert(reported.polygons.end(), d.obstacles.polygons.begin(), d.obstacles.polygons.end());
        }
        scene.detected = &reported;
        for (const Repair& r : replay->repairs) {
          if (r.found) scene.repaired_routes.push_back(r.route);
        }
        scene.track = replay->track;
      }
      if (o->render_graph && plan.planner->quadtree() != nullptr) {
        const CellTree<2>& tree = plan.planner->quadtree()->tree();
        for (const auto& leaf : tree.leaves()) {
          auto& cells = leaf.state == CellState::free ? scene.free_cells : scene.occupied_cells;
          const auto box = tree.box(leaf);
          cells.emplace_back(box.min, box.max);
        }
      }
      if (o->render_graph) {
        if (!plan.planner->zone_polygons().empty()) scene.zone_polygons = &plan.planner->zone_polygons();
        scene.graph_edges = plan.planner->graph_edges();
      }
      render_route(scene, o->render);
    }
    // Written and printed first, then said loudly: a replay where the vehicle is walled in is exit 3.
    const auto stopped = [&] {
      if (!replay || replay->reached_goal) return;
      const Repair& last = replay->repairs.back();
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    "after report %zu (in order of detected_at_m), %.1f m along the route at (%.2f, %.2f), no way on "
                    "to the goal",
                    replay->repairs.size(), last.along_m, last.vehicle.x(), last.vehicle.y());
      throw NoRouteError(buf);
    };
    if (o->json) {
      std::cout << summary.dump(2) << "\n";
      stopped();
      return;
    }
    std::printf("length           %.2f m, %zu waypoints\n", route.length(), route.points.size());
    if (!out.result.legs.empty()) {
      std::printf("exact length     %.3f m in %zu lines and arcs (the polyline keeps outside the arcs)\n",
                  out.result.exact_length_m, out.result.legs.size());
      double tightest = std::numeric_limits<double>::infinity();
      for (const RouteLeg& leg : out.result.legs) tightest = std::min(tightest, min_turn_radius(leg));
      if (std::isfinite(tightest)) {
        std::printf("tightest turn    %.2f m radius%s\n", tightest,
                    options.turn_radius_m > 0.0 ? (" (turning radius " + general(options.turn_radius_m) + " m)").c_str()
                                                : "");
      }
    }
    std::printf("min clearance    %.2f m (margin %.2f m)\n", min_clearance, o->margin);
    if (!out.escaped_from.empty() && route.points.size() > 1) {
      std::printf("escape           the first leg, %.1f m, leaves obstacle '%s''s zone from inside it; the clearance "
                  "is the rest's\n",
                  (route.points[1] - route.points[0]).norm(), printable(out.escaped_from).c_str());
    }
    std::printf("graph            %s over %zu of %zu obstacles, %zu vertices, %zu edges; %s expanded %zu\n",
                o->graph.c_str(), plan.obstacles_used, plan.obstacles_total, out.result.stats.graph_vertices,
                out.result.stats.graph_edges, o->search.c_str(), out.result.stats.expanded);
    if (out.result.stats.open_water_vertices > 0) {
      std::printf("waypoint grid    %zu open-water vertices %.0f m apart\n", out.result.stats.open_water_vertices,
                  *o->waypoint_grid);
    }
    if (out.result.stats.refine_sweeps > 0) {
      std::printf("refinement       %.3f %% of the graph route's %s saved off its vertices, %zu sweeps\n",
                  100.0 * out.result.stats.refine_gain, o->cost.c_str(), out.result.stats.refine_sweeps);
    }
    std::printf("time             build %.2f ms, query %.2f ms (%d round%s)", plan.build_ms, plan.query_ms, plan.rounds,
                plan.rounds == 1 ? "" : "s");
    if (out.result.stats.refine_sweeps > 0) std::printf(", refinement %.1f ms", out.result.stats.refine_ms);
    std::printf("\n");
    if (priced.feasible) {
      std::printf("time, energy     %.1f s (%s), %.1f kJ at %s speed\n", priced.time_s, clock_text(priced.time_s).c_str(), priced.energy_j / 1e3, o->speed.c_str());
      if (timed) {
        std::printf("depart, arrive   %s, %s\n", format_utc(model->depart_s).c_str(),
                    format_utc(model->depart_s + priced.time_s).c_str());
      }
    }
    if (shortest && !shortest->feasible) {
      std::printf("shortest route   %.2f m: the current beats the vehicle on it\n", shortest->length_m);
    } else if (shortest && priced.feasible) {
      const bool by_time = model->kind == CostKind::time;
      const double saved = 1.0 - (by_time ? priced.time_s / shortest->time_s : priced.energy_j / shortest->energy_j);
      std::printf("shortest route   %.2f m: %.1f s, %.1f kJ; this route saves %.2f %% %s\n", shortest->length_m,
                  shortest->time_s, shortest->energy_j / 1e3, 100.0 * saved, by_time ? "time" : "energy");
    }
    if (model->current && priced.unknown_current_m > 0.0) {
      std::printf("current unknown  over %.0f m of the route (taken as still water)\n", priced.unknown_current_m);
    }
    if (model->current || model->economical) {
      std::printf("%4s %10s %9s %9s %10s%s\n", "leg", "length m", "speed m/s", "time s", "energy kJ",
                  timed ? "  arrive" : "");
      for (const PricedLeg& leg : priced.legs) {
        const std::size_t k = static_cast<std::size_t>(&leg - priced.legs.data()) + 1;
        if (!leg.cost.feasible) {
          std::printf("%4zu %10.1f %9.2f  the current beats the vehicle\n", k, leg.cost.length_m, leg.cost.speed_mps);
          continue;
        }
        std::printf("%4zu %10.1f %9.2f %9.1f %10.1f%s%s\n", k, leg.cost.length_m, leg.cost.speed_mps, leg.cost.time_s,
                    leg.cost.energy_j / 1e3, timed ? "  " : "", timed ? format_utc(leg.arrive_s).c_str() : "");
      }
    }
    if (replay) {
      std::printf("replanning       %zu detection(s) replayed with D* Lite; the vehicle %s\n", replay->repairs.size(),
                  replay->reached_goal ? "reaches the goal" : "stops: no way on");
      std::printf("%6s %10s %8s %10s %9s %10s\n", "repair", "along m", "blocked", "length m", "expanded", "repair ms");
      for (std::size_t k = 0; k < replay->repairs.size(); ++k) {
        const Repair& r = replay->repairs[k];
        if (r.found) {
          std::printf("%6zu %10.1f %8zu %10.2f %9zu %10.2f\n", k + 1, r.along_m, r.blocked_edges, r.cost, r.expanded,
                      r.repair_ms);
        } else {
          std::printf("%6zu %10.1f %8zu %10s %9zu %10.2f\n", k + 1, r.along_m, r.blocked_edges, "no route",
                      r.expanded, r.repair_ms);
        }
      }
    }
    if (passed_over > 0) std::printf("passed over      %zu obstacle(s) deeper than the depth band\n", passed_over);
    if (!o->output.empty()) std::printf("wrote            %s\n", o->output.c_str());
    if (!o->render.empty()) std::printf("rendered         %s\n", o->render.c_str());
    stopped();
  });
}

}  // namespace deepguide::app
