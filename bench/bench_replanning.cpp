// D* Lite repairs against planning from scratch (docs/PERFORMANCE.md
// "Replanning"): a 2000 m x 2000 m area with 2 m minimum quadtree cells,
// random obstacles, and one rock the sonar reports on the route ahead. Per
// event: the D* Lite repair (blocking the edges and resuming the search)
// against A* from scratch from the vehicle's cell on the same changed graph,
// and against rebuilding the quadtree with the rock and planning again.
// And the navigation mesh's repair on the same events: the rock inserted
// into a mesh built over the same obstacles (NavMeshGraph::insert) and the
// exact route found again from the same vehicle position.
//
//   build/bench/bench_replanning [--scenarios N]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/replanning.hpp"
#include "deepguide/planning/route_check.hpp"

using namespace deepguide;

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int scenarios = 40;
  CLI::App app{"bench_replanning: D* Lite repairs against A* from scratch"};
  app.add_option("--scenarios", scenarios, "Random detection scenarios")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  deepguide::bench::parse_or_exit(app, argc, argv);
  std::mt19937 rng(20021);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> build, repair, scratch, rebuild, ratio, rebuild_ratio, leaves, expanded_repair, expanded_scratch;
  std::vector<double> mesh_repair, mesh_ratio, length_ratio;
  int mesh_unsafe = 0;
  int events = 0, at_goal = 0;
  for (int sc = 0; sc < scenarios; ++sc) {
    ObstacleSet set;
    for (int i = 0; i < 60; ++i) {
      EllipticCylinder c;
      c.id = "e" + std::to_string(i);
      const double a = 10.0 + 40.0 * u(rng);
      c.footprint = Ellipse{{2000.0 * u(rng), 2000.0 * u(rng)}, a, a * (0.3 + 0.7 * u(rng)), M_PI * u(rng)};
      set.ellipses.push_back(c);
    }
    const ObstacleField field(set, 5.0);
    const PlanningProblem problem{{10.0, 1000.0}, {1990.0, 1000.0}};
    if (!field.is_free(problem.start) || !field.is_free(problem.goal)) continue;
    QuadtreeOptions q;
    q.min_cell_m = 2.0;
    q.area_min = {0.0, 0.0};
    q.area_max = {2000.0, 2000.0};
    auto t0 = std::chrono::steady_clock::now();
    QuadtreeGraph graph(field, q);
    build.push_back(ms_since(t0));
    leaves.push_back(static_cast<double>(graph.tree().leaves().size()));
    // The route the vehicle sails (D* Lite's first; A*'s may differ where cells tie).
    Replay plain;
    try {
      plain = replay_detections(graph, problem, {}, 5.0);
    } catch (const NoRouteError&) {
      continue;
    }
    const Route first{plain.initial_route};
    // One rock 25 m across, reported on the route 40 % along, when the vehicle has sailed 30 %.
    const double length = first.length();
    const Vec2 c = first.point_at(0.4 * length);
    ReplanEvent d;
    d.along_m = 0.3 * length;
    EllipticCylinder rock;
    rock.id = "rock";
    rock.footprint = Ellipse{c, 12.5, 12.5, 0.0};
    d.obstacles.ellipses.push_back(rock);
    PlannerOptions mesh_options;
    mesh_options.margin = 5.0;
    mesh_options.graph = GraphKind{"navmesh"};
    Planner mesh_planner(set, mesh_options);
    NavMeshGraph& mesh = *mesh_planner.graph().as<NavMeshGraph>();
    replay_detections(graph, problem, {d}, 5.0, [&](const Repair& r, GraphVertex at) {
      const GraphVertex goal = graph.goal_vertex();
      const auto t1 = std::chrono::steady_clock::now();
      const SearchResult s = shortest_path(graph.graph(), at, goal, SearchAlgorithm::astar, [&](GraphVertex v) {
        return (graph.position(v) - graph.position(goal)).norm();
      });
      const double scratch_ms = ms_since(t1);
      // Rebuilding: the quadtree over the obstacles and the rock, then A* from the vehicle.
      ObstacleSet with_rock = set;
      with_rock.ellipses.push_back(rock);
      const auto t2 = std::chrono::steady_clock::now();
      const ObstacleField field2(with_rock, 5.0);
      QuadtreeGraph rebuilt(field2, q);
      (void)rebuilt.solve({r.vehicle, problem.goal}, SearchAlgorithm::astar);
      const double rebuild_ms = ms_since(t2);
      // The mesh: the rock inserted, the exact route from the same place.
      const auto t3 = std::chrono::steady_clock::now();
      mesh.insert(d.obstacles);
      const PlanResult exact = mesh.solve({r.vehicle, problem.goal}, SearchAlgorithm::astar, nullptr, {});
      const double mesh_ms = ms_since(t3);
      if (!r.found || !s.found) return;
      // A route of one straight leg is sailed whole before the vehicle can
      // act (it acts at vertices): nothing is left to repair.
      if (at == goal) {
        ++at_goal;
        return;
      }
      ++events;
      repair.push_back(r.repair_ms);
      scratch.push_back(scratch_ms);
      rebuild.push_back(rebuild_ms);
      ratio.push_back(scratch_ms / r.repair_ms);
      rebuild_ratio.push_back(rebuild_ms / r.repair_ms);
      expanded_repair.push_back(static_cast<double>(r.expanded));
      expanded_scratch.push_back(static_cast<double>(s.expanded));
      if (std::abs(r.cost - s.cost) > 1e-9 * s.cost) std::printf("MISMATCH %.9f vs %.9f\n", r.cost, s.cost);
      ObstacleSet with_rock2 = set;
      with_rock2.ellipses.push_back(rock);
      if (!exact.found || !check_route(exact.route.points, ObstacleField(with_rock2, 5.0)).safe) {
        ++mesh_unsafe;
        return;
      }
      mesh_repair.push_back(mesh_ms);
      mesh_ratio.push_back(mesh_ms / r.repair_ms);
      length_ratio.push_back(r.cost / exact.route.length());
    });
  }
  std::printf(
      "2000 m x 2000 m, 60 random ellipses, margin 5 m, quadtree with 2 m minimum cells; one 25 m rock "
      "reported on the route 40 %% along when the vehicle has sailed 30 %%. %d events (%d more left out: "
      "a straight route, sailed whole before the report). Medians; the total is all events' A* time over "
      "all their repair time.\n\n",
      events, at_goal);
  double total_repair = 0.0, total_scratch = 0.0;
  for (double v : repair) total_repair += v;
  for (double v : scratch) total_scratch += v;
  std::sort(ratio.begin(), ratio.end());
  const auto at = [&](double q) {
    return ratio.empty() ? NAN : ratio[static_cast<std::size_t>(q * (ratio.size() - 1))];
  };
  std::printf(
      "| quadtree leaves | build ms | D* Lite repair ms | A* from scratch ms | A* / repair: median (p10, min) | "
      "A* / repair: total | rebuild + A* ms | rebuild / repair | vertices processed: repair / from scratch |\n"
      "|---:|---:|---:|---:|---|---:|---:|---:|---|\n");
  std::printf("| %.0f | %.0f | %.3f | %.2f | %.1f× (%.1f×, %.1f×) | %.1f× | %.0f | %.0f× | %.0f / %.0f |\n",
              median(leaves), median(build), median(repair), median(scratch), at(0.5), at(0.1), at(0.0),
              total_scratch / total_repair, median(rebuild), median(rebuild_ratio), median(expanded_repair),
              median(expanded_scratch));
  std::printf(
      "\nThe navigation mesh on the same events (the rock inserted into a mesh of the same obstacles, then "
      "Polyanya from the vehicle; %d not found or unsafe):\n\n"
      "| navmesh insert + query ms | navmesh / D* Lite repair: median | D* Lite's cell route / the exact route, "
      "length: median (max) |\n|---:|---:|---|\n",
      mesh_unsafe);
  std::printf("| %.3f | %.1f× | %.4f (%.4f) |\n", median(mesh_repair), median(mesh_ratio), median(length_ratio),
              length_ratio.empty() ? NAN : *std::max_element(length_ratio.begin(), length_ratio.end()));
  return 0;
}
