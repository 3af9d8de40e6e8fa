// Queries on a prebuilt navigation mesh at chart scale, against the reduced
// visibility graph on the same queries in the same run: the no-go of a chart
// (S-57 cells or an exchange set's folder) at a depth, one Planner per graph
// over every obstacle, then N random pairs of free points (seeded), each
// answered by both. Prints markdown: build time, peak RSS, and the whole
// Planner::solve's median, p90, p99 and max, with the ratios.
//
// Then repairs (--repairs N): on the route of a random pair, a rock 25 m
// across is reported 40 % along when the vehicle has sailed 30 %; it goes
// into the same mesh (NavMeshGraph::insert, detections piling up as on a
// voyage) and the route is found again from the vehicle, every one checked
// against the chart and every rock so far. The reduced visibility graph
// answers the same changed query as `plan` would (plan_single_query over
// the chart and the rocks) on the first of them, and must give the same length.
//   bench_navmesh CHART [--depth M] [--queries N] [--seed S] [--no-visibility] [--repairs N]
#include <sys/resource.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/single_query.hpp"

using namespace deepguide;
using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

struct Run {
  std::string graph;
  double build_ms = 0.0, rss_mb = 0.0;
  std::vector<double> solve_ms, search_ms, lengths;
  std::vector<double> expanded;
  int found = 0;
};

Run run(const ObstacleSet& obstacles, const GraphKind& kind, const std::vector<std::pair<Vec2, Vec2>>& queries) {
  Run r;
  r.graph = kind.name;
  PlannerOptions options;
  options.margin = 5.0;
  options.graph = kind;
  const auto t0 = Clock::now();
  Planner planner(obstacles, options);
  r.build_ms = ms_since(t0);
  for (const auto& [s, g] : queries) {
    const auto q0 = Clock::now();
    const PlanOutcome out = planner.solve({s, g});
    r.solve_ms.push_back(ms_since(q0));
    r.lengths.push_back(out.result.found ? out.result.route.length() : -1.0);
    r.search_ms.push_back(out.result.stats.query_ms);
    r.expanded.push_back(static_cast<double>(out.result.stats.expanded));
    r.found += out.result.found && out.check.safe ? 1 : 0;
    if (out.result.found && !out.check.safe) {
      std::printf("unsafe: %s from (%.17g, %.17g) to (%.17g, %.17g): %s\n", kind.name.c_str(), s.x(), s.y(), g.x(),
                  g.y(), out.check.describe().c_str());
    }
  }
  r.rss_mb = peak_rss_mb();
  return r;
}

// Detections on the routes of `pairs`, inserted into one navmesh Planner's
// mesh one after the other, each followed by the query from the vehicle.
void repairs(const ObstacleSet& obstacles, const ObstacleField& field, const std::vector<std::pair<Vec2, Vec2>>& pairs,
             int count, int compared) {
  PlannerOptions options;
  options.margin = 5.0;
  options.graph = GraphKind{"navmesh"};
  Planner planner(obstacles, options);
  NavMeshGraph& mesh = *planner.graph().as<NavMeshGraph>();
  ObstacleSet rocks;
  std::vector<double> insert_ms, query_ms, total_ms, removed, single_ms;
  int events = 0, unsafe = 0, differ = 0, rebuilt = 0;
  for (const auto& [s, g] : pairs) {
    if (events == count) break;
    const PlanResult first = mesh.solve({s, g}, SearchAlgorithm::astar, nullptr, {});
    if (!first.found) continue;
    const double length = first.route.length();
    if (length < 500.0) continue;  // the rock's zone would reach the vehicle
    const Vec2 vehicle = first.route.point_at(0.3 * length);
    ObstacleSet rock;
    EllipticCylinder c;
    c.id = "rock" + std::to_string(events);
    c.footprint = Ellipse{first.route.point_at(0.4 * length), 12.5, 12.5, 0.0};
    rock.ellipses.push_back(c);
    rocks.ellipses.push_back(c);
    const ObstacleField rocks_field(rocks, 5.0);
    if (!rocks_field.is_free(vehicle) || !rocks_field.is_free(g)) continue;
    const std::size_t faces_before = mesh.mesh().faces().size();
    const auto t0 = Clock::now();
    const NavMesh::Repair r = mesh.insert(rock);
    const double inserted = ms_since(t0);
    const auto t1 = Clock::now();
    const PlanResult again = mesh.solve({vehicle, g}, SearchAlgorithm::astar, nullptr, {});
    const double queried = ms_since(t1);
    ++events;
    rebuilt += r.removed == faces_before ? 1 : 0;
    insert_ms.push_back(inserted);
    query_ms.push_back(queried);
    total_ms.push_back(inserted + queried);
    removed.push_back(static_cast<double>(r.removed));
    if (!again.found || !check_route(again.route.points, field).safe ||
        !check_route(again.route.points, rocks_field).safe) {
      ++unsafe;
      std::printf("repair %d: %s\n", events, again.found ? "unsafe" : again.message.c_str());
    }
    if (events <= compared) {
      ObstacleSet all = obstacles;
      all.ellipses.insert(all.ellipses.end(), rocks.ellipses.begin(), rocks.ellipses.end());
      PlannerOptions reduced;
      reduced.margin = 5.0;
      const auto t2 = Clock::now();
      const SingleQueryPlan one = plan_single_query(all, {vehicle, g}, reduced);
      single_ms.push_back(ms_since(t2));
      const double a = again.found ? again.route.length() : -1.0;
      const double b = one.outcome.result.found ? one.outcome.result.route.length() : -1.0;
      if (std::abs(a - b) > 1e-9 * std::max(b, 1.0)) {
        ++differ;
        std::printf("repair %d differs: navmesh %.6f m, visibility %.6f m\n", events, a, b);
      }
    }
  }
  std::printf(
      "\n## Repairs: %d detections inserted into the mesh one after another (%d widened the area: a rebuild), "
      "each followed by the query from the vehicle; %d unsafe or not found\n\n",
      events, rebuilt, unsafe);
  std::printf("| | median | p90 | p99 | max |\n|---|---:|---:|---:|---:|\n");
  const auto row = [](const char* what, const std::vector<double>& v, const char* format) {
    std::printf("| %s | ", what);
    for (const double q : {0.5, 0.9, 0.99, 1.0}) std::printf(format, quantile(v, q));
    std::printf("\n");
  };
  row("insert ms", insert_ms, "%.3f | ");
  row("query from the vehicle ms", query_ms, "%.3f | ");
  row("insert + query ms", total_ms, "%.3f | ");
  row("faces re-triangulated", removed, "%.0f | ");
  if (!single_ms.empty()) {
    row("reduced visibility, `plan`'s single query with the rocks, ms", single_ms, "%.1f | ");
    std::printf(
        "\nOn the first %zu: navmesh insert + query / reduced visibility single query, medians: %.4f; equal "
        "lengths (1e-9) on %zu of %zu\n",
        single_ms.size(),
        quantile(
            std::vector<double>(total_ms.begin(), total_ms.begin() + static_cast<std::ptrdiff_t>(single_ms.size())),
            0.5) /
            quantile(single_ms, 0.5),
        single_ms.size() - static_cast<std::size_t>(differ), single_ms.size());
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string chart;
  double depth = 5.0;
  int queries = 1000;
  unsigned seed = 1;
  bool visibility = true;
  int repair_count = 100, compared = 20;
  CLI::App app{"bench_navmesh: queries on a prebuilt navigation mesh of a chart, against the visibility graph"};
  app.add_option("CHART", chart, "S-57 cell, folder of cells or prepared chart")->required();
  app.add_option("--depth", depth, "Operating depth (m); the vertical clearance is 2 m")->capture_default_str();
  app.add_option("--queries", queries, "Random pairs of free points")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--seed", seed, "Seed of the pairs")->capture_default_str();
  app.add_flag("!--no-visibility", visibility, "Skip the visibility graph (its build takes long on large sets)");
  app.add_option("--repairs", repair_count, "Detections inserted into the mesh (0: none)")->capture_default_str();
  app.add_option("--repairs-compared", compared, "Of them, how many the reduced visibility graph answers too")
      ->capture_default_str();
  deepguide::bench::parse_or_exit(app, argc, argv);

  EncNoGoOptions options;
  options.operating_depth_m = depth;
  options.vertical_clearance_m = 2.0;
  const auto t0 = Clock::now();
  const EncNoGo no_go = enc_no_go({chart}, std::nullopt, options);
  const double read_ms = ms_since(t0);
  const ObstacleField field(no_go.obstacles, 5.0);
  const auto [lo, hi] = footprint_box(no_go.obstacles);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(lo.x(), hi.x()), y(lo.y(), hi.y());
  auto free_point = [&] {
    for (;;) {
      const Vec2 p(x(rng), y(rng));
      if (field.is_free(p)) return p;
    }
  };
  std::vector<std::pair<Vec2, Vec2>> pairs;
  for (int k = 0; k < queries; ++k) pairs.emplace_back(free_point(), free_point());

  std::printf("# bench_navmesh: %s at %g m\n\n", chart.c_str(), depth);
  std::printf(
      "%zu obstacles, read and made no-go in %.0f ms; %d random pairs of free points (seed %u), margin 5 m. "
      "`solve` is the whole Planner::solve (route check included), `search` the graph's own query, ms.\n\n",
      no_go.obstacles.size(), read_ms, queries, seed);
  std::vector<Run> runs{run(no_go.obstacles, GraphKind{"navmesh"}, pairs)};
  if (visibility) runs.push_back(run(no_go.obstacles, GraphKind::visibility, pairs));
  std::printf(
      "| graph | build ms | peak RSS MB | found and safe | solve median | p90 | p99 | max | search median | search p99 "
      "| expanded p99 |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Run& r : runs) {
    std::printf("| %s | %.1f | %.0f | %d/%d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.0f |\n", r.graph.c_str(),
                r.build_ms, r.rss_mb, r.found, queries, quantile(r.solve_ms, 0.5), quantile(r.solve_ms, 0.9),
                quantile(r.solve_ms, 0.99), quantile(r.solve_ms, 1.0), quantile(r.search_ms, 0.5),
                quantile(r.search_ms, 0.99), quantile(r.expanded, 0.99));
  }
  if (runs.size() == 2) {
    int same = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const double a = runs[0].lengths[k], b = runs[1].lengths[k];
      const bool equal = (a < 0 && b < 0) || (a >= 0 && b >= 0 && std::abs(a - b) <= 1e-9 * b);
      same += equal ? 1 : 0;
      if (!equal) {
        std::printf("differ: from (%.17g, %.17g) to (%.17g, %.17g): navmesh %.6f m, visibility %.6f m (-1: none)\n",
                    pairs[k].first.x(), pairs[k].first.y(), pairs[k].second.x(), pairs[k].second.y(), a, b);
      }
    }
    std::printf("\nnavmesh / visibility: build %.3f, solve median %.3f, p99 %.3f; equal lengths (1e-9) on %d of %d\n",
                runs[0].build_ms / runs[1].build_ms, quantile(runs[0].solve_ms, 0.5) / quantile(runs[1].solve_ms, 0.5),
                quantile(runs[0].solve_ms, 0.99) / quantile(runs[1].solve_ms, 0.99), same, queries);
  }
  if (repair_count > 0) repairs(no_go.obstacles, field, pairs, repair_count, compared);
  return 0;
}
