#include "deepguide/identification/going_around.hpp"

#include <cmath>
#include <numbers>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/identification/offset_path.hpp"

namespace deepguide {

void validate(const AroundParams& p) {
  auto check = [](bool ok, const char* field, const char* expected, double got) {
    require_param(ok, "going around", field, expected, got);
  };
  check(std::isfinite(p.distance_m) && p.distance_m > 0.0, "distance_m", "a distance > 0 m", p.distance_m);
  check(p.direction == 1 || p.direction == -1, "direction", "+1 or -1", p.direction);
  check(std::isfinite(p.laps) && p.laps > 0.0, "laps", "a number of laps > 0", p.laps);
  check(std::isfinite(p.lookahead_m) && p.lookahead_m > 0.0, "lookahead_m", "a distance > 0 m", p.lookahead_m);
  check(std::isfinite(p.switch_m) && p.switch_m > 0.0, "switch_m", "a distance > 0 m", p.switch_m);
  check(std::isfinite(p.speed_mps) && p.speed_mps > 0.0, "speed_mps", "a speed > 0 m/s", p.speed_mps);
}

double AroundMemory::laps_done() const { return turned / (2.0 * std::numbers::pi); }

AroundCommand around_command(const Ellipse& object, const AroundParams& params, AroundMemory& memory, const Vec2& p,
                             const Vec2& ground_velocity) {
  validate(params);
  if (!p.allFinite() || !ground_velocity.allFinite()) {
    throw InputError("going around: position and ground velocity: expected finite values");
  }
  const OffsetProjection q = project_to_offset(object, params.distance_m, p);
  AroundCommand cmd;
  cmd.cross_track_m = q.signed_m;
  cmd.path_course = math_angle(params.direction * q.tangent);
  const double e = std::abs(q.signed_m);
  if (memory.mode == AroundMode::done) {
    cmd.mode = AroundMode::done;
    cmd.course = math_angle(params.direction * q.tangent);
    return cmd;
  }
  if (memory.mode == AroundMode::steering && e <= params.switch_m) memory.mode = AroundMode::tracking;
  if (memory.mode == AroundMode::tracking && e > 2.0 * params.switch_m) memory.mode = AroundMode::steering;
  cmd.mode = memory.mode;
  cmd.speed_mps = params.speed_mps;
  if (memory.mode == AroundMode::steering) {
    cmd.course = e > 0.0 ? math_angle(q.point - p) : math_angle(params.direction * q.tangent);
    return cmd;
  }
  // Laps: the parameter's progress in the travel direction since tracking began.
  if (memory.started) memory.turned += params.direction * wrap_pi(q.t - memory.last_t);
  memory.started = true;
  memory.last_t = q.t;
  if (memory.laps_done() >= params.laps) {
    memory.mode = AroundMode::done;
    cmd.mode = AroundMode::done;
    cmd.speed_mps = 0.0;
    cmd.course = math_angle(params.direction * q.tangent);
    return cmd;
  }
  const double alpha = cmd.path_course;
  cmd.course = wrap_pi(alpha + params.direction * std::atan(q.signed_m / params.lookahead_m));
  // The rate of chi (header); rho + e is the distance to the centre of curvature, > 0 outside the object.
  const double rho = 1.0 / offset_curvature(object, params.distance_m, q.t);
  const Vec2 n(q.tangent.y(), -q.tangent.x());  // outward: right of the anticlockwise tangent
  const double l = params.lookahead_m;
  cmd.course_rate = ground_velocity.dot(q.tangent) / std::max(rho + q.signed_m, 1e-3) +
                    params.direction * l * ground_velocity.dot(n) / (l * l + q.signed_m * q.signed_m);
  return cmd;
}

}  // namespace deepguide
