// The Monte Carlo evaluation: order statistics by hand, scenarios that are
// reproducible and start and end in open water, and a small run whose
// summary adds up.
#include <gtest/gtest.h>

#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/evaluation/monte_carlo.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"

using namespace deepguide;

TEST(MonteCarlo, DistributionUsesNearestRanks) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);  // unsorted on purpose
  const Distribution d = distribution(v);
  EXPECT_EQ(d.count, 20u);
  EXPECT_EQ(d.min, 1.0);
  EXPECT_EQ(d.p5, 1.0);       // ceil(0.05 * 20) = 1st value
  EXPECT_EQ(d.median, 10.0);  // ceil(0.5 * 20) = 10th
  EXPECT_EQ(d.p95, 19.0);     // ceil(0.95 * 20) = 19th
  EXPECT_EQ(d.max, 20.0);
  EXPECT_DOUBLE_EQ(d.mean, 10.5);
  const Distribution one = distribution({7.0});
  EXPECT_EQ(one.p5, 7.0);
  EXPECT_EQ(one.p95, 7.0);
  const Distribution none = distribution({});
  EXPECT_EQ(none.count, 0u);
  EXPECT_EQ(none.max, 0.0);
}

TEST(MonteCarlo, ScenariosAreReproducibleAndStartInOpenWater) {
  const MonteCarloParams p;
  const Scenario a = monte_carlo_scenario(p, 17);
  const Scenario b = monte_carlo_scenario(p, 17);
  ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
  for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
    EXPECT_EQ(a.obstacles[i].footprint.centre, b.obstacles[i].footprint.centre);
    EXPECT_EQ(a.obstacles[i].footprint.a, b.obstacles[i].footprint.a);
  }
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.current, b.current);
  EXPECT_EQ(a.sonar.seed, b.sonar.seed);
  EXPECT_NE(monte_carlo_scenario(p, 18).target, a.target);
  MonteCarloParams other = p;
  other.seed = 2;
  EXPECT_NE(monte_carlo_scenario(other, 17).target, a.target);

  int counts[7] = {};
  for (int k = 0; k < 300; ++k) {
    const Scenario sc = monte_carlo_scenario(p, k);
    const double length = (sc.target - sc.start).norm();
    EXPECT_GE(length, 400.0);
    EXPECT_LE(length, 800.0);
    EXPECT_LE(sc.current.norm(), p.max_current_mps);
    ASSERT_GE(sc.obstacles.size(), 1u);
    ASSERT_LE(sc.obstacles.size(), 6u);
    ++counts[sc.obstacles.size()];
    for (const EllipticCylinder& e : sc.obstacles) {
      // Exact distance from start and target to the footprint: beyond margin + 25 m.
      EXPECT_GT(signed_distance(e.footprint, sc.start), sc.reactive.margin_m + 25.0) << k;
      EXPECT_GT(signed_distance(e.footprint, sc.target), sc.reactive.margin_m + 25.0) << k;
      EXPECT_GE(e.footprint.a, 5.0);
      EXPECT_LE(e.footprint.a, 30.0);
      EXPECT_GE(e.footprint.b, 0.3 * e.footprint.a - 1e-12);
    }
    EXPECT_NO_THROW(validate(sc));
  }
  for (int n = 1; n <= 6; ++n) EXPECT_GT(counts[n], 20) << n << " obstacles";  // about 50 each
}

TEST(MonteCarlo, BadParametersAreBadInput) {
  MonteCarloParams p;
  p.scenarios = 0;
  EXPECT_THROW(run_monte_carlo(p, {}), InputError);
  p = {};
  p.max_current_mps = std::nan("");
  EXPECT_THROW(monte_carlo_scenario(p, 0), InputError);
  p = {};
  p.max_obstacles = -1;
  EXPECT_THROW(monte_carlo_scenario(p, 0), InputError);
  p = {};
  p.cross_track_sigma_m = -1.0;
  EXPECT_THROW(monte_carlo_scenario(p, 0), InputError);
}

TEST(MonteCarlo, SmallRunAddsUp) {
  MonteCarloParams p;
  p.scenarios = 4;
  const ReactiveMethod methods[] = {ReactiveMethod::geometric, ReactiveMethod::dipole};
  const MonteCarloResult r = run_monte_carlo(p, methods);
  ASSERT_EQ(r.runs.size(), 8u);
  EXPECT_EQ(r.runs[0].scenario, 0);
  EXPECT_EQ(r.runs[0].method, ReactiveMethod::geometric);
  EXPECT_EQ(r.runs[1].method, ReactiveMethod::dipole);
  ASSERT_EQ(r.summaries.size(), 2u);
  for (const MethodSummary& s : r.summaries) {
    EXPECT_EQ(s.runs, 4);
    EXPECT_EQ(s.reached + s.stalled + s.target_in_zone + s.no_progress + s.time_out, s.runs);
    EXPECT_EQ(s.max_abs_rate_ref.count, 4u);
    EXPECT_LE(s.max_abs_rate_ref.median, s.max_abs_rate_ref.max);
    EXPECT_EQ(s.path_ratio.count, static_cast<std::size_t>(s.reached));
    // Never shorter than the straight line less the arrival radius (5 m of at least 400 m).
    if (s.reached > 0) {
      EXPECT_GE(s.path_ratio.min, 1.0 - 5.0 / 400.0 - 1e-9);
    }
  }
  EXPECT_LE(r.summaries[0].collisions, r.summaries[0].runs);
  // The same run again: the same numbers, bit for bit.
  const MonteCarloResult again = run_monte_carlo(p, methods);
  for (std::size_t i = 0; i < r.runs.size(); ++i) {
    EXPECT_EQ(r.runs[i].stats.path_length_m, again.runs[i].stats.path_length_m);
    EXPECT_EQ(r.runs[i].stats.max_abs_rate_ref, again.runs[i].stats.max_abs_rate_ref);
  }
}
