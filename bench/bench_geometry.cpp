// Geometry core: the primitives every planner calls in its inner loops.
// Run: scripts/bench.sh (figures go to docs/PERFORMANCE.md).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/geometry/ellipse_tangents.hpp"
#include "deepguide/geometry/safety_zone.hpp"

using namespace deepguide;

namespace {
struct Case {
  Ellipse e;
  Vec2 p;
  Vec2 q;
};

std::vector<Case> cases(std::size_t n) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> pos(-100.0, 100.0), axis(1.0, 50.0), ang(-3.14159, 3.14159);
  std::vector<Case> out(n);
  for (auto& c : out) {
    const double a = axis(rng), b = axis(rng);
    c.e = {{pos(rng), pos(rng)}, std::max(a, b), std::min(a, b), ang(rng)};
    c.p = {pos(rng), pos(rng)};
    c.q = {pos(rng), pos(rng)};
  }
  return out;
}
}  // namespace

static void BM_PointEllipseDistance(benchmark::State& state) {
  const auto cs = cases(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cs[i++ & 1023];
    benchmark::DoNotOptimize(signed_distance(c.e, c.p));
  }
}
BENCHMARK(BM_PointEllipseDistance);

static void BM_SegmentIntersectsEllipse(benchmark::State& state) {
  const auto cs = cases(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cs[i++ & 1023];
    benchmark::DoNotOptimize(segment_intersects(c.e, c.p, c.q));
  }
}
BENCHMARK(BM_SegmentIntersectsEllipse);

static void BM_TangentPointsFromPoint(benchmark::State& state) {
  const auto cs = cases(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cs[i++ & 1023];
    benchmark::DoNotOptimize(tangent_points(c.e, c.p));
  }
}
BENCHMARK(BM_TangentPointsFromPoint);

static void BM_CommonTangents(benchmark::State& state) {
  const Ellipse e1{{0.0, 0.0}, 30.0, 8.0, 0.3};
  const Ellipse e2{{120.0, 40.0}, 20.0, 15.0, -1.1};
  for (auto _ : state) benchmark::DoNotOptimize(common_tangents(e1, e2));
}
BENCHMARK(BM_CommonTangents);

// Enclosing polygon of the zone a = 10, b = 2, d = 5 for tolerances 1, 0.1, 0.01 m (argument in mm).
static void BM_EnclosingPolygon(benchmark::State& state) {
  const SafetyZone z{{{0.0, 0.0}, 10.0, 2.0, 0.4}, 5.0};
  const ZonePolygonOptions opt{state.range(0) / 1000.0, 4096};
  std::size_t vertices = 0;
  for (auto _ : state) {
    const auto poly = enclosing_polygon(z, opt);
    vertices = poly.size();
    benchmark::DoNotOptimize(poly.data());
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_EnclosingPolygon)->Arg(1000)->Arg(100)->Arg(10);

BENCHMARK_MAIN();
