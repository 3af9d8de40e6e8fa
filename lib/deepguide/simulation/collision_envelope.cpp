#include "deepguide/simulation/collision_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/vehicle/sonar.hpp"

namespace deepguide {

double hard_over_clearance(const VehicleParams& vehicle, VehicleState state, const Ellipse& footprint,
                           const Vec2& current, int side) {
  const VehicleCommand hard{side * vehicle.max_rudder, state.speed_mps, state.depth_m};
  // One full circle at the limiting rate, and the time the rudder and the
  // turning rate take to build up.
  const double limit = std::max(vehicle.max_turn_rate, 1e-6);
  const double horizon = 2.0 * std::numbers::pi / limit + vehicle.nomoto_time_constant_s +
                         vehicle.max_rudder / std::max(vehicle.max_rudder_rate, 1e-6);
  double least = signed_distance(footprint, state.position);
  for (double t = 0.0; t < horizon; t += vehicle.step_s) {
    step_vehicle(vehicle, state, hard, current);
    least = std::min(least, signed_distance(footprint, state.position));
  }
  return least;
}

void CollisionWatch::observe(const VehicleState& state) {
  if (cause_) return;
  const SonarParams& sonar = scenario_.sonar;
  for (std::size_t i = 0; i < scenario_.obstacles.size(); ++i) {
    const Ellipse& e = scenario_.obstacles[i].footprint;
    const double reach = (e.centre - state.position).norm() - e.a;  // a lower bound of the distance
    if (!first_seen_[i] && sonar.range_m > 0.0 && reach <= sonar.range_m) {
      double range = 0.0;
      Vec2 nearest;
      if (in_sonar_sector(sonar, state.position, state.heading, e, range, nearest)) first_seen_[i] = state;
    }
    if (reach > 0.0 || signed_distance(e, state.position) >= 0.0) continue;
    CollisionCause c;
    c.obstacle = i;
    c.time_s = state.time_s;
    const std::string name =
        scenario_.obstacles[i].id.empty() ? "obstacle " + std::to_string(i + 1) : printable(scenario_.obstacles[i].id);
    if (!first_seen_[i]) {
      c.unavoidable = true;
      c.reason = name + " was never in the sonar's view before the vehicle met it";
    } else {
      const VehicleState& seen = *first_seen_[i];
      c.seen = true;
      c.seen_time_s = seen.time_s;
      c.seen_distance_m = signed_distance(e, seen.position);
      const Vec2 water = seen.speed_mps * Vec2(std::cos(seen.heading), std::sin(seen.heading));
      const Vec2 current = seen.ground_velocity - water;
      c.escape_clearance_m = std::max(hard_over_clearance(scenario_.vehicle, seen, e, current, +1),
                                      hard_over_clearance(scenario_.vehicle, seen, e, current, -1));
      c.unavoidable = c.escape_clearance_m <= 0.0;
      c.reason = name + " came into the sonar's view " + fixed(c.seen_distance_m, 1) + " m away at " +
                 fixed(c.seen_time_s, 1) + " s; " +
                 (c.unavoidable ? "a hard-over turn either way would still have met it: unavoidable"
                                : "a hard-over turn then would have cleared it by " + fixed(c.escape_clearance_m, 1) +
                                      " m: avoidable");
    }
    cause_ = c;
    return;
  }
}

}  // namespace deepguide
