#include "deepguide/evaluation/eval_method.hpp"

#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/simulation/route_following.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace deepguide {

namespace {

[[noreturn]] void unknown(const std::string& text, const std::string& why) {
  throw InputError("unknown method '" + printable(text) + "'" + (why.empty() ? "" : " (" + why + ")") + ": expected " +
                   reactive_method_names_text() + ", or GRAPH[:SEARCH][:COST] with GRAPH " +
                   graph_names_text([](const GraphEntry& e) { return !e.can.in_depth; }) +
                   ", SEARCH astar or dijkstra, COST length, time or energy");
}

void fill_from(MethodRun& run, const SimulationResult& sim) {
  run.end = std::string(to_string(sim.end));
  run.reached = sim.stats.reached;
  run.collided = sim.stats.collided;
  if (sim.collision) {
    run.unavoidable = sim.collision->unavoidable;
    run.note = sim.collision->reason;
  }
  run.path_length_m = sim.stats.path_length_m;
  run.energy_j = sim.stats.energy_j;
  run.time_s = sim.stats.time_s;
  run.min_clearance_m = sim.stats.min_clearance_m;
  run.max_rate_ref = sim.stats.max_abs_rate_ref;
  run.rms_rate_ref = sim.stats.rms_rate_ref;
  run.max_rate = sim.stats.max_abs_rate;
  run.rms_rate = sim.stats.rms_rate;
  run.heading_reversals = sim.stats.heading_reversals;
}

void keep(MethodRun& run, const SimulationResult& sim) {
  for (const TrajectorySample& x : sim.trajectory) run.track.push_back(x.position);
}

MethodRun run_planner(const Scenario& sc, const EvalMethod& m, bool keep_track) {
  ObstacleSet obstacles;
  obstacles.ellipses = sc.obstacles;
  PlannerOptions options;
  options.margin = sc.reactive.margin_m;
  options.graph = m.graph;
  options.search = m.search;
  // Routes that turn no tighter than the vehicle can at the speed it sails
  // them (the tangent graph along rounded zones, the visibility graphs and
  // the smoothed quadtree with rounded corners), planned with room for
  // tracking. A graph that keeps no radius gives its corners as they are.
  if (graph_entry(m.graph).can.turn_radius) {
    options.turn_radius_m = route_turn_radius(sc.vehicle, sc.reactive.speed_mps, sc.current.norm());
  }
  options.margin += kPathTrackingAllowance_m;
  options.quadtree.smooth = true;
  if (m.cost != CostKind::length) {
    auto cost = std::make_shared<CostModel>();
    cost->kind = m.cost;
    const Vec2 current = sc.current;
    cost->current = [current](const Vec2&, double) { return std::optional<Vec2>(current); };
    cost->max_current_mps = current.norm();
    cost->speed_mps = sc.reactive.speed_mps;
    cost->leg.energy = sc.energy;
    validate(*cost);
    options.cost = cost;
  }
  MethodRun run;
  SingleQueryPlan plan;
  try {
    plan = plan_single_query(obstacles, {sc.start, sc.target, false}, options);
  } catch (const NoRouteError& e) {
    run.end = "no_route";
    run.note = e.what();
    return run;
  }
  run.compute_ms = plan.build_ms + plan.query_ms;
  const PlanResult& r = plan.outcome.result;
  run.graph_vertices = r.stats.graph_vertices;
  run.graph_edges = r.stats.graph_edges;
  if (!r.found) {
    run.end = "no_route";
    run.note = r.message;
    run.min_clearance_m = std::numeric_limits<double>::infinity();
    return run;
  }
  run.route_length_m = r.legs.empty() ? r.route.length() : r.exact_length_m;  // what is sailed
  RouteFollowing follow;
  follow.simulation.record_trajectory = keep_track;
  const SimulationResult sailed = r.legs.empty() ? follow_route(sc, r.route, follow) : follow_route(sc, r.legs, follow);
  fill_from(run, sailed);
  if (keep_track) {
    run.route = r.route.points;
    keep(run, sailed);
  }
  return run;
}

}  // namespace

std::vector<EvalMethod> parse_eval_methods(const std::string& list) {
  std::vector<EvalMethod> out;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) out.push_back(parse_eval_method(name));
  if (out.empty())
    throw InputError("methods: expected a comma-separated list, e.g. visibility,quadtree,geometric,dipole");
  return out;
}

EvalMethod parse_eval_method(const std::string& text) {
  EvalMethod m;
  if (const auto reactive = parse_reactive_method(text)) {
    m.reactive = *reactive;
    m.name = text;
    return m;
  }
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
  if (text.empty() || text.back() == ':' || parts.empty() || parts.size() > 3) unknown(text, "");
  try {
    m.graph = parse_graph_kind(parts[0]);
  } catch (const InputError&) {
    unknown(text, "");
  }
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if (parts[i] == "astar" || parts[i] == "dijkstra") {
      if (i != 1) unknown(text, "the search comes before the cost");
      m.search = parse_search(parts[i]);
    } else if (parts[i] == "length" || parts[i] == "time" || parts[i] == "energy") {
      if (i + 1 != parts.size()) unknown(text, "the cost comes last");
      m.cost = parse_cost_kind(parts[i]);
    } else {
      unknown(text, "no search or cost '" + printable(parts[i]) + "'");
    }
  }
  const GraphEntry& graph = graph_entry(m.graph);
  if (graph.can.in_depth) unknown(text, "the " + graph.name + " graph plans in depth; the scenarios are in the plane");
  if (m.cost != CostKind::length && !graph.can.weighs_cost) {
    unknown(text, "the " + graph.name + " graph prices by length only");
  }
  m.name = to_string(m.graph);
  if (m.search != SearchAlgorithm::astar) m.name += ":" + to_string(m.search);
  if (m.cost != CostKind::length) m.name += ":" + to_string(m.cost);
  return m;
}

MethodRun run_method(const Scenario& sc, const EvalMethod& m, bool keep_track) {
  if (m.is_planner()) return run_planner(sc, m, keep_track);
  SimulationOptions options;
  options.record_trajectory = keep_track;
  const SimulationResult sim = simulate(sc, *m.reactive, options);
  MethodRun run;
  fill_from(run, sim);
  if (keep_track) keep(run, sim);
  run.compute_ms = sim.guidance_ms;
  return run;
}

}  // namespace deepguide
