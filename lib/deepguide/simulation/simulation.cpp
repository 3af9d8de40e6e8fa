#include "deepguide/simulation/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/simulation/contacts.hpp"
#include "deepguide/simulation/plant.hpp"
#include "deepguide/vehicle/sonar.hpp"

namespace deepguide {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

std::string_view to_string(SimulationEnd end) {
  switch (end) {
    case SimulationEnd::reached: return "reached";
    case SimulationEnd::stalled: return "stalled";
    case SimulationEnd::target_in_zone: return "target_in_zone";
    case SimulationEnd::no_progress: return "no_progress";
    case SimulationEnd::time_out: return "time_out";
  }
  return "?";
}

StatsOptions stats_options(const Scenario& sc) {
  return {sc.target, sc.reactive.arrival_radius_m, sc.energy, sc.reversal_dead_band};
}

void StatsAccumulator::add(const TrajectorySample& x) {
  const auto power = [this](double v) { return options_.energy.power_w(v); };
  if (!started_) {
    started_ = true;
    first_ = x;
    s_.min_clearance_m = kInf;
  } else {
    const double dt = x.time_s - last_.time_s;
    s_.path_length_m += (x.position - last_.position).norm();
    s_.energy_j += 0.5 * dt * (power(last_.speed_mps) + power(x.speed_mps));
    rate_ref_sq_dt_ += 0.5 * dt * (last_.rate_ref * last_.rate_ref + x.rate_ref * x.rate_ref);
    rate_sq_dt_ += 0.5 * dt * (last_.rate * last_.rate + x.rate * x.rate);
    if (last_.course_unreachable) s_.course_unreachable_s += dt;
  }
  s_.min_clearance_m = std::min(s_.min_clearance_m, x.clearance_m);
  s_.max_abs_rate_ref = std::max(s_.max_abs_rate_ref, std::abs(x.rate_ref));
  s_.max_abs_rate = std::max(s_.max_abs_rate, std::abs(x.rate));
  if (std::abs(x.rate_ref) > options_.reversal_dead_band) {
    const int sign = x.rate_ref > 0.0 ? 1 : -1;
    if (significant_sign_ != 0 && sign != significant_sign_) ++s_.heading_reversals;
    significant_sign_ = sign;
  }
  last_ = x;
}

SimulationStats StatsAccumulator::stats() const {
  SimulationStats s = s_;
  if (!started_) return s;
  s.time_s = last_.time_s - first_.time_s;
  s.collided = s.min_clearance_m < 0.0;
  s.reached = (last_.position - options_.target).norm() <= options_.arrival_radius_m;
  if (s.time_s > 0.0) {
    s.rms_rate_ref = std::sqrt(rate_ref_sq_dt_ / s.time_s);
    s.rms_rate = std::sqrt(rate_sq_dt_ / s.time_s);
  }
  return s;
}

SimulationStats trajectory_stats(std::span<const TrajectorySample> trajectory, const StatsOptions& options) {
  StatsAccumulator acc(options);
  for (const TrajectorySample& x : trajectory) acc.add(x);
  return acc.stats();
}

ReactiveParams sailing_params(const ReactiveParams& params, const VehicleParams& vehicle) {
  ReactiveParams p = params;
  if (!p.turn_rate_limit) {
    p.turn_rate_limit = vehicle.autopilot.max_reference_turn_rate;
    p.turn_lag_s = 2.0 * vehicle.autopilot.damping_ratio / vehicle.autopilot.natural_frequency_rad_s;
  }
  return p;
}

SimulationResult simulate(const Scenario& sc, ReactiveMethod method, const SimulationOptions& options) {
  validate(sc);
  std::optional<Sonar> sonar;
  if (sc.sonar.range_m > 0.0) sonar.emplace(sc.sonar);
  ContactMemory contacts(sc.contacts, sc.sonar);
  ReactiveMemory memory;
  const ReactiveParams params = sailing_params(sc.reactive, sc.vehicle);
  CollisionWatch watch(sc);
  std::vector<int> seen;  // contacts given to the method, a step each (guidance is asked once a step)
  const Guidance reactive = [&](double t, const VehicleState& state) {
    watch.observe(state);
    if (sonar && sonar->update(t, state.position, state.heading, sc.obstacles)) {
      contacts.update(sonar->detections(), t);
    }
    const ReactiveInput input{
        t, state.position, course_over_ground(state), state.speed_mps, sc.target, contacts.ellipses(), state.yaw_rate};
    if (options.record_trajectory) seen.push_back(static_cast<int>(input.objects.size()));
    return reactive_command(method, params, memory, input);
  };
  SimulationResult result = simulate_guided(sc, reactive, options);
  for (std::size_t k = 0; k < result.trajectory.size() && k < seen.size(); ++k) result.trajectory[k].contacts = seen[k];
  result.method = method;
  result.contacts = contacts.size();
  result.collision = watch.cause();
  return result;
}

SimulationResult simulate_guided(const Scenario& sc, const Guidance& guidance, const SimulationOptions& options) {
  validate(sc);
  // validate() leaves the target alone when there is an identify section (its
  // target defaults to the object's centre); a run to the target needs one outside.
  for (const EllipticCylinder& o : sc.obstacles) {
    if (o.footprint.contains(sc.target)) {
      throw input_error({sc.source, "", "target"},
                        "a target outside every obstacle (an identify scenario runs with deepguide identify)",
                        "inside obstacle '" + printable(o.id) + "'");
    }
  }
  const double h = sc.vehicle.step_s;
  const double max_time = std::isnan(sc.max_time_s) ? default_max_time_s(sc) : sc.max_time_s;
  const auto max_steps = static_cast<std::size_t>(std::ceil(max_time / h - 1e-9));

  const double heading0 = sc.start_heading.value_or(math_angle(sc.target - sc.start));
  Plant plant(sc, sc.start, heading0, sc.reactive.speed_mps);
  const VehicleState& state = plant.state();
  NearestClearance clearance(sc.obstacles);
  StatsAccumulator stats(stats_options(sc));

  SimulationResult result;
  if (options.record_trajectory) result.trajectory.reserve(std::min<std::size_t>(max_steps + 1, std::size_t{1} << 20));

  double progress_distance = (sc.target - sc.start).norm();
  double progress_time = 0.0;
  double stopped_since = -1.0;
  double last_course_cmd = 0.0;
  for (std::size_t k = 0;; ++k) {
    plant.at_step(k);
    const double t = plant.time_s();
    const auto t0 = std::chrono::steady_clock::now();
    const ReactiveCommand cmd = guidance(t, state);
    result.guidance_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const AutopilotOutput ap = plant.steer({cmd.course, cmd.speed_mps, sc.depth_m, cmd.course_rate});

    const TrajectorySample x{.time_s = t,
                             .position = state.position,
                             .heading = state.heading,
                             .course_cmd = cmd.course,
                             .rate_cmd = k == 0 ? 0.0 : wrap_pi(cmd.course - last_course_cmd) / h,
                             .rate_ref = ap.rate_ref,
                             .rate = state.yaw_rate,
                             .speed_mps = state.speed_mps,
                             .clearance_m = clearance.at(state.position),
                             .sector = cmd.sector,
                             .status = cmd.status,
                             .course_unreachable = ap.course_unreachable};
    last_course_cmd = cmd.course;
    stats.add(x);
    if (options.record_trajectory) result.trajectory.push_back(x);
    result.samples = k + 1;

    const double distance = (sc.target - state.position).norm();
    if (distance < progress_distance - kProgress_m) {
      progress_distance = distance;
      progress_time = t;
    }
    // Given up: speed 0 short of the target (stalled, or waiting at a zone's edge).
    const bool given_up = cmd.speed_mps == 0.0 && cmd.status != ReactiveStatus::arrived;
    stopped_since = !given_up ? -1.0 : stopped_since < 0.0 ? t : stopped_since;
    if (distance <= sc.reactive.arrival_radius_m) {
      result.end = SimulationEnd::reached;
      break;
    }
    if (given_up && cmd.status == ReactiveStatus::target_in_zone) {
      result.end = SimulationEnd::target_in_zone;  // as close as the zone allows: waiting there is all that is left
      break;
    }
    if (stopped_since >= 0.0 && t - stopped_since >= sc.stall_time_s) {
      result.end = SimulationEnd::stalled;
      break;
    }
    if (t - progress_time >= sc.no_progress_s) {
      result.end = SimulationEnd::no_progress;
      break;
    }
    if (k >= max_steps) {
      result.end = SimulationEnd::time_out;
      break;
    }
    plant.advance();
  }
  result.stats = stats.stats();
  return result;
}

}  // namespace deepguide
