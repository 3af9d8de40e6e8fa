#include "deepguide/planning/replanning.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/dstar_lite.hpp"

namespace deepguide {

std::vector<ReplanEvent> load_detections(const std::string& path, const LocalFrame& frame,
                                         const std::string& source_crs) {
  ObstacleReadOptions options;
  options.local_crs = frame.id();
  options.source_crs = source_crs;
  options.extra_fields = {"detected_at_m"};
  const LoadedObstacles loaded = load_obstacles({path}, options);
  std::vector<ReplanEvent> out;
  const auto distance = [](const ObstacleOrigin& origin) {
    const std::optional<std::string>& text = origin.extra.at(0);
    InputLocation at = origin.where;
    at.field = "detected_at_m";
    double v = std::nan("");
    if (text) {
      try {
        std::size_t used = 0;
        v = std::stod(*text, &used);
        if (used != text->size()) v = std::nan("");
      } catch (const std::exception&) {
      }
    }
    if (!(v >= 0.0) || !std::isfinite(v)) {
      throw input_error(at, "the distance sailed (m, >= 0) when the sonar reports it",
                        text ? "'" + *text + "'" : std::string("nothing"));
    }
    return v;
  };
  for (std::size_t i = 0; i < loaded.obstacles.ellipses.size(); ++i) {
    ReplanEvent d;
    d.along_m = distance(loaded.ellipse_origins.at(i));
    d.obstacles.ellipses.push_back(loaded.obstacles.ellipses[i]);
    out.push_back(std::move(d));
  }
  for (std::size_t i = 0; i < loaded.obstacles.polygons.size(); ++i) {
    ReplanEvent d;
    d.along_m = distance(loaded.polygon_origins.at(i));
    d.obstacles.polygons.push_back(loaded.obstacles.polygons[i]);
    out.push_back(std::move(d));
  }
  return out;
}

namespace {

// The detections in the order the vehicle meets them.
void sort_detections(std::vector<ReplanEvent>& detections) {
  for (const ReplanEvent& d : detections) {
    if (!(d.along_m >= 0.0) || !std::isfinite(d.along_m)) {
      throw InputError("detection: along_m: expected a distance >= 0 m along the route");
    }
  }
  std::stable_sort(detections.begin(), detections.end(),
                   [](const ReplanEvent& a, const ReplanEvent& b) { return a.along_m < b.along_m; });
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Replay replay_detections(QuadtreeGraph& graph, const PlanningProblem& problem, std::vector<ReplanEvent> detections,
                         double margin, const std::function<void(const Repair&, GraphVertex)>& after_repair) {
  sort_detections(detections);
  graph.attach(problem);
  const GraphVertex goal = graph.goal_vertex();
  const auto h = [&graph](GraphVertex a, GraphVertex b) { return (graph.position(a) - graph.position(b)).norm(); };
  DStarLite dstar(graph.graph(), graph.start_vertex(), goal, h);
  const auto positions = [&graph](const std::vector<GraphVertex>& path) {
    std::vector<Vec2> out;
    for (GraphVertex v : path) out.push_back(graph.position(v));
    return out;
  };

  Replay replay;
  if (!dstar.compute()) {
    graph.detach();
    throw NoRouteError("the goal cannot be reached from the start through the quadtree's free cells");
  }
  replay.initial_route = positions(dstar.path());
  replay.initial_cost = dstar.cost();
  GraphVertex at = graph.start_vertex();
  replay.track = {graph.position(at)};
  replay.track_vertices = {at};
  double sailed = 0.0;
  // Sails on along the current route until `until` metres (or the goal, or a dead end).
  const std::size_t vertices = boost::num_vertices(graph.graph());
  const auto sail = [&](double until) {
    for (std::size_t steps = 0; at != goal && sailed < until; ++steps) {
      // An optimal route visits no vertex twice: more steps than vertices is a defect, not a voyage.
      if (steps > vertices) throw std::logic_error("replanning: the vehicle's route does not reach the goal");
      const GraphVertex next = dstar.next_from(at);
      if (next == at) return;
      sailed += (graph.position(next) - graph.position(at)).norm();
      at = next;
      replay.track.push_back(graph.position(at));
      replay.track_vertices.push_back(at);
    }
  };
  for (const ReplanEvent& d : detections) {
    sail(d.along_m);
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t before = dstar.expanded();
    dstar.move_to(at);
    Repair r;
    r.along_m = sailed;
    r.vehicle = graph.position(at);
    const ObstacleField newcomers(d.obstacles, margin);
    for (const auto& [u, v] : graph.edges_blocked_by(newcomers)) {
      // Edges an earlier report blocked already are not counted again.
      if (dstar.update_edge(u, v, std::numeric_limits<double>::infinity())) ++r.blocked_edges;
    }
    r.found = dstar.compute();
    r.cost = dstar.cost();
    r.expanded = dstar.expanded() - before;
    r.repair_ms = ms_since(t0);
    if (r.found) r.route = positions(dstar.path());
    if (after_repair) after_repair(r, at);
    replay.repairs.push_back(std::move(r));
    if (!replay.repairs.back().found) break;  // no way on: the vehicle stops here
  }
  if (replay.repairs.empty() || replay.repairs.back().found) sail(std::numeric_limits<double>::infinity());
  replay.reached_goal = at == goal;
  graph.detach();
  return replay;
}

Replay replay_detections(NavMeshGraph& graph, const PlanningProblem& problem, std::vector<ReplanEvent> detections) {
  sort_detections(detections);
  const PlanResult first = graph.solve(problem, SearchAlgorithm::astar, nullptr, {});
  if (!first.found) throw NoRouteError(first.message.empty() ? "no route from the start to the goal" : first.message);
  Replay replay;
  replay.remeshed = true;
  replay.initial_route = first.route.points;
  replay.initial_cost = first.route.length();
  replay.track = {problem.start};
  std::vector<Vec2> route = first.route.points;  // what the vehicle sails now, from its last vertex
  std::size_t next = 1;                          // the route's vertex it sails towards
  Vec2 at = problem.start;
  double sailed = 0.0;
  // Sails on along the route until `until` metres, or to its end.
  const auto sail = [&](double until) {
    while (next < route.size()) {
      const double leg = (route[next] - at).norm();
      if (sailed + leg > until) {
        at += (until - sailed) / leg * (route[next] - at);
        sailed = until;
        replay.track.push_back(at);
        return;
      }
      sailed += leg;
      at = route[next++];
      replay.track.push_back(at);
    }
  };
  for (const ReplanEvent& d : detections) {
    sail(d.along_m);
    Repair r;
    r.along_m = sailed;
    r.vehicle = at;
    const auto t0 = std::chrono::steady_clock::now();
    r.remeshed_faces = graph.insert(d.obstacles).removed;
    if (at == problem.goal) {
      // Reported when the vehicle has arrived: nothing is left to repair.
      r.found = true;
      r.route = {at};
    } else {
      const PlanResult again = graph.solve({at, problem.goal}, SearchAlgorithm::astar, nullptr, {});
      r.found = again.found;
      r.expanded = again.stats.expanded;
      if (again.found) r.route = again.route.points;
    }
    r.cost = r.found ? Route{r.route}.length() : std::numeric_limits<double>::infinity();
    r.repair_ms = ms_since(t0);
    if (r.found && r.route.size() >= 2) {
      route = r.route;
      next = 1;
    }
    replay.repairs.push_back(std::move(r));
    if (!replay.repairs.back().found) break;  // no way on: the vehicle stops here
  }
  if (replay.repairs.empty() || replay.repairs.back().found) sail(std::numeric_limits<double>::infinity());
  replay.reached_goal = at == problem.goal;
  return replay;
}

}  // namespace deepguide
