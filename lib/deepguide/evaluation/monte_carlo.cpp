#include "deepguide/evaluation/monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"

namespace deepguide {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Clear water the vehicle needs around start and target beyond the margin (m).
constexpr double kOpenWater_m = 25.0;

}  // namespace

void validate(const MonteCarloParams& p) {
  if (p.scenarios < 1 || p.scenarios > 1000000) {
    throw InputError("monte carlo: scenarios: expected 1 .. 1000000, got " + std::to_string(p.scenarios));
  }
  if (p.max_obstacles < 0 || p.max_obstacles > 1000) {
    throw InputError("monte carlo: max_obstacles: expected 0 .. 1000, got " + std::to_string(p.max_obstacles));
  }
  if (p.min_obstacles < 0 || p.min_obstacles > p.max_obstacles) {
    throw InputError("monte carlo: min_obstacles: expected 0 .. max_obstacles (" + std::to_string(p.max_obstacles) +
                     "), got " + std::to_string(p.min_obstacles));
  }
  if (!std::isfinite(p.min_size_m) || p.min_size_m < 0.1 || p.min_size_m > 1000.0) {
    throw InputError("monte carlo: min_size_m: expected 0.1 .. 1000 m");
  }
  if (!std::isfinite(p.max_size_m) || p.max_size_m < p.min_size_m || p.max_size_m > 1000.0) {
    throw InputError("monte carlo: max_size_m: expected min_size_m .. 1000 m");
  }
  if (!std::isfinite(p.sonar_noise) || p.sonar_noise < 0.0 || p.sonar_noise > 100.0) {
    throw InputError("monte carlo: sonar_noise: expected a factor 0 .. 100");
  }
  if (!std::isfinite(p.cross_track_sigma_m) || p.cross_track_sigma_m < 0.0 || p.cross_track_sigma_m > 1e4) {
    throw InputError("monte carlo: cross_track_sigma_m: expected 0 .. 10000 m");
  }
  if (!std::isfinite(p.max_current_mps) || p.max_current_mps < 0.0 || p.max_current_mps > 20.0) {
    throw InputError("monte carlo: max_current_mps: expected 0 .. 20 m/s");
  }
}

Scenario monte_carlo_scenario(const MonteCarloParams& params, int index) {
  validate(params);
  std::mt19937_64 rng(splitmix64(params.seed + static_cast<std::uint64_t>(index)));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  std::normal_distribution<double> normal(0.0, 1.0);

  Scenario sc;
  sc.name = "monte-carlo-" + std::to_string(index);
  sc.source = sc.name;
  const double length = uniform(400.0, 800.0);
  const double direction = uniform(0.0, kTwoPi);
  const Vec2 along(std::cos(direction), std::sin(direction));
  const Vec2 across(-along.y(), along.x());
  sc.start = Vec2::Zero();
  sc.target = length * along;

  const int span = params.max_obstacles - params.min_obstacles + 1;
  const int count = params.max_obstacles == 0 ? 0 : params.min_obstacles + static_cast<int>(unit(rng) * span) % span;
  const double keep_clear = sc.reactive.margin_m + kOpenWater_m;
  for (int i = 0; i < count; ++i) {
    EllipticCylinder e;
    e.id = "o" + std::to_string(i);
    for (int attempt = 0;; ++attempt) {
      const double a = uniform(params.min_size_m, params.max_size_m);
      const Vec2 c = uniform(0.25, 0.85) * length * along + params.cross_track_sigma_m * normal(rng) * across;
      e.footprint = Ellipse{c, a, a * uniform(0.3, 1.0), uniform(0.0, kTwoPi)};
      // The disc of radius a holds the footprint: clear of it is clear of the ellipse.
      const bool clear = (c - sc.start).norm() - a > keep_clear && (c - sc.target).norm() - a > keep_clear;
      if (clear) break;
      if (attempt > 1000) {
        throw InputError("monte carlo: max_size_m: expected obstacles that fit between start and target (scenario " +
                         std::to_string(index) + " found no place for one in 1000 draws)");
      }
    }
    sc.obstacles.push_back(e);
  }
  const double current_speed = uniform(0.0, params.max_current_mps);
  const double current_dir = uniform(0.0, kTwoPi);
  sc.current = current_speed * Vec2(std::cos(current_dir), std::sin(current_dir));
  sc.sonar.seed = rng();
  sc.sonar.position_sigma_m *= params.sonar_noise;
  sc.sonar.position_sigma_per_m *= params.sonar_noise;
  sc.sonar.size_sigma_m *= params.sonar_noise;
  sc.sonar.size_sigma_per_m *= params.sonar_noise;
  return sc;
}

Distribution distribution(std::vector<double> values) {
  Distribution d;
  d.count = values.size();
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  // Nearest rank: the smallest value with at least q of the sample at or below it.
  auto rank = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
    return values[std::clamp<std::size_t>(k, 1, values.size()) - 1];
  };
  d.min = values.front();
  d.max = values.back();
  d.p5 = rank(0.05);
  d.median = rank(0.5);
  d.p95 = rank(0.95);
  double sum = 0.0;
  for (double v : values) sum += v;
  d.mean = sum / static_cast<double>(values.size());
  return d;
}

MonteCarloResult run_monte_carlo(const MonteCarloParams& params, std::span<const ReactiveMethod> methods,
                                 void (*progress)(int done, int total)) {
  validate(params);
  MonteCarloResult result;
  result.params = params;
  result.runs.reserve(static_cast<std::size_t>(params.scenarios) * methods.size());
  SimulationOptions options;
  options.record_trajectory = false;
  for (int k = 0; k < params.scenarios; ++k) {
    const Scenario sc = monte_carlo_scenario(params, k);
    for (const ReactiveMethod& m : methods) {
      const SimulationResult r = simulate(sc, m, options);
      result.runs.push_back({k, m, r.stats, r.end, (sc.target - sc.start).norm(), r.collision});
    }
    if (progress != nullptr) progress(k + 1, params.scenarios);
  }
  for (const ReactiveMethod& m : methods) {
    MethodSummary s;
    s.method = m;
    std::vector<double> clearance, max_ref, rms_ref, max_r, rms_r, reversals, ratio;
    for (const MonteCarloRun& run : result.runs) {
      if (run.method != m) continue;
      ++s.runs;
      s.reached += run.stats.reached;
      s.collisions += run.stats.collided;
      s.unavoidable += run.collision && run.collision->unavoidable;
      switch (run.end) {
        case SimulationEnd::reached: break;
        case SimulationEnd::stalled: ++s.stalled; break;
        case SimulationEnd::target_in_zone: ++s.target_in_zone; break;
        case SimulationEnd::no_progress: ++s.no_progress; break;
        case SimulationEnd::time_out: ++s.time_out; break;
      }
      if (std::isfinite(run.stats.min_clearance_m)) clearance.push_back(run.stats.min_clearance_m);
      max_ref.push_back(run.stats.max_abs_rate_ref);
      rms_ref.push_back(run.stats.rms_rate_ref);
      max_r.push_back(run.stats.max_abs_rate);
      rms_r.push_back(run.stats.rms_rate);
      reversals.push_back(run.stats.heading_reversals);
      if (run.stats.reached) ratio.push_back(run.stats.path_length_m / run.straight_m);
    }
    s.min_clearance_m = distribution(std::move(clearance));
    s.max_abs_rate_ref = distribution(std::move(max_ref));
    s.rms_rate_ref = distribution(std::move(rms_ref));
    s.max_abs_rate = distribution(std::move(max_r));
    s.rms_rate = distribution(std::move(rms_r));
    s.reversals = distribution(std::move(reversals));
    s.path_ratio = distribution(std::move(ratio));
    result.summaries.push_back(s);
  }
  return result;
}

}  // namespace deepguide
