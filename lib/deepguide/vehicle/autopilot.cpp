#include "deepguide/vehicle/autopilot.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace {
// Share of the rudder the reference's feed-forward may use (the rest is for the feedback).
constexpr double kFeedForwardShare = 0.8;
}  // namespace

HeadingGains heading_gains(const VehicleParams& p) {
  const double m = p.nomoto_time_constant_s / p.nomoto_gain_per_s;
  const double d = 1.0 / p.nomoto_gain_per_s;
  const double wn = p.autopilot.natural_frequency_rad_s;
  const double kp = m * wn * wn;
  return {kp, 2.0 * p.autopilot.damping_ratio * wn * m - d, kp * wn / 10.0};
}

std::optional<double> ground_speed_along(const Vec2& d, const Vec2& current, double speed_mps) {
  const double along = d.dot(current);
  const double cross = d.x() * current.y() - d.y() * current.x();
  const double v = speed_mps;
  if (v * v < cross * cross || v <= 0.0) return std::nullopt;
  const double s = along + std::sqrt(v * v - cross * cross);
  if (s <= 0.0) return std::nullopt;
  return s;
}

double crab_heading(double course, double speed_mps, const Vec2& current, bool& reachable) {
  const Vec2 d = unit_vector(course);
  reachable = true;
  if (const auto s = ground_speed_along(d, current, speed_mps)) return math_angle(*s * d - current);
  reachable = false;
  const double cross = d.x() * current.y() - d.y() * current.x();
  if (speed_mps * speed_mps < cross * cross || speed_mps <= 0.0) {
    // No heading cancels the cross-current: push against it as hard as possible.
    reachable = current.norm() == 0.0;
    const Vec2 perp = current - d.dot(current) * d;
    return perp.norm() > 0.0 ? math_angle(-perp) : course;
  }
  // The head current wins: facing the course loses the least ground.
  return course;
}

AutopilotOutput autopilot_step(const VehicleParams& p, AutopilotState& memory, const VehicleState& vehicle,
                               const AutopilotSetpoint& setpoint, const Vec2& current_estimate) {
  if (!std::isfinite(setpoint.course) || !std::isfinite(setpoint.speed_mps) || !std::isfinite(setpoint.depth_m) ||
      !std::isfinite(setpoint.course_rate) || !current_estimate.allFinite()) {
    // A guidance method that divides by zero must not steer the vehicle with NaN.
    throw input_error({"autopilot", "", "set-point"}, "finite course, speed, depth and current", "a NaN or infinity");
  }
  const double h = p.step_s;
  const AutopilotTuning& tune = p.autopilot;
  // The reference starts (and restarts on a switch of mode) where the vehicle
  // is: its heading in heading mode, its course over ground otherwise, so a
  // switch does not jump the heading error by the crab angle. A vehicle that
  // switches while all but stopped (station keeping) has no course to speak
  // of: the current's drift would set it, so it restarts at the heading.
  const auto where_it_is = [&] { return setpoint.heading_mode ? vehicle.heading : course_over_ground(vehicle); };
  if (!memory.started) {
    memory = AutopilotState{true, where_it_is(), vehicle.yaw_rate, 0.0, setpoint.heading_mode};
  } else if (memory.heading_mode != setpoint.heading_mode) {
    constexpr double kSteerageWay_mps = 0.25;
    const bool crawling = vehicle.speed_mps < kSteerageWay_mps;
    memory.course_ref = crawling && !setpoint.heading_mode ? vehicle.heading : where_it_is();
    memory.heading_mode = setpoint.heading_mode;
  }

  // 1. Reference model.
  const double wr = tune.reference_natural_frequency_rad_s;
  const double rmax = tune.max_reference_turn_rate;
  double acc =
      wr * wr * wrap_pi(setpoint.course - memory.course_ref) + 2.0 * wr * (setpoint.course_rate - memory.rate_ref);
  // The feed-forward (T a + r) / K must stay within kFeedForwardShare of the
  // rudder limit, leaving the rest to the feedback: that bounds a for this r.
  const double reach = kFeedForwardShare * p.nomoto_gain_per_s * p.max_rudder;
  acc = std::clamp(acc, (-reach - memory.rate_ref) / p.nomoto_time_constant_s,
                   (reach - memory.rate_ref) / p.nomoto_time_constant_s);
  const double rate = std::clamp(memory.rate_ref + h * acc, -rmax, rmax);
  acc = (rate - memory.rate_ref) / h;  // the acceleration the reference really made
  memory.rate_ref = rate;
  memory.course_ref = wrap_pi(memory.course_ref + h * rate);

  AutopilotOutput out;
  out.course_ref = memory.course_ref;
  out.rate_ref = memory.rate_ref;

  // 2. Course over ground -> heading, then the heading PID.
  AutopilotOutput& o = out;
  bool reachable = true;
  // The vehicle crabs at the speed it has; before it makes way, at the one it was told.
  const double v = vehicle.speed_mps > 0.05 ? vehicle.speed_mps : std::clamp(setpoint.speed_mps, 0.0, p.max_speed_mps);
  o.heading_setpoint =
      setpoint.heading_mode ? memory.course_ref : crab_heading(memory.course_ref, v, current_estimate, reachable);
  o.course_unreachable = !reachable;

  // In a current the heading turns at k = d psi / d chi times the course's
  // rate (the crab changes with the course). On a course that keeps turning
  // (a path's, whose rate the guidance gives) k r_r is fed to the heading
  // loop; with a set-point that jumps and holds (the reactive methods) the
  // crab's change is a transient the feedback absorbs, and feeding it
  // forward made the 500-scenario Monte Carlo worse (geometric 2 collisions
  // instead of 0, potential 2 instead of 0), so there k = 1.
  double k = 1.0;
  if (setpoint.course_rate != 0.0 && !setpoint.heading_mode && reachable && current_estimate.squaredNorm() > 0.0) {
    constexpr double kDelta = 1e-4;
    bool ok_lo = true, ok_hi = true;
    const double lo = crab_heading(memory.course_ref - kDelta, v, current_estimate, ok_lo);
    const double hi = crab_heading(memory.course_ref + kDelta, v, current_estimate, ok_hi);
    // Bounded: near an unreachable course the crab turns without limit.
    if (ok_lo && ok_hi) k = std::clamp(wrap_pi(hi - lo) / (2.0 * kDelta), 0.0, 3.0);
  }
  const double heading_rate_ref = k * memory.rate_ref;
  const HeadingGains g = heading_gains(p);
  const double m = p.nomoto_time_constant_s / p.nomoto_gain_per_s;
  const double d = 1.0 / p.nomoto_gain_per_s;
  const double e = wrap_pi(vehicle.heading - o.heading_setpoint);
  const double feed_forward = k * (m * acc + d * memory.rate_ref);
  const double unsat = feed_forward - g.kp * e - g.kd * (vehicle.yaw_rate - heading_rate_ref) - g.ki * memory.integral;
  o.command.rudder = std::clamp(unsat, -p.max_rudder, p.max_rudder);
  o.rudder_saturated = std::abs(unsat) >= p.max_rudder;
  if (!o.rudder_saturated) memory.integral += h * e;

  o.command.speed_mps = std::clamp(setpoint.speed_mps, 0.0, p.max_speed_mps);
  o.speed_limited = o.command.speed_mps != setpoint.speed_mps;
  o.command.depth_m = std::clamp(setpoint.depth_m, 0.0, p.max_depth_m);
  o.depth_limited = o.command.depth_m != setpoint.depth_m;
  return out;
}

}  // namespace deepguide
