#pragma once
// The course, speed and depth autopilot: set-points in, a VehicleCommand out.
//
// What "course" means. The seed's guidance hands the autopilot "desired values
// for course, depth and speed", and those courses come from gradient lines and
// routes drawn over the ground: a reactive method asks for a direction of
// motion over the ground. So the set-point is the COURSE OVER GROUND chi. With a
// current the autopilot turns it into a heading set-point by the crab
// (docs/SIMULATION.md, "Autopilot", step 2): for the unit direction d of chi,
// current c and speed through water v,
//   s = d.c + sqrt(v^2 - (d x c)^2),  heading vector h = (s d - c) / v,
// using the current estimate it is given (the simulation passes the truth; a
// real vehicle has DVL bottom track minus water track). It reports, instead of
// failing silently, when it cannot: course_unreachable when v < |d x c| or
// s <= 0 (then it heads against the cross-current, or into the current, to
// lose the least ground), and the rudder, speed or depth limits it hits.
//
// Course loop, per step of params.step_s:
//  1. Reference model (Fossen's idea, second order here): the course reference
//     chi_r follows the set-point as a critically damped second-order system
//     with natural frequency w_r, its rate r_r saturated at
//     max_reference_turn_rate (0.8 K d_max by default), semi-implicit Euler:
//       a_r = w_r^2 ssa(chi_d - chi_r) + 2 w_r (r_d - r_r);  r_r += h a_r (clamped);  chi_r += h r_r
//     r_d the set-point's own rate (course_rate, 0 unless the guidance knows
//     it): without it the reference lags a course that turns at r_d by
//     2 r_d / w_r (40 degrees at 4 deg/s), which on a curved path is metres
//     of cross-track error
//     and a_r clamped so that the feed-forward (T a_r + r_r) / K stays within
//     0.8 of the rudder limit (a second-order model jumps in acceleration at a
//     set-point step; Fossen's third-order model smooths it, the clamp bounds
//     it, which is what matters for the rudder). So a step in the set-point
//     never asks for more than the vehicle can turn, and the reference turning
//     rate is reported for the statistics.
//  2. Heading PID by pole placement on Nomoto (Fossen, PythonVehicleSimulator,
//     lib/control.py, PIDpolePlacement), m = T/K, d = 1/K:
//       Kp = m w_n^2,  Kd = 2 zeta w_n m - d,  Ki = Kp w_n / 10
//       delta_c = (m a_r + d r_r) - Kp e - Kd (r - r_r) - Ki int(e),  e = ssa(psi - psi_d)
//     where the first term is the feed-forward that makes the reference turn
//     without error. With a course_rate in the set-point and a current, the
//     heading turns at k = d psi / d chi times the course (the crab changes
//     with the course): a_r and r_r are then multiplied by k in the
//     feed-forward and the damping term (autopilot.cpp says why only then).
//     The error is wrapped to [-pi, pi), so 179 -> -179 deg turns 2 deg, not
//     358. The integral stops while the rudder is saturated (anti-windup).
//     Angles are math angles (rad, ccw from east) throughout.
// Speed and depth: the set-points are clamped to [0, max] and passed to the
// vehicle's first-order speed and depth loops (vehicle_model.hpp).

#include <optional>

#include "deepguide/core/api.hpp"
#include "deepguide/vehicle/vehicle_model.hpp"

namespace DEEPGUIDE_API deepguide {

struct AutopilotSetpoint {
  double course = 0.0;  ///< course over ground, math angle (rad)
  double speed_mps = 0.0;
  double depth_m = 0.0;
  /// Feed-forward: how fast the course set-point turns (rad/s, ccw positive),
  /// e.g. a path's curvature times the ground speed; 0 for a set-point that
  /// holds still between steps.
  double course_rate = 0.0;
  /// `course` is the HEADING (where the bow points), not the course over
  /// ground: for station keeping, where the ground velocity is too small to
  /// have a direction. The crab is skipped; the reference model is the same.
  bool heading_mode = false;
};

/// The autopilot's memory between steps. Value-initialised = not started; the
/// first step starts the reference at the vehicle's course over ground.
struct AutopilotState {
  bool started = false;
  double course_ref = 0.0;    ///< chi_r, math rad
  double rate_ref = 0.0;      ///< r_r, rad/s (ccw positive)
  double integral = 0.0;      ///< int of the heading error (rad s)
  bool heading_mode = false;  ///< the reference is a heading (AutopilotSetpoint::heading_mode)

  bool operator==(const AutopilotState&) const = default;
};

struct AutopilotOutput {
  VehicleCommand command;
  double course_ref = 0.0;          ///< reference course (math rad)
  double rate_ref = 0.0;            ///< reference turning rate (rad/s, ccw positive)
  double heading_setpoint = 0.0;    ///< heading that makes good course_ref in the current (math rad)
  bool rudder_saturated = false;    ///< |delta_c| reached max_rudder
  bool course_unreachable = false;  ///< the current is too strong for this course at this speed
  bool speed_limited = false;       ///< the speed set-point was outside [0, max_speed]
  bool depth_limited = false;       ///< the depth set-point was outside [0, max_depth]
};

/// The PID gains of the heading loop, from the vehicle's Nomoto K, T and the tuning.
struct HeadingGains {
  double kp, kd, ki;
};
HeadingGains heading_gains(const VehicleParams& params);

/// Ground speed along the unit direction `d` at `speed_mps` through the water
/// in `current` (the crab, above): s = d.c + sqrt(v^2 - (d x c)^2); nullopt when no
/// heading holds the line (v < |d x c|) or the current wins (s <= 0).
std::optional<double> ground_speed_along(const Vec2& d, const Vec2& current, double speed_mps);

/// Heading (math rad) that makes good the course `course` (math rad) at speed
/// through water `speed_mps` in `current`; sets `reachable` false and returns the
/// least-bad heading when no heading does.
double crab_heading(double course, double speed_mps, const Vec2& current, bool& reachable);

/// One autopilot step of params.step_s; call it once per vehicle step.
AutopilotOutput autopilot_step(const VehicleParams& params, AutopilotState& memory, const VehicleState& vehicle,
                               const AutopilotSetpoint& setpoint, const Vec2& current_estimate);

}  // namespace deepguide
