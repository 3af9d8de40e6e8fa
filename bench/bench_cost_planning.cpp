// Routes by time and energy in a current (docs/PERFORMANCE.md "Costs in a
// current"): over random fields of obstacles and currents, for each cost
// model with and without open-water vertices, the single-query time, the
// vertices A* and Dijkstra examine, and what the route saves against the
// shortest route; then the real HYCOM Gulf Stream sample when ../shared has it.
//
//   build/bench/bench_cost_planning [--scenarios N]     (from the repository root)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/world/local_frame.hpp"

using namespace deepguide;

namespace {

struct Scenario {
  ObstacleSet obstacles;
  PlanningProblem problem;
  CurrentAtTime current;
  double max_current = 0.0;
};

// 20 ellipses over 2 km x 2 km, a uniform drift up to 0.6 m/s and an eddy up to 1 m/s.
Scenario random_scenario(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scenario sc;
  for (int i = 0; i < 20; ++i) {
    EllipticCylinder c;
    c.id = "e" + std::to_string(i);
    const double a = 20.0 + 80.0 * u(rng);
    c.footprint = Ellipse{{2000.0 * u(rng), 2000.0 * u(rng)}, a, a * (0.3 + 0.7 * u(rng)), M_PI * u(rng)};
    sc.obstacles.ellipses.push_back(c);
  }
  const double heading = 2.0 * M_PI * u(rng), drift = 0.6 * u(rng);
  const Vec2 uniform = drift * Vec2(std::cos(heading), std::sin(heading));
  const Vec2 eddy(2000.0 * u(rng), 2000.0 * u(rng));
  const double swirl = (u(rng) < 0.5 ? -1.0 : 1.0) * 2.3, radius = 300.0 + 400.0 * u(rng);
  sc.current = [=](const Vec2& p, double t) -> std::optional<Vec2> {
    const Vec2 r = p - eddy;
    const double q = r.norm() / radius;
    return (uniform + swirl * std::exp(-q * q) / radius * Vec2(-r.y(), r.x())) *
           std::cos(2.0 * M_PI * t / (12.42 * 3600.0));
  };
  sc.max_current = drift + 2.3 / std::sqrt(2.0 * M_E);
  sc.problem = {{-100.0, 2000.0 * u(rng)}, {2100.0, 2000.0 * u(rng)}};
  return sc;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Variant {
  const char* name;
  CostKind kind;
  bool economical;
  bool tidal;
  double grid_m;
};

}  // namespace

int main(int argc, char** argv) {
  int scenarios = 100;
  CLI::App app{"bench_cost_planning: time and energy routes in random current fields, then HYCOM"};
  app.add_option("--scenarios", scenarios, "Random current fields")->check(CLI::PositiveNumber)->capture_default_str();
  deepguide::bench::parse_or_exit(app, argc, argv);
  std::mt19937 rng(20261123);
  std::vector<Scenario> all;
  for (int i = 0; i < scenarios; ++i) all.push_back(random_scenario(rng));

  const Variant variants[] = {
      {"length", CostKind::length, false, false, 0.0},
      {"time", CostKind::time, false, false, 0.0},
      {"energy", CostKind::energy, false, false, 0.0},
      {"energy, optimal speed", CostKind::energy, true, false, 0.0},
      {"time, tidal", CostKind::time, false, true, 0.0},
      {"time, grid 50 m", CostKind::time, false, false, 50.0},
      {"energy, grid 50 m", CostKind::energy, false, false, 50.0},
      {"time, tidal, grid 50 m", CostKind::time, false, true, 50.0},
  };
  std::printf("%d random scenarios: 20 ellipses over 2 km x 2 km, a drift up to 0.6 m/s and an eddy up to 1.0 m/s\n",
              scenarios);
  std::printf(
      "(the tidal cases scale it by cos(2 pi t / 12.42 h) from a random departure); margin 5 m, cruise 2.06 m/s\n\n");
  std::printf(
      "| cost | routes | query ms (median / max) | A* examined | Dijkstra examined | saves vs shortest (mean / max) "
      "|\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::uniform_real_distribution<double> departure(0.0, 12.42 * 3600.0);
  for (const Variant& v : variants) {
    std::vector<double> times, astar, dijkstra, saves;
    int found = 0;
    for (const Scenario& sc : all) {
      auto m = std::make_shared<CostModel>();
      m->kind = v.kind;
      m->economical = v.economical;
      m->max_current_mps = sc.max_current;
      m->current = sc.current;
      m->leg.step_m = 20.0;
      if (v.tidal) {
        m->steady = false;
        m->time_first_s = 0.0;
        m->time_last_s = 1e7;
        m->depart_s = departure(rng);
      }
      PlannerOptions options;
      options.cost = m;
      if (v.grid_m > 0.0) options.grid = waypoint_grid_for(sc.problem.start, sc.problem.goal, v.grid_m);
      const auto t0 = std::chrono::steady_clock::now();
      const SingleQueryPlan plan = plan_single_query(sc.obstacles, sc.problem, options);
      times.push_back(ms_since(t0));
      if (!plan.outcome.result.found) continue;
      ++found;
      astar.push_back(static_cast<double>(plan.outcome.result.stats.expanded));
      options.search = SearchAlgorithm::dijkstra;
      dijkstra.push_back(
          static_cast<double>(plan_single_query(sc.obstacles, sc.problem, options).outcome.result.stats.expanded));
      if (v.kind != CostKind::length) {
        PlannerOptions plain;
        const SingleQueryPlan shortest = plan_single_query(sc.obstacles, sc.problem, plain);
        const RoutePricing a = price_route(*m, plan.outcome.result.route.points);
        const RoutePricing b = price_route(*m, shortest.outcome.result.route.points);
        if (a.feasible && b.feasible) saves.push_back(100.0 * (1.0 - a.cost / b.cost));
      }
    }
    double mean_save = 0.0, max_save = 0.0;
    for (double s : saves) mean_save += s / static_cast<double>(saves.size()), max_save = std::max(max_save, s);
    char save[64] = "—";
    if (!saves.empty()) std::snprintf(save, sizeof save, "%.2f %% / %.1f %%", mean_save, max_save);
    std::printf("| %s | %d | %.2f / %.1f | %.0f | %.0f | %s |\n", v.name, found, median(times),
                *std::max_element(times.begin(), times.end()), median(astar), median(dijkstra), save);
  }

  // The real Gulf Stream (docs/PLANNING.md's example).
  const std::string hycom = "../shared/data/real/currents-hycom/hycom_glby_930_2019030712_t003_uv3z.nc";
  if (!std::filesystem::exists(hycom) || !std::filesystem::exists("data/gulf_stream_banks.geojson")) {
    std::printf("\n%s is absent (or not run from the repository root): no Gulf Stream table\n", hycom.c_str());
    return 0;
  }
  const LoadedObstacles banks = load_obstacles({"data/gulf_stream_banks.geojson"});
  const LocalFrame& frame = banks.frame;
  const PlanningProblem problem{frame.from_lonlat(-74.80, 35.10), frame.from_lonlat(-75.40, 34.60)};
  auto m = std::make_shared<CostModel>();
  m->kind = CostKind::time;
  attach_current(*m, std::make_shared<const CurrentField>(load_current_field(hycom)), frame,
                 problem.start.cwiseMin(problem.goal), problem.start.cwiseMax(problem.goal));
  const SingleQueryPlan shortest = plan_single_query(banks.obstacles, problem, PlannerOptions{});
  const double base = price_route(*m, shortest.outcome.result.route.points).time_s;
  std::printf("\nHYCOM Gulf Stream, 79 km south-west against the stream, --cost time (shortest route: %.0f s)\n\n",
              base);
  std::printf(
      "| --waypoint-grid | open-water vertices | edges | query ms | route time s | saves "
      "|\n|---|---|---|---|---|---|\n");
  for (double grid : {0.0, 4000.0, 2000.0, 1000.0}) {
    PlannerOptions options;
    options.cost = m;
    if (grid > 0.0) options.grid = waypoint_grid_for(problem.start, problem.goal, grid);
    const auto t0 = std::chrono::steady_clock::now();
    const SingleQueryPlan plan = plan_single_query(banks.obstacles, problem, options);
    const double ms = ms_since(t0);
    const double t = price_route(*m, plan.outcome.result.route.points).time_s;
    std::printf("| %s | %zu | %zu | %.1f | %.0f | %.2f %% |\n", grid > 0.0 ? std::to_string(int(grid)).c_str() : "none",
                plan.outcome.result.stats.open_water_vertices, plan.outcome.result.stats.graph_edges, ms, t,
                100.0 * (1.0 - t / base));
  }
  return 0;
}
