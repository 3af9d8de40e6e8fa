// The navigation mesh on real charts: random pairs of free points on
// US4MD81M, US5FL4DQ and the Kachemak exchange set, each routed by the
// navmesh and by the reduced visibility graph over the same no-go. The
// lengths agree to 1e-9 relative (the reduced graph's routes are the full
// graph's, tests/planning/test_visibility_planner.cpp; the full graph does
// not build at chart scale), both find a route or neither does, and every
// navmesh route passes the independent checker. DEEPGUIDE_NAVMESH_PAIRS sets
// the pairs per chart (default 20; scripts/navmesh_charts.sh runs 200);
// DEEPGUIDE_ENC_SEED shifts the seeds.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/world/enc_no_go.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

int pairs_per_chart() {
  const char* env = std::getenv("DEEPGUIDE_NAVMESH_PAIRS");
  return env != nullptr ? std::max(1, std::atoi(env)) : 20;
}

unsigned shifted(unsigned seed) {
  const char* shift = std::getenv("DEEPGUIDE_ENC_SEED");
  return seed + (shift != nullptr ? static_cast<unsigned>(std::atoi(shift)) : 0u);
}

// One query each, as `plan` runs them (plan_single_query), over the cell's
// no-go at `depth` with a 5 m margin; pairs at least `min_km` apart.
void compare_on_chart(const std::string& rel, double depth, double min_km, unsigned seed) {
#ifdef DEEPGUIDE_SANITIZED
  GTEST_SKIP() << "chart-scale planning runs in the Release build";
#endif
  const std::string path = test::real_file(rel).empty() ? test::real_folder(rel) : test::real_file(rel);
  if (path.empty()) GTEST_SKIP() << "../shared/data/real/" << rel << " is absent: skipping the test on real data";
  EncNoGoOptions options;
  options.operating_depth_m = depth;
  options.vertical_clearance_m = 2.0;
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, options);
  PlannerOptions visibility;
  visibility.margin = 5.0;
  PlannerOptions navmesh = visibility;
  navmesh.graph = GraphKind{"navmesh"};
  const ObstacleField field(no_go.obstacles, visibility.margin);
  const auto [lo, hi] = footprint_box(no_go.obstacles);
  std::mt19937 rng(shifted(seed));
  std::uniform_real_distribution<double> x(lo.x(), hi.x()), y(lo.y(), hi.y());
  auto free_point = [&] {
    for (;;) {
      const Vec2 p(x(rng), y(rng));
      if (field.is_free(p)) return p;
    }
  };
  int routes = 0, none = 0;
  double longest_km = 0.0;
  for (int n = 0; n < pairs_per_chart(); ++n) {
    const Vec2 s = free_point();
    Vec2 g = free_point();
    for (int tries = 0; tries < 100 && (g - s).norm() < 1e3 * min_km; ++tries) g = free_point();
    SCOPED_TRACE(::testing::Message() << rel << " depth " << depth << " pair " << n << " from (" << s.x() << ", "
                                      << s.y() << ") to (" << g.x() << ", " << g.y() << ")");
    const SingleQueryPlan v = plan_single_query(no_go.obstacles, {s, g}, visibility);
    const SingleQueryPlan m = plan_single_query(no_go.obstacles, {s, g}, navmesh);
    ASSERT_EQ(m.outcome.result.found, v.outcome.result.found) << m.outcome.result.message;
    if (!v.outcome.result.found) {
      ++none;
      continue;
    }
    ++routes;
    ASSERT_TRUE(m.outcome.check.safe) << m.outcome.check.describe();
    const double lv = v.outcome.result.route.length(), lm = m.outcome.result.route.length();
    ASSERT_NEAR(lm, lv, 1e-9 * lv);
    longest_km = std::max(longest_km, lv / 1e3);
  }
  std::printf("%s at %g m: %d routes of the visibility graph's length (the longest %.1f km), %d pairs without one\n",
              rel.c_str(), depth, routes, longest_km, none);
}

TEST(EncNavMesh, ChesapeakeRoutesEqualTheVisibilityGraphs) {
  compare_on_chart("noaa-enc-US4MD81M/US4MD81M.000", 5.0, 5.0, 41);
}
TEST(EncNavMesh, KeyWestRoutesEqualTheVisibilityGraphs) {
  compare_on_chart("noaa-enc-US5FL4DQ/US5FL4DQ.000", 1.0, 2.0, 42);
}
TEST(EncNavMesh, KachemakRoutesEqualTheVisibilityGraphs) { compare_on_chart("noaa-enc-kachemak", 5.0, 20.0, 43); }

}  // namespace
}  // namespace deepguide
