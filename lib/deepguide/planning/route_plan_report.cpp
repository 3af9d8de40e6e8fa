#include "deepguide/planning/route_plan_report.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/charts/enc_route_check.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/waypoint_grid.hpp"
#include "deepguide/world/frame_scale.hpp"

namespace deepguide {
namespace {

void append(ObstacleSet& to, const ObstacleSet& from) {
  to.ellipses.insert(to.ellipses.end(), from.ellipses.begin(), from.ellipses.end());
  to.polygons.insert(to.polygons.end(), from.polygons.begin(), from.polygons.end());
}

// The vehicle's speeds and energy, the current bound to the frame over the
// start-goal box, the departure time.
CostModel cost_model_of(const RoutePlanRequest& r, const VehicleParams& vehicle, const LocalFrame& frame) {
  CostModel m;
  m.kind = r.cost;
  m.leg.energy = vehicle.energy;
  m.min_speed_mps = vehicle.min_speed_mps;
  m.max_speed_mps = vehicle.max_speed_mps;
  m.speed_mps = vehicle.cruise_speed_mps;
  if (r.speed == "optimal") {
    m.economical = true;
  } else if (r.speed != "cruise") {
    try {
      std::size_t used = 0;
      m.speed_mps = std::stod(r.speed, &used);
      if (used != r.speed.size() || !std::isfinite(m.speed_mps)) throw std::invalid_argument("not a finite number");
    } catch (const std::exception&) {
      throw InputError("`speed`: expected cruise, optimal or a speed in m/s, got '" + r.speed + "'");
    }
  }
  std::shared_ptr<const CurrentField> current = r.current;
  if (!r.current_file.empty()) {
    CurrentOptions read;
    if (!std::isnan(r.depth_m)) read.depth_m = r.depth_m;
    read.assumed_crs = r.src_crs;
    current = std::make_shared<const CurrentField>(load_current_field(r.current_file, read));
  }
  if (current) {
    const Vec2 lo = r.problem.start.cwiseMin(r.problem.goal), hi = r.problem.start.cwiseMax(r.problem.goal);
    attach_current(m, current, frame, lo, hi);
  }
  if (r.depart_s)
    m.depart_s = *r.depart_s;
  else if (!m.steady)
    m.depart_s = m.time_first_s;  // the start of the forecast
  validate(m);
  return m;
}

// Whether the plan turns within a radius: one given, or a vehicle's, which a
// graph whose routes step cell to cell keeps only when smoothed (planner.cpp).
bool keeps_turn_radius(const RoutePlanRequest& r) {
  return r.turn_radius_m || (!r.vehicle.empty() && (!graph_entry(r.graph).can.steps || r.smooth));
}

// The options' combinations the graphs cannot serve, before any file is read.
void check_request(const RoutePlanRequest& r) {
  // Headings ask for Dubins ends, which the tangent graph alone plans (planner.hpp).
  const PlanningProblem& p = r.problem;
  for (const auto& [flag, heading] :
       {std::pair{"`start_heading`", p.start_heading}, {"`goal_heading`", p.goal_heading}}) {
    if (heading && !std::isfinite(*heading)) throw InputError(std::string(flag) + ": expected a heading in degrees");
  }
  if (p.start_heading || p.goal_heading) {
    const std::string which = p.start_heading ? "`start_heading`" : "`goal_heading`";
    if (!graph_entry(r.graph).can.dubins_ends) {
      throw InputError(which + ": expected `graph` " +
                       graph_names_text([](const GraphEntry& e) { return e.can.dubins_ends; }) +
                       " (the graph that plans Dubins ends), got " + to_string(r.graph));
    }
    if (!r.turn_radius_m && r.vehicle.empty()) {
      throw InputError(which + ": expected `turn_radius_m` or `vehicle` (the radius the route turns on)");
    }
  }
  if (r.turn_radius_m && (!std::isfinite(*r.turn_radius_m) || *r.turn_radius_m <= 0.0)) {
    throw InputError("`turn_radius_m`: expected a radius > 0 m, got " + general(*r.turn_radius_m));
  }
  if (!r.replan_events.empty() && (!graph_entry(r.graph).can.repairs || r.cost != CostKind::length || r.smooth ||
                                   r.problem.escape || keeps_turn_radius(r))) {
    throw InputError("`replan_events`: expected `graph` " +
                     graph_names_text([](const GraphEntry& e) { return e.can.repairs; }) +
                     " with `cost` length, and neither `smooth`, `escape` nor a turning radius (`turn_radius_m`, "
                     "or a `vehicle` on that graph): the repairs are unrounded routes by length from a start "
                     "outside every zone");
  }
  if (r.smooth && !graph_entry(r.graph).can.steps) {
    throw InputError("`smooth`: expected `graph` " + graph_names_text([](const GraphEntry& e) { return e.can.steps; }) +
                     " (the other graphs' routes are taut already)");
  }
}

// S-57 charts: a start or goal in a no-go area names the charted feature, not
// the merged no-go polygon the planner would.
void refuse_ends_in_enc_no_go(const EncNoGo& enc, const RoutePlanRequest& r) {
  auto refuse_inside = [&](const Vec2& p, const char* which) {
    if (const EncNoGoFeature* f = no_go_feature_at(enc, p, r.margin_m)) {
      throw NoRouteError(std::string("the ") + which + " lies within " + fixed(r.margin_m, 2) + " m of " + f->id +
                         (f->cell.empty() ? "" : " of " + f->cell) + " (" + f->reason + ")" +
                         (which[0] == 's' ? "; `escape` leaves it by the shortest way" : ""));
    }
  };
  if (!r.problem.escape) refuse_inside(r.problem.start, "start");
  refuse_inside(r.problem.goal, "goal");
}

// Outside a bathymetry raster the depth is not known: a route that leaves it is not safe.
void refuse_leaving_coverage(const ChartObstacles& charted, const Route& route, const LocalFrame& frame) {
  const auto exit = route_leaves_coverage(route.points, charted.raster_coverage);
  if (!exit) return;
  const Vec2 ll = frame.to_lonlat(exit->at);
  const std::string charts =
      charted.raster_paths.front() + (charted.raster_paths.size() > 1 ? " and the other rasters" : std::string());
  const bool start = exit->leg == 0 && (exit->at - route.points.front()).norm() < 1e-9;
  throw NoRouteError((start
                          ? "the start lies outside the coverage of " + charts
                          : "the route leaves the coverage of " + charts + " on leg " + std::to_string(exit->leg + 1)) +
                     " at " + fixed(ll.x(), 6) + "," + fixed(ll.y(), 6) +
                     ": the depth there is not known (give a chart that covers the way)");
}

// Reports that reached the vehicle at the goal: their "repair" is the goal alone.
std::size_t after_arrival(const Replay& replay) {
  return static_cast<std::size_t>(std::count_if(replay.repairs.begin(), replay.repairs.end(),
                                                [](const Repair& r) { return r.found && r.route.size() < 2; }));
}

// No route in a changing current: a route that arrives after the field's last
// time step is as infeasible as one against a current too strong, and
// which it is decides what the user must change (issue 39). The shortest
// route at the planned speed with every node's current behind it gives the
// earliest arrival there can be.
std::string time_axis_reason(const RoutePlanReport& report, const std::string& why) {
  const CostModel& model = *report.model;
  PlannerOptions by_length = report.options;
  by_length.cost = nullptr;
  const SingleQueryPlan shortest = plan_single_query(report.obstacles, report.request.problem, by_length);
  if (!shortest.outcome.result.found) return why;
  const double length = shortest.outcome.result.route.length();
  const double through_water = model.economical ? model.max_speed_mps : model.speed_mps;
  const double earliest = model.depart_s + length / (through_water + model.max_current_mps);
  const std::string axis = format_utc(model.time_first_s) + " .. " + format_utc(model.time_last_s);
  if (earliest <= model.time_last_s) return why + " (or the current field's time axis " + axis + " ends too soon)";
  return "the current field's time axis " + axis + " ends before the vehicle can arrive: the shortest route, " +
         fixed(length, 0) + " m at " + fixed(through_water, 2) + " m/s with at most " +
         fixed(model.max_current_mps, 2) + " m/s of current behind it, departing " + format_utc(model.depart_s) +
         ", arrives at " + format_utc(earliest) + " at the earliest; give a field that covers the voyage";
}

// The detections replayed along the route: with D* Lite on the quadtree
// (the route the report keeps is D* Lite's first: of equal length to A*'s,
// but on a cell grid ties abound, and detected_at_m is measured along the
// one the vehicle sails), or cut out of the navigation mesh and searched
// again. Every mesh repair is checked against the obstacles and every
// detection so far (from where it leaves a detection's zone it started in).
void replay(RoutePlanReport& report) {
  const RoutePlanRequest& r = report.request;
  report.detections = load_detections(r.replan_events, report.frame, r.src_crs);
  RouteGraph& graph = report.plan.planner->graph();
  if (QuadtreeGraph* cells = graph.as<QuadtreeGraph>()) {
    report.replay = replay_detections(*cells, r.problem, report.detections, r.margin_m);
  } else if (NavMeshGraph* mesh = graph.as<NavMeshGraph>()) {
    report.replay = replay_detections(*mesh, r.problem, report.detections);
    ObstacleSet found;
    for (std::size_t k = 0; k < report.replay->repairs.size(); ++k) {
      const ReplanEvent& d = report.detections[k];
      found.ellipses.insert(found.ellipses.end(), d.obstacles.ellipses.begin(), d.obstacles.ellipses.end());
      found.polygons.insert(found.polygons.end(), d.obstacles.polygons.begin(), d.obstacles.polygons.end());
      const Repair& repair = report.replay->repairs[k];
      if (!repair.found || repair.route.size() < 2) continue;
      const ObstacleField detected(found, r.margin_m);
      const bool stepped_out = !detected.is_free(repair.route.front());
      const std::vector<Vec2> judged(repair.route.begin() + (stepped_out ? 1 : 0), repair.route.end());
      for (const ObstacleField* field : {&report.plan.planner->field(), &detected}) {
        const RouteCheck check = check_route(judged, *field);
        if (!check.safe)
          throw std::runtime_error("repair " + std::to_string(k + 1) +
                                   " failed the independent check: " + check.describe());
      }
    }
  } else {
    throw std::logic_error("replay: the plan's graph repairs no route (check_request lets none else)");
  }
  for (std::size_t k = 0; k < report.replay->repairs.size(); ++k) {
    // A report that reaches the vehicle at the goal (reported past the route's
    // end) repairs nothing: no file (it once failed writing a one-point route).
    const Repair& repair = report.replay->repairs[k];
    const bool written = repair.found && repair.route.size() >= 2 && !r.route_file.empty();
    report.repair_files.push_back(written ? repair_file_name(r.route_file, k + 1) : "");
  }
  report.route = Route{report.replay->initial_route};
  const RouteCheck check = check_route(report.route.points, report.plan.planner->field());
  if (!check.safe) throw std::runtime_error("the replanned route failed the independent check: " + check.describe());
  report.min_clearance_m = check.min_clearance_m;
}

}  // namespace

std::string repair_file_name(const std::string& route_file, std::size_t k) {
  const std::filesystem::path p(route_file);
  return (p.parent_path() / (p.stem().string() + "_repair_" + std::to_string(k) + p.extension().string())).string();
}

RoutePlanReport plan_route_request(const LocalFrame& frame, const RoutePlanRequest& r) {
  check_request(r);
  RoutePlanReport report(frame);
  report.request = r;
  report.request.obstacles = {};
  report.obstacles = r.obstacles;
  if (!std::isnan(r.depth_m)) report.passed_over = remove_passable(report.obstacles, r.depth_m, r.vertical_clearance_m);
  std::shared_ptr<const ChartObstacles> read = r.charted;
  if (!read && !r.charts.empty()) {
    ChartObstacleOptions chart_options;
    chart_options.depth_m = r.depth_m;
    chart_options.clearance_m = r.vertical_clearance_m;
    chart_options.source_crs = r.src_crs;
    chart_options.enc = enc_options(r.chart);
    read = std::make_shared<const ChartObstacles>(chart_obstacles(r.charts, frame, chart_options));
  }
  static const ChartObstacles none;
  const ChartObstacles& charted = read ? *read : none;
  if (read) {
    for (const ChartFileObstacles& f : charted.files) report.passed_over += f.passed_over;
    append(report.obstacles, charted.obstacles);
  }
  if (charted.enc) {
    report.enc_charts = true;
    report.enc = charted.enc;
    refuse_ends_in_enc_no_go(*charted.enc, r);
  }
  report.vehicle = r.vehicle.empty() ? VehicleParams{} : read_vehicle_file(r.vehicle);
  report.model = std::make_shared<const CostModel>(cost_model_of(r, report.vehicle, frame));
  const CostModel& model = *report.model;

  PlannerOptions& options = report.options;
  options.margin = r.margin_m;
  options.tolerance = r.tolerance_m;
  options.graph = r.graph;
  options.search = r.search;
  options.quadtree.min_cell_m = r.min_cell_m;
  options.quadtree.smooth = r.smooth;
  options.refine = r.refine;
  options.budget.max_expansions = r.max_expansions;
  if (model.kind != CostKind::length) options.cost = report.model;
  if (r.turn_radius_m) {
    options.turn_radius_m = *r.turn_radius_m;
  } else if (keeps_turn_radius(r)) {
    options.turn_radius_m = route_turn_radius(report.vehicle, model.speed_mps, model.max_current_mps);
  }
  if (r.waypoint_grid_m) options.grid = waypoint_grid_for(r.problem.start, r.problem.goal, *r.waypoint_grid_m);
  options.prepared = charted.prepared_graphs;
  options.prepared_obstacles = charted.prepared_obstacles;

  report.plan = plan_single_query(report.obstacles, r.problem, options);
  const PlanOutcome& out = report.plan.outcome;
  if (!out.result.found) {
    std::string why = out.result.message;
    if (options.cost && !model.steady && out.result.stats.stopped == SearchStop::none)
      why = time_axis_reason(report, why);
    if (charted.enc) {
      // What an operator looks at first: the no-go feature across the straight line (a shoal, a
      // hazard's disc across a channel).
      const ChartRouteCheck straight =
          check_route_on_chart({r.problem.start, r.problem.goal}, *charted.enc, r.margin_m);
      if (!straight.safe) why += "; the straight line " + straight.describe(frame);
    }
    throw NoRouteError(why);
  }
  if (!out.check.safe)
    throw std::runtime_error("the planned route failed the independent check: " + out.check.describe());
  if (out.legs_check && !out.legs_check->safe) {
    throw std::runtime_error("the route's lines and arcs failed the independent check: " + out.legs_check->describe());
  }
  // What the vehicle sails: the lines and arcs where the planner gives them
  // (a polygon route's fillets lie inside its corners), else the polyline.
  report.route = out.result.route;
  report.min_clearance_m = out.legs_check ? out.legs_check->min_clearance_m : out.check.min_clearance_m;
  if (!r.replan_events.empty()) replay(report);
  refuse_leaving_coverage(charted, report.route, frame);
  {  // Where the route goes, the frame's metres are true ones (frame_scale.hpp).
    std::vector<Vec2> lonlat;
    for (const Vec2& p : report.route.points) lonlat.push_back(frame.to_lonlat(p));
    require_true_scale(frame, lonlat, "the route");
  }
  if (charted.enc) report.chart_quality = route_quality(report.route.points, *charted.enc);

  report.priced = price_route(model, report.route.points);
  report.timed = !model.steady || r.depart_s.has_value();
  if (model.kind != CostKind::length) {
    PlannerOptions by_length = options;
    by_length.cost = nullptr;
    by_length.grid = {};
    const SingleQueryPlan plain = plan_single_query(report.obstacles, r.problem, by_length);
    if (plain.outcome.result.found) report.shortest = price_route(model, plain.outcome.result.route.points);
  }
  return report;
}

nlohmann::json RoutePlanReport::route_properties() const {
  const PlanOutcome& out = plan.outcome;
  const PlanStats& stats = out.result.stats;
  nlohmann::json j = {{"length_m", route.length()},
                      {"waypoints", route.points.size()},
                      {"min_clearance_m", min_clearance_m},
                      {"margin_m", request.margin_m},
                      {"graph", to_string(request.graph)},
                      {"search", to_string(request.search)},
                      {"graph_vertices", stats.graph_vertices},
                      {"graph_edges", stats.graph_edges},
                      {"graph_prepared", stats.prepared},
                      {"open_water_vertices", stats.open_water_vertices},
                      {"refine_sweeps", stats.refine_sweeps},
                      {"refine_gain", stats.refine_gain},
                      {"refine_ms", stats.refine_ms},
                      {"expanded", stats.expanded},
                      {"build_ms", plan.build_ms},
                      {"query_ms", plan.query_ms},
                      {"obstacles", plan.obstacles_total},
                      {"obstacles_in_graph", plan.obstacles_used},
                      {"rounds", plan.rounds},
                      {"passed_over", passed_over},
                      {"crs", frame.id()}};
  j["cost"] = to_string(request.cost);
  j["speed"] = request.speed;
  j["feasible"] = priced.feasible;
  j["time_s"] = priced.feasible ? nlohmann::json(priced.time_s) : nlohmann::json();
  j["energy_j"] = priced.feasible ? nlohmann::json(priced.energy_j) : nlohmann::json();
  if (model->current) {
    j["max_current_mps"] = model->max_current_mps;
    j["unknown_current_m"] = priced.unknown_current_m;
    j["current"] = request.current_source.empty() ? request.current_file : request.current_source;
  }
  if (shortest) {
    j["shortest_length_m"] = shortest->length_m;
    j["shortest_feasible"] = shortest->feasible;
    if (shortest->feasible) j["shortest_time_s"] = shortest->time_s;
    if (shortest->feasible) j["shortest_energy_j"] = shortest->energy_j;
  }
  if (timed) {
    j["depart"] = format_utc(model->depart_s);
    if (priced.feasible) j["arrive"] = format_utc(model->depart_s + priced.time_s);
  }
  if (!out.escaped_from.empty()) j["escaped_from"] = out.escaped_from;
  if (!out.result.legs.empty()) {
    j["exact_length_m"] = out.result.exact_length_m;
    std::size_t arcs = 0;
    double tightest = std::numeric_limits<double>::infinity();
    for (const RouteLeg& leg : out.result.legs) {
      arcs += leg.kind == RouteLeg::Kind::arc;
      tightest = std::min(tightest, min_turn_radius(leg));
    }
    j["arcs"] = arcs;
    j["lines"] = out.result.legs.size() - arcs;
    if (arcs > 0) j["min_turn_radius_m"] = tightest;
    if (options.turn_radius_m > 0.0) j["turn_radius_m"] = options.turn_radius_m;
    const PlanningProblem& p = request.problem;
    if (p.start_heading) j["from_heading_deg"] = frame.local_to_heading(*p.start_heading, p.start);
    if (p.goal_heading) j["to_heading_deg"] = frame.local_to_heading(*p.goal_heading, p.goal);
  }
  return j;
}

nlohmann::json RoutePlanReport::to_json() const {
  nlohmann::json j = route_properties();
  nlohmann::json legs = nlohmann::json::array();
  for (std::size_t i = 0; i < priced.legs.size(); ++i) {
    const PricedLeg& leg = priced.legs[i];
    nlohmann::json row = {{"leg", i + 1},
                          {"length_m", leg.cost.length_m},
                          {"speed_mps", leg.cost.speed_mps},
                          {"feasible", leg.cost.feasible}};
    if (leg.cost.feasible) row["time_s"] = leg.cost.time_s, row["energy_j"] = leg.cost.energy_j;
    if (timed && leg.cost.feasible) row["arrive"] = format_utc(leg.arrive_s);
    legs.push_back(row);
  }
  j["legs"] = legs;
  if (chart_quality) j["chart_quality"] = chart_quality->to_json(frame);
  if (replay) {
    nlohmann::json repairs = nlohmann::json::array();
    for (std::size_t k = 0; k < replay->repairs.size(); ++k) {
      const Repair& r = replay->repairs[k];
      nlohmann::json row = {{"repair", k + 1},  {"along_m", r.along_m},   {"blocked_edges", r.blocked_edges},
                            {"found", r.found}, {"expanded", r.expanded}, {"repair_ms", r.repair_ms}};
      if (replay->remeshed) row["remeshed_faces"] = r.remeshed_faces;
      if (r.found) row["length_m"] = r.cost;
      if (!repair_files[k].empty()) row["file"] = repair_files[k];
      repairs.push_back(row);
    }
    j["repairs"] = repairs;
    j["reached_goal"] = replay->reached_goal;
    j["detections_after_arrival"] = after_arrival(*replay);
  }
  return j;
}

std::vector<nlohmann::json> RoutePlanReport::waypoint_properties() const {
  std::vector<nlohmann::json> waypoints(route.points.size(), nlohmann::json::object());
  double time = 0.0, energy = 0.0;
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    if (i < priced.legs.size()) waypoints[i]["speed_mps"] = priced.legs[i].cost.speed_mps;
    if (i > 0) time += priced.legs[i - 1].cost.time_s, energy += priced.legs[i - 1].cost.energy_j;
    if (!priced.feasible) continue;
    waypoints[i]["cum_time_s"] = time;
    waypoints[i]["cum_energy_j"] = energy;
    if (timed) waypoints[i]["eta"] = format_utc(model->depart_s + time);
  }
  return waypoints;
}

std::vector<std::string> RoutePlanReport::warnings() const {
  if (priced.feasible) return {};
  return {"the current beats the vehicle on part of this " + to_string(request.cost) +
          " route; plan by time or energy to avoid it"};
}

std::optional<std::string> RoutePlanReport::stop_reason() const {
  if (!replay || replay->reached_goal) return std::nullopt;
  const Repair& last = replay->repairs.back();
  return "after report " + std::to_string(replay->repairs.size()) + " (in order of detected_at_m), " +
         fixed(last.along_m, 1) + " m along the route at " + point_text(last.vehicle, 2) + ", no way on to the goal";
}

std::string RoutePlanReport::to_text() const {
  const PlanOutcome& out = plan.outcome;
  const PlanStats& stats = out.result.stats;
  std::string t =
      report_line("length", fixed(route.length(), 2) + " m, " + std::to_string(route.points.size()) + " waypoints");
  if (!out.result.legs.empty()) {
    t += report_line("exact length", fixed(out.result.exact_length_m, 3) + " m in " +
                                         std::to_string(out.result.legs.size()) +
                                         " lines and arcs (the polyline keeps outside the arcs)");
    double tightest = std::numeric_limits<double>::infinity();
    for (const RouteLeg& leg : out.result.legs) tightest = std::min(tightest, min_turn_radius(leg));
    if (std::isfinite(tightest)) {
      t += report_line(
          "tightest turn",
          fixed(tightest, 2) + " m radius" +
              (options.turn_radius_m > 0.0 ? " (turning radius " + general(options.turn_radius_m) + " m)" : ""));
    }
  }
  t += report_line("min clearance", fixed(min_clearance_m, 2) + " m (margin " + fixed(request.margin_m, 2) + " m)");
  if (!out.escaped_from.empty() && route.points.size() > 1) {
    t += report_line("escape", "the first leg, " + fixed((route.points[1] - route.points[0]).norm(), 1) +
                                   " m, leaves obstacle '" + printable(out.escaped_from) +
                                   "''s zone from inside it; the clearance is the rest's");
  }
  t += report_line("graph", to_string(request.graph) + (stats.prepared ? " (prepared)" : "") + " over " +
                                std::to_string(plan.obstacles_used) + " of " + std::to_string(plan.obstacles_total) +
                                " obstacles, " + std::to_string(stats.graph_vertices) + " vertices, " +
                                std::to_string(stats.graph_edges) + " edges; " + to_string(request.search) +
                                " expanded " + std::to_string(stats.expanded));
  if (stats.open_water_vertices > 0) {
    t += report_line("waypoint grid", std::to_string(stats.open_water_vertices) + " open-water vertices " +
                                          fixed(request.waypoint_grid_m.value_or(0.0), 0) + " m apart");
  }
  if (stats.refine_sweeps > 0) {
    t += report_line("refinement", fixed(100.0 * stats.refine_gain, 3) + " % of the graph route's " +
                                       to_string(request.cost) + " saved off its vertices, " +
                                       std::to_string(stats.refine_sweeps) + " sweeps");
  }
  t += report_line("time", "build " + fixed(plan.build_ms, 2) + " ms, query " + fixed(plan.query_ms, 2) + " ms (" +
                               std::to_string(plan.rounds) + " round" + (plan.rounds == 1 ? "" : "s") + ")" +
                               (stats.refine_sweeps > 0 ? ", refinement " + fixed(stats.refine_ms, 1) + " ms" : ""));
  if (priced.feasible) {
    t += report_line("time, energy", fixed(priced.time_s, 1) + " s (" + clock_text(priced.time_s) + "), " +
                                         fixed(priced.energy_j / 1e3, 1) + " kJ at " + request.speed + " speed");
    if (timed) {
      t += report_line("depart, arrive",
                       format_utc(model->depart_s) + ", " + format_utc(model->depart_s + priced.time_s));
    }
  }
  if (shortest && !shortest->feasible) {
    t += report_line("shortest route", fixed(shortest->length_m, 2) + " m: the current beats the vehicle on it");
  } else if (shortest && priced.feasible) {
    const bool by_time = model->kind == CostKind::time;
    const double saved = 1.0 - (by_time ? priced.time_s / shortest->time_s : priced.energy_j / shortest->energy_j);
    t += report_line("shortest route", fixed(shortest->length_m, 2) + " m: " + fixed(shortest->time_s, 1) + " s, " +
                                           fixed(shortest->energy_j / 1e3, 1) + " kJ; this route saves " +
                                           fixed(100.0 * saved, 2) + " % " + (by_time ? "time" : "energy"));
  }
  if (model->current && priced.unknown_current_m > 0.0) {
    t += report_line("current unknown",
                     "over " + fixed(priced.unknown_current_m, 0) + " m of the route (taken as still water)");
  }
  if (chart_quality) t += chart_quality->to_text(frame);
  if (model->current || model->economical) {
    t += printf_text("%4s %10s %9s %9s %10s%s\n", "leg", "length m", "speed m/s", "time s", "energy kJ",
                     timed ? "  arrive" : "");
    for (std::size_t k = 0; k < priced.legs.size(); ++k) {
      const LegCost& c = priced.legs[k].cost;
      if (!c.feasible) {
        t += printf_text("%4zu %10.1f %9.2f  the current beats the vehicle\n", k + 1, c.length_m, c.speed_mps);
      } else {
        t += printf_text("%4zu %10.1f %9.2f %9.1f %10.1f%s%s\n", k + 1, c.length_m, c.speed_mps, c.time_s,
                         c.energy_j / 1e3, timed ? "  " : "", timed ? format_utc(priced.legs[k].arrive_s).c_str() : "");
      }
    }
  }
  if (replay) {
    const bool mesh = replay->remeshed;
    t += report_line("replanning",
                     std::to_string(replay->repairs.size()) + " detection(s) replayed " +
                         (mesh ? "on the navigation mesh (cut round each, searched again)" : "with D* Lite") +
                         "; the vehicle " + (replay->reached_goal ? "reaches the goal" : "stops: no way on") +
                         (after_arrival(*replay) > 0 ? "; " + std::to_string(after_arrival(*replay)) +
                                                           " detection(s) reached it at the goal, nothing to repair"
                                                     : std::string()));
    t += printf_text("%6s %10s %8s %10s %9s %10s\n", "repair", "along m", mesh ? "remeshed" : "blocked", "length m",
                     "expanded", "repair ms");
    for (std::size_t k = 0; k < replay->repairs.size(); ++k) {
      const Repair& r = replay->repairs[k];
      const std::size_t changed = mesh ? r.remeshed_faces : r.blocked_edges;
      if (r.found) {
        t += printf_text("%6zu %10.1f %8zu %10.2f %9zu %10.2f\n", k + 1, r.along_m, changed, r.cost, r.expanded,
                         r.repair_ms);
      } else {
        t += printf_text("%6zu %10.1f %8zu %10s %9zu %10.2f\n", k + 1, r.along_m, changed, "no route", r.expanded,
                         r.repair_ms);
      }
    }
  }
  if (passed_over > 0) {
    t += report_line("passed over", std::to_string(passed_over) + " obstacle(s) deeper than the depth band");
  }
  return t;
}

GraphKind default_plan_graph(const std::vector<std::string>& charts, CostKind cost, bool waypoint_grid, bool heading) {
  if (heading) return GraphKind::tangent;
  if (cost == CostKind::length && !waypoint_grid && std::any_of(charts.begin(), charts.end(), reads_as_enc))
    return GraphKind{"navmesh"};
  return GraphKind::visibility;
}

}  // namespace deepguide
