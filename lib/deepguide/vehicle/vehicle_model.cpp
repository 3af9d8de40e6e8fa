#include "deepguide/vehicle/vehicle_model.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {
namespace {

// The integrated part of the state. Heading is integrated unwrapped within a
// step and wrapped once at the end.
struct Continuous {
  double x, y, z, psi, r, u, d;
};

// Commands after clamping to what the actuators accept.
struct Clamped {
  double d_c, u_c, z_c;
};

template <class Current>
Continuous derivative(const VehicleParams& p, const Clamped& c, const Continuous& s, double t, const Current& current) {
  Continuous ds{};
  ds.d = std::clamp((c.d_c - s.d) / p.rudder_time_constant_s, -p.max_rudder_rate, p.max_rudder_rate);
  const double r = std::clamp(s.r, -p.max_turn_rate, p.max_turn_rate);
  ds.r = (p.nomoto_gain_per_s * s.d - s.r) / p.nomoto_time_constant_s;
  // At the turning-rate limit the vehicle cannot turn faster; it may slow down.
  if ((s.r >= p.max_turn_rate && ds.r > 0.0) || (s.r <= -p.max_turn_rate && ds.r < 0.0)) ds.r = 0.0;
  ds.psi = r;
  ds.u = (c.u_c - s.u) / p.speed_time_constant_s;
  ds.z = std::clamp((c.z_c - s.z) / p.depth_time_constant_s, -p.max_vertical_speed_mps, p.max_vertical_speed_mps);
  const Vec2 w = current(Vec2(s.x, s.y), s.z, t);
  ds.x = s.u * std::cos(s.psi) + w.x();
  ds.y = s.u * std::sin(s.psi) + w.y();
  return ds;
}

Continuous axpy(const Continuous& s, double h, const Continuous& k) {
  return {s.x + h * k.x, s.y + h * k.y, s.z + h * k.z, s.psi + h * k.psi, s.r + h * k.r, s.u + h * k.u, s.d + h * k.d};
}

template <class Current>
void rk4_step(const VehicleParams& p, VehicleState& state, const VehicleCommand& command, const Current& current) {
  const Clamped c{std::clamp(command.rudder, -p.max_rudder, p.max_rudder),
                  std::clamp(command.speed_mps, 0.0, p.max_speed_mps), std::clamp(command.depth_m, 0.0, p.max_depth_m)};
  const double h = p.step_s;
  const double t = state.time_s;
  const Continuous s{state.position.x(), state.position.y(), state.depth_m, state.heading,
                     state.yaw_rate,     state.speed_mps,    state.rudder};
  const Continuous k1 = derivative(p, c, s, t, current);
  const Continuous k2 = derivative(p, c, axpy(s, 0.5 * h, k1), t + 0.5 * h, current);
  const Continuous k3 = derivative(p, c, axpy(s, 0.5 * h, k2), t + 0.5 * h, current);
  const Continuous k4 = derivative(p, c, axpy(s, h, k3), t + h, current);
  auto combine = [h](double v, double a, double b, double cc, double d) {
    return v + h / 6.0 * (a + 2.0 * b + 2.0 * cc + d);
  };
  Continuous n{};
  n.x = combine(s.x, k1.x, k2.x, k3.x, k4.x);
  n.y = combine(s.y, k1.y, k2.y, k3.y, k4.y);
  n.z = combine(s.z, k1.z, k2.z, k3.z, k4.z);
  n.psi = combine(s.psi, k1.psi, k2.psi, k3.psi, k4.psi);
  n.r = combine(s.r, k1.r, k2.r, k3.r, k4.r);
  n.u = combine(s.u, k1.u, k2.u, k3.u, k4.u);
  n.d = combine(s.d, k1.d, k2.d, k3.d, k4.d);

  // Projections: the limits hold exactly at every step, whatever RK4's stages did.
  state.time_s = t + h;
  state.position = Vec2(n.x, n.y);
  state.depth_m = std::clamp(n.z, 0.0, p.max_depth_m);
  state.heading = wrap_pi(n.psi);
  state.yaw_rate = std::clamp(n.r, -p.max_turn_rate, p.max_turn_rate);
  state.speed_mps = std::clamp(n.u, 0.0, p.max_speed_mps);
  state.rudder = std::clamp(n.d, -p.max_rudder, p.max_rudder);
  state.ground_velocity =
      state.speed_mps * unit_vector(state.heading) + current(state.position, state.depth_m, state.time_s);
}

}  // namespace

VehicleState make_vehicle_state(const Vec2& position, double depth_m, double heading, double speed_mps,
                                const Vec2& current) {
  VehicleState s;
  s.position = position;
  s.depth_m = depth_m;
  s.heading = wrap_pi(heading);
  s.speed_mps = speed_mps;
  s.ground_velocity = speed_mps * unit_vector(s.heading) + current;
  return s;
}

void step_vehicle(const VehicleParams& params, VehicleState& state, const VehicleCommand& command,
                  const Vec2& current) {
  rk4_step(params, state, command, [&current](const Vec2&, double, double) { return current; });
}

void step_vehicle(const VehicleParams& params, VehicleState& state, const VehicleCommand& command,
                  const CurrentFunction& current) {
  rk4_step(params, state, command, current);
}

double course_over_ground(const VehicleState& state) {
  // Below a millimetre per second the direction of motion is noise.
  if (state.ground_velocity.norm() < 1e-3) return state.heading;
  return math_angle(state.ground_velocity);
}

}  // namespace deepguide
