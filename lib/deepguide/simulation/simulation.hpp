#pragma once
// The offline simulation of the reactive level: a vehicle (vehicle/), its
// autopilot, a forward-looking sonar (vehicle/sonar.hpp), the contacts it
// remembers (contacts.hpp) and one reactive method (reactive/), stepped
// together at the vehicle's fixed step h until the target is reached or a stop
// rule fires. Deterministic: the same scenario, method and seed give a
// bit-identical trajectory (plain double arithmetic in a fixed order; the only
// random numbers are the sonar's, from its own seeded generator).
//
// Loop, at t_k = t_{k-1} + h starting at 0 (sample k describes the state at t_k):
//   1. sonar.update (scans at its own rate) -> contacts.update with the new scan
//   2. reactive_command on every remembered contact -> course, speed, status
//   3. autopilot_step (course over ground, the true current as its estimate)
//   4. record sample k: state, commanded course and its rate
//      wrap(course_k - course_{k-1}) / h (0 at k = 0; raw, so a contact that
//      moves between scans shows as a spike), r_ref (the autopilot's reference
//      turning rate for the coming step, within its limit), r, the exact
//      clearance
//   5. stop if: reached (|p - target| <= arrival_radius_m); or the method
//      reports target_in_zone with speed 0 (it is at the nearest point the
//      zone around the target allows: stopping there is all that is left, and
//      a vehicle coasting on would only enter the zone); or the method has
//      given up, commanding speed 0 short of the target, for stall_time_s
//      (`stalled`); or the distance to the target has not shrunk by
//      kProgress_m for no_progress_s; or t_k >= max_time_s
//   6. step_vehicle (RK4) in the current
// The vehicle starts at `start` at the reactive speed through the water, on
// start_heading (default: towards the target), at depth_m, turning at 0.
// A collision does not stop the run (the vehicle is a point; the trajectory
// shows what the method did next); it is reported in the statistics.
//
// Clearance: the exact signed distance to the nearest TRUE footprint (plant.hpp).
// The vehicle, its autopilot and the current are the plant (plant.hpp).
//
// Statistics (SimulationStats), over the samples k = 0..N, dt_k = t_{k+1} - t_k:
//   time_s          t_N - t_0
//   path_length_m   sum |p_{k+1} - p_k|   (over ground)
//   energy_j        sum dt_k (P(v_k) + P(v_{k+1})) / 2,  P(v) = P_hotel + k v^3,
//                   v the speed through the water (trapezoid rule)
//   min_clearance_m min over samples (+infinity without obstacles); collided if < 0
//   max_abs_rate(_ref)  max |r_k|, max |r_ref,k|
//   rms_rate(_ref)      sqrt(sum dt_k (r_k^2 + r_{k+1}^2) / 2 / time_s): time-weighted
//                       (not per sample), 0 for a single sample
//   heading_reversals   sign changes of r_ref counting only |r_ref| > the dead band
//                       (0.5 deg/s by default): the last significant sign is kept,
//                       and a significant sample of the other sign counts one
//                       (docs/SIMULATION.md, "Statistics"). On r_ref, not r: r_ref is what the guidance asked for,
//                       free of the loop's own small oscillations.
//   course_unreachable_s  sum dt_k over samples where the autopilot could not make
//                       good the course in the current
//   reached         |p_N - target| <= arrival_radius_m

#include <cstddef>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/simulation/collision_envelope.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/vehicle/vehicle_model.hpp"

namespace DEEPGUIDE_API deepguide {

struct TrajectorySample {
  double time_s = 0.0;
  Vec2 position{0.0, 0.0};   ///< local frame (m)
  double heading = 0.0;      ///< math rad
  double course_cmd = 0.0;   ///< the reactive method's commanded course over ground (math rad)
  double rate_cmd = 0.0;     ///< rate of the commanded course, raw finite difference (rad/s, ccw positive)
  double rate_ref = 0.0;     ///< the autopilot's reference turning rate r_ref (rad/s, ccw positive)
  double rate = 0.0;         ///< actual turning rate r (rad/s, ccw positive)
  double speed_mps = 0.0;    ///< through the water
  double clearance_m = 0.0;  ///< to the nearest TRUE obstacle footprint (negative inside, +inf without obstacles)
  int sector = 0;            ///< geometric method's sector, 0 otherwise
  ReactiveStatus status = ReactiveStatus::ok;
  bool course_unreachable = false;  ///< the autopilot could not make good the course in the current
  /// Sonar contacts the reactive method was given at this step (simulate();
  /// 0 under other guidance). Not a column of the trajectory CSV.
  int contacts = 0;

  bool operator==(const TrajectorySample&) const = default;
};

struct SimulationStats {
  bool reached = false;   ///< ended within the arrival radius of the target
  bool collided = false;  ///< the vehicle's position was ever inside a true obstacle
  double time_s = 0.0;
  double path_length_m = 0.0;                         ///< over ground
  double energy_j = 0.0;                              ///< EnergyModel (vehicle/energy_model.hpp)
  double min_clearance_m = 0.0;                       ///< to the true obstacle footprints; +inf without obstacles
  double max_abs_rate_ref = 0.0, rms_rate_ref = 0.0;  ///< rad/s
  double max_abs_rate = 0.0, rms_rate = 0.0;          ///< rad/s
  int heading_reversals = 0;                          ///< sign changes of r_ref beyond the dead band (header)
  double course_unreachable_s = 0.0;
};

/// Why a run ended (the stop rules in the header, checked in this order).
enum class SimulationEnd { reached, stalled, target_in_zone, no_progress, time_out };
std::string_view to_string(SimulationEnd end);

struct SimulationResult {
  ReactiveMethod method = ReactiveMethod::geometric;
  std::vector<TrajectorySample> trajectory;  ///< empty when not recorded
  SimulationStats stats;
  SimulationEnd end = SimulationEnd::time_out;
  std::size_t samples = 0;   ///< samples taken (the trajectory's size when recorded)
  std::size_t contacts = 0;  ///< contacts remembered at the end
  double guidance_ms = 0.0;  ///< wall time spent in the guidance (sonar, contacts and method; not the plant)
  /// simulate(): the first collision, and whether any guidance could have
  /// avoided it (simulation/collision_envelope.hpp); nullopt without one.
  std::optional<CollisionCause> collision;
};

struct SimulationOptions {
  /// false: only the statistics (Monte Carlo runs); they are the same either way.
  bool record_trajectory = true;
};

/// What a reactive method is told of the vehicle it steers: unless `params`
/// sets turn_rate_limit, the autopilot's largest reference turning rate and
/// the closed loop's lag in taking it up, 2 zeta / omega_n (6.7 s for DeepC:
/// a first-order fit to its course loop within 3 m over a 90 degree turn and
/// a reversal; docs/SIMULATION.md).
ReactiveParams sailing_params(const ReactiveParams& params, const VehicleParams& vehicle);

/// Runs `scenario` with `method`. Throws InputError for an invalid scenario
/// (validate()) or a vehicle that leaves a gridded current field.
SimulationResult simulate(const Scenario& scenario, ReactiveMethod method, const SimulationOptions& options = {});

/// One guidance step: the time and the vehicle's state in, a commanded course
/// over ground, speed and status out (the reactive methods' command; other
/// guidance, such as following a planned route, leaves sector at 0).
using Guidance = std::function<ReactiveCommand(double time_s, const VehicleState& state)>;

/// The loop above with any guidance in step 2 (simulate() passes the sonar,
/// the contacts and the reactive method): the same plant, samples,
/// statistics and stop rules, so runs of different guidance compare.
SimulationResult simulate_guided(const Scenario& scenario, const Guidance& guidance,
                                 const SimulationOptions& options = {});

/// What the statistics need besides the samples.
struct StatsOptions {
  Vec2 target{0.0, 0.0};
  double arrival_radius_m = 5.0;
  EnergyModel energy;
  double reversal_dead_band = deg_to_rad(0.5);  ///< rad/s
};
StatsOptions stats_options(const Scenario& scenario);

/// The statistics, sample by sample (the simulation's own, so a trajectory
/// need not be kept for them).
class StatsAccumulator {
 public:
  explicit StatsAccumulator(const StatsOptions& options) : options_(options) {}
  void add(const TrajectorySample& sample);
  SimulationStats stats() const;

 private:
  StatsOptions options_;
  SimulationStats s_;
  bool started_ = false;
  TrajectorySample first_, last_;
  double rate_ref_sq_dt_ = 0.0, rate_sq_dt_ = 0.0;
  int significant_sign_ = 0;
};

/// The statistics of a recorded trajectory (header for the definitions).
SimulationStats trajectory_stats(std::span<const TrajectorySample> trajectory, const StatsOptions& options);

}  // namespace deepguide
