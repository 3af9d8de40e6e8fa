#pragma once
// The vehicle model of the offline simulation: enough manoeuvring dynamics to
// show what the seed's Fig. 12 shows, a vehicle that cannot follow fast changes
// of the reference course. Parameters and their sources: vehicle_params.hpp.
//
// Equations (local frame: x east, y north, depth positive down; psi is the
// heading as a MATH angle, counter-clockwise from east):
//   rudder   d' = clamp((d_c - d) / T_d, -d'_max, d'_max),  d_c clamped to +-d_max
//   yaw      T r' + r = K d        (first-order Nomoto), |r| <= r_max
//   heading  psi' = r
//   speed    u' = (u_c - u) / T_u,  u_c clamped to [0, u_max]   (surge through water)
//   depth    z' = clamp((z_c - z) / T_z, -w_max, w_max),  z_c clamped to [0, z_max]
//   ground   p' = u (cos psi, sin psi) + c(p, z, t)   (no sway: heading and course
//                                                      differ only by the current)
// Signs: r and the rudder angle d are in the math sense too: d > 0 turns the
// vehicle counter-clockwise (to port) and r > 0 is a turn to port. A nautical
// turning rate (clockwise positive, deg/s) is -rad_to_deg(r).
//
// Integration: classic RK4 with a fixed step (params.step_s, default 0.1 s) and
// the commands held over the step. Why RK4 and not an exact discretisation of
// the linear parts: the linear parts (Nomoto, speed) could be stepped exactly,
// but the position integrates u (cos psi, sin psi) along a heading that is itself
// an exponential in time, which has no closed form; RK4 on the whole state is one
// consistent fourth-order scheme. Its error on a lag with time constant T is
// about (h/T)^4 / 120 per unit of response: 2e-9 for T = 4 s at h = 0.1 s, far
// below anything that matters, and a step costs four cheap derivative
// evaluations. The saturations are applied inside the derivative (rates) and
// as a projection after the step (rudder, turning rate, speed, depth), so the
// limits hold exactly at every step. The current is sampled at the RK4 stages
// when given as a field. Everything is plain double arithmetic in a fixed
// order: the same inputs give bit-identical states.

#include <functional>

#include "deepguide/core/api.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"

namespace DEEPGUIDE_API deepguide {

struct VehicleState {
  double time_s = 0.0;
  Vec2 position{0.0, 0.0};  ///< local frame (m)
  double depth_m = 0.0;     ///< positive down
  double heading = 0.0;     ///< math angle (rad), wrapped to [-pi, pi)
  double yaw_rate = 0.0;    ///< r (rad/s), counter-clockwise positive
  double speed_mps = 0.0;   ///< u, surge speed through the water
  double rudder = 0.0;      ///< d (rad), positive turns counter-clockwise
  /// Velocity over ground at time_s (m/s): through-water velocity + current.
  Vec2 ground_velocity{0.0, 0.0};

  bool operator==(const VehicleState&) const = default;
};

/// What the autopilot hands the vehicle: a rudder command and the speed and
/// depth set-points of the (modelled, not simulated) propulsion and depth loops.
struct VehicleCommand {
  double rudder = 0.0;  ///< commanded rudder angle (rad), math sense
  double speed_mps = 0.0;
  double depth_m = 0.0;
};

/// Sea current (east, north, m/s) at a position, depth and time. A gridded or
/// constant field from currents/current_field.hpp plugs in through a lambda over
/// CurrentSampler::sample (the simulation's clock and the field's epoch are
/// the caller's to match).
using CurrentFunction = std::function<Vec2(const Vec2& position, double depth_m, double time_s)>;

/// A state at rest in the water column position/depth, with the given heading
/// (math rad) and through-water speed, rudder and yaw rate zero; the ground
/// velocity includes `current`.
VehicleState make_vehicle_state(const Vec2& position, double depth_m, double heading, double speed_mps,
                                const Vec2& current = Vec2::Zero());

/// Advances `state` by params.step_s in a uniform current (m/s, east/north).
void step_vehicle(const VehicleParams& params, VehicleState& state, const VehicleCommand& command, const Vec2& current);

/// Same, with a current field evaluated at the RK4 stages.
void step_vehicle(const VehicleParams& params, VehicleState& state, const VehicleCommand& command,
                  const CurrentFunction& current);

/// Course over ground (math rad) of a state; the heading when it is not moving.
double course_over_ground(const VehicleState& state);

}  // namespace deepguide
