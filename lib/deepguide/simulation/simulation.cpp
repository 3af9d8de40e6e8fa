#include "deepguide/simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/vehicle/autopilot.hpp"
#include "deepguide/world/current_field.hpp"

namespace deepguide {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The exact clearance to the nearest true footprint, pruned (simulation.hpp).
class Clearance {
 public:
  explicit Clearance(const std::vector<EllipticCylinder>& obstacles) : obstacles_(obstacles) {}

  double at(const Vec2& p) {
    if (obstacles_.empty()) return kInf;
    double best = signed_distance(obstacles_[nearest_].footprint, p);
    std::size_t best_i = nearest_;
    for (std::size_t i = 0; i < obstacles_.size(); ++i) {
      if (i == nearest_) continue;
      const Ellipse& e = obstacles_[i].footprint;
      if ((p - e.center).norm() - e.a >= best) continue;
      const double d = signed_distance(e, p);
      if (d < best) {
        best = d;
        best_i = i;
      }
    }
    nearest_ = best_i;
    return best;
  }

 private:
  const std::vector<EllipticCylinder>& obstacles_;
  std::size_t nearest_ = 0;
};

// The current where the vehicle is: uniform, or the field (whose absence is an error, never a zero).
Vec2 field_current(const CurrentSampler& field, const std::string& source, double offset_s, const Vec2& p, double t) {
  const auto c = field.sample(p, offset_s + t);
  if (!c) {
    std::ostringstream s;
    s << "a current field covering the vehicle's track, got no value at x " << p.x() << ", y " << p.y() << " m, t " << t
      << " s";
    throw input_error({source, "", "current_file"}, s.str());
  }
  return *c;
}

}  // namespace

std::string_view to_string(SimulationEnd end) {
  switch (end) {
    case SimulationEnd::reached:
      return "reached";
    case SimulationEnd::stalled:
      return "stalled";
    case SimulationEnd::target_in_zone:
      return "target_in_zone";
    case SimulationEnd::no_progress:
      return "no_progress";
    case SimulationEnd::time_out:
      return "time_out";
  }
  return "?";
}

StatsOptions stats_options(const Scenario& sc) {
  return {sc.target, sc.reactive.arrival_radius_m, sc.energy, sc.reversal_dead_band};
}

void StatsAccumulator::add(const TrajectorySample& x) {
  const auto power = [this](double v) {
    return options_.energy.hotel_power_w + options_.energy.propulsion_k_w_per_mps3 * v * v * v;
  };
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

SimulationResult simulate(const Scenario& sc, ReactiveMethod method, const SimulationOptions& options) {
  validate(sc);
  const VehicleParams& vp = sc.vehicle;
  const double h = vp.step_s;
  const double max_time = std::isnan(sc.max_time_s) ? default_max_time_s(sc) : sc.max_time_s;
  const auto max_steps = static_cast<std::size_t>(std::ceil(max_time / h - 1e-9));

  // The current, as the vehicle model wants it, built once (no per-step allocation).
  const CurrentSampler* field = sc.current_field.get();
  const CurrentFunction field_fn = [&](const Vec2& p, double, double t) {
    return field_current(*field, sc.source, sc.current_time_offset_s, p, t);
  };
  auto current_at = [&](const Vec2& p, double t) { return field ? field_fn(p, sc.depth_m, t) : sc.current; };

  const double heading0 = sc.start_heading.value_or(math_angle(sc.target - sc.start));
  VehicleState state =
      make_vehicle_state(sc.start, sc.depth_m, heading0, sc.reactive.speed_mps, current_at(sc.start, 0.0));
  std::optional<Sonar> sonar;
  if (sc.sonar.range_m > 0.0) sonar.emplace(sc.sonar);
  ContactMemory contacts(sc.contacts, sc.sonar);
  AutopilotState autopilot;
  ReactiveMemory memory;
  Clearance clearance(sc.obstacles);
  StatsAccumulator stats(stats_options(sc));

  SimulationResult result;
  result.method = method;
  if (options.record_trajectory) result.trajectory.reserve(std::min<std::size_t>(max_steps + 1, std::size_t{1} << 20));

  double progress_distance = (sc.target - sc.start).norm();
  double progress_time = 0.0;
  double stopped_since = -1.0;
  double last_course_cmd = 0.0;
  for (std::size_t k = 0;; ++k) {
    // Time counted, not summed (3000 x 0.1 is 300 this way), so stop rules fire on the step they name.
    state.time_s = static_cast<double>(k) * h;
    const double t = state.time_s;
    if (sonar && sonar->update(t, state.position, state.heading, sc.obstacles)) {
      contacts.update(sonar->detections(), t);
    }
    const ReactiveInput input{t,         state.position,     course_over_ground(state), state.speed_mps,
                              sc.target, contacts.ellipses()};
    const ReactiveCommand cmd = reactive_command(method, sc.reactive, memory, input);
    const Vec2 current = current_at(state.position, t);
    const AutopilotOutput ap = autopilot_step(vp, autopilot, state, {cmd.course, cmd.speed_mps, sc.depth_m}, current);

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
    if (field) {
      step_vehicle(vp, state, ap.command, field_fn);
    } else {
      step_vehicle(vp, state, ap.command, sc.current);
    }
  }
  result.stats = stats.stats();
  result.contacts = contacts.size();
  return result;
}

}  // namespace deepguide
