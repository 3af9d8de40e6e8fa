#pragma once
// Monte Carlo evaluation of the reactive methods: many seeded random
// scenarios, every method on each, and the statistics that decide between
// them (collisions, clearance, turning rates).
//
// Scenario k of a run with seed S draws from its own generator
// (std::mt19937_64 seeded with splitmix64(S + k)), so scenario k is the same
// whatever the number of scenarios, and runs are reproducible on one build.
// What scenario k holds (lengths in m, speeds in m/s):
//   start (0, 0); target at distance U(400, 800) in a direction U(0, 360) deg;
//   min_obstacles .. max_obstacles ellipses (uniform count), centres at
//   U(0.25, 0.85) of the way and N(0, cross_track_sigma_m) across it (the
//   density: the count over the leg and this spread), semi-major
//   U(min_size_m, max_size_m), b/a U(0.3, 1),
//   any orientation; an obstacle that would put start or target within
//   margin + 25 m of its footprint (the vehicle's turning circle at cruise
//   is about 20 m) is drawn again, so every run starts and ends in open water;
//   obstacles may overlap;
//   a uniform current of speed U(0, max_current_mps) setting in a direction U(0, 360) deg;
//   the default inexact sonar with its four error sigmas times sonar_noise
//   and its seed from the scenario's generator;
//   the scenario defaults otherwise (DeepC-like vehicle, margin 10 m).
// The defaults draw exactly what the first version of this generator drew.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace DEEPGUIDE_API deepguide {

struct MonteCarloParams {
  int scenarios = 500;
  std::uint64_t seed = 1;
  int min_obstacles = 1;  ///< 0 .. max_obstacles
  int max_obstacles = 6;
  double min_size_m = 5.0, max_size_m = 30.0;  ///< semi-major axis range, 0.1 .. 1000 m
  double cross_track_sigma_m = 25.0;
  double max_current_mps = 0.5;
  double sonar_noise = 1.0;  ///< factor on the default sonar's error sigmas, 0 = exact detections

  bool operator==(const MonteCarloParams&) const = default;
};

/// Throws InputError naming the first bad field ("monte carlo: FIELD: expected ...").
void validate(const MonteCarloParams& params);

/// Scenario `index` of a Monte Carlo run (header).
Scenario monte_carlo_scenario(const MonteCarloParams& params, int index);

/// One method on one scenario.
struct MonteCarloRun {
  int scenario = 0;
  ReactiveMethod method = ReactiveMethod::geometric;
  SimulationStats stats;
  SimulationEnd end = SimulationEnd::time_out;
  double straight_m = 0.0;                  ///< |target - start|
  std::optional<CollisionCause> collision;  ///< SimulationResult::collision
};

/// Order statistics of a sample (nearest-rank percentiles); all zero when empty.
struct Distribution {
  std::size_t count = 0;
  double min = 0.0, p5 = 0.0, median = 0.0, p95 = 0.0, max = 0.0, mean = 0.0;
};
Distribution distribution(std::vector<double> values);

struct MethodSummary {
  ReactiveMethod method = ReactiveMethod::geometric;
  int runs = 0;
  int reached = 0;
  int collisions = 0;   ///< runs in which the vehicle was ever inside a true obstacle
  int unavoidable = 0;  ///< of those, collisions no guidance could have avoided (simulation/collision_envelope.hpp)
  int stalled = 0, no_progress = 0, time_out = 0, target_in_zone = 0;  ///< how the other runs ended
  Distribution min_clearance_m;
  Distribution max_abs_rate_ref, rms_rate_ref;  ///< rad/s
  Distribution max_abs_rate, rms_rate;          ///< rad/s
  Distribution reversals;
  Distribution path_ratio;  ///< path length / straight distance, reached runs only
};

struct MonteCarloResult {
  MonteCarloParams params;
  std::vector<MonteCarloRun> runs;       ///< scenario-major: all methods of scenario 0, then 1, ...
  std::vector<MethodSummary> summaries;  ///< one per method, in the order asked
};

/// Runs every method on scenarios 0 .. params.scenarios - 1 (trajectories not
/// kept). `progress`, when set, is called after each scenario with its index.
MonteCarloResult run_monte_carlo(const MonteCarloParams& params, std::span<const ReactiveMethod> methods,
                                 void (*progress)(int done, int total) = nullptr);

}  // namespace deepguide
