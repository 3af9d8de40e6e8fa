// The octree over a large volume (docs/PERFORMANCE.md "Octree in depth"):
// 2 km x 2 km x 200 m of water over a synthetic sea floor (150-210 m deep,
// hills and a ridge on a 5 m grid) with 100 random cylinders (a third
// filling the column, a third with a top depth, a third standing on the
// floor), the band 5 m .. the floor. Prints one markdown row: cells, free
// cells, build time, the decomposition's bytes, the process's peak RSS
// (getrusage, so one configuration per run) and one query across the volume.
//
//   build/bench/bench_octree [--min-cell M] [--dive DEG] [--header]

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/planning/graphs/octree/octree_graph.hpp"
#include "deepguide/planning/route_check.hpp"

using namespace deepguide;

namespace {

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: KiB
}

}  // namespace

int main(int argc, char** argv) {
  double min_cell = 1.0, dive = 45.0;
  bool header = false;
  CLI::App app{"bench_octree: one octree configuration over a 2 km synthetic sea floor, one markdown row"};
  app.add_option("--min-cell", min_cell, "The smallest cell's height (m)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--dive", dive, "The steepest dive (deg)")->check(CLI::Range(1.0, 89.0))->capture_default_str();
  app.add_flag("--header", header, "Print the table's header only");
  deepguide::bench::parse_or_exit(app, argc, argv);
  if (header) {
    std::printf(
        "| min cell (h x w) | dive | cells | free cells | build s | octree MiB | peak RSS MiB | query s | route m | "
        "expanded |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    return 0;
  }
  const double side = 2000.0, spacing = 5.0;
  const std::size_t n = static_cast<std::size_t>(side / spacing) + 1;
  std::vector<double> depth;
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = spacing * static_cast<double>(i), y = spacing * static_cast<double>(j);
      depth.push_back(195.0 + 12.0 * std::sin(x / 170.0) * std::cos(y / 230.0) -
                      45.0 * std::exp(-std::pow((x - 0.6 * y - 700.0) / 120.0, 2)));
    }
  }
  const SeaFloor floor({0.0, 0.0}, spacing, n, n, depth);
  std::mt19937 rng(2005);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ObstacleSet set;
  for (int k = 0; k < 100; ++k) {
    EllipticCylinder c;
    c.id = "c" + std::to_string(k);
    const double a = 5.0 + 25.0 * u(rng);
    c.footprint = Ellipse{{side * u(rng), side * u(rng)}, a, a * (0.4 + 0.6 * u(rng)), M_PI * u(rng)};
    if (k % 3 == 1) c.top_depth_m = 40.0 + 140.0 * u(rng);
    if (k % 3 == 2) c.height_m = 10.0 + 50.0 * u(rng);
    set.ellipses.push_back(c);
  }
  const ObstacleField field(set, 5.0);
  const WaterVolume volume(field, &floor, {2.0, 5.0, 250.0});
  OctreeOptions o;
  o.min_cell_m = min_cell;
  o.max_dive_deg = dive;
  o.area_min = {0.0, 0.0};
  o.area_max = {side, side};
  o.smooth = true;
  const OctreeGraph graph(volume, o);
  const Vec3 cell = graph.min_cell();
  // One query corner to corner, near the floor at both ends.
  Vec3 s(20.0, 20.0, 0.0), g(1980.0, 1980.0, 0.0);
  s.z() = floor.depth_at(s.head<2>()) - 10.0;
  g.z() = floor.depth_at(g.head<2>()) - 10.0;
  const auto t0 = std::chrono::steady_clock::now();
  const PlanResult r = graph.solve(s, g);
  const double query_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const bool safe = r.found && check_route_in_depth(r.route, volume, dive).safe;
  std::printf("| %.2f x %.2f m | %.0f deg | %zu | %zu | %.1f | %.0f | %.0f | %.2f | %.0f%s | %zu |\n", cell.z(),
              cell.x(), dive, graph.tree().leaves().size(), graph.vertex_count(), graph.build_ms() / 1000.0,
              static_cast<double>(graph.memory_bytes()) / (1024.0 * 1024.0), peak_rss_mib(), query_s,
              r.found ? r.route.length() : 0.0, safe ? "" : " (UNSAFE or none)", r.stats.expanded);
  return safe ? 0 : 1;
}
