#include "deepguide/identification/aligning.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"

namespace deepguide {

void validate(const AlignParams& p) {
  auto check = [](bool ok, const char* field, const char* expected, double got) {
    require_param(ok, "aligning", field, expected, got);
  };
  check(std::isfinite(p.standoff_m) && p.standoff_m > 0.0, "standoff_m", "a distance > 0 m", p.standoff_m);
  check(std::isfinite(p.still_mps) && p.still_mps >= 0.0, "still_mps", "a speed >= 0 m/s", p.still_mps);
  check(std::isfinite(p.speed_mps) && p.speed_mps > 0.0, "speed_mps", "a speed > 0 m/s", p.speed_mps);
  check(std::isfinite(p.max_speed_mps) && p.max_speed_mps > 0.0, "max_speed_mps", "a speed > 0 m/s", p.max_speed_mps);
  check(std::isfinite(p.position_gain_per_s) && p.position_gain_per_s > 0.0, "position_gain_per_s", "a gain > 0 1/s",
        p.position_gain_per_s);
  check(std::isfinite(p.max_approach_mps) && p.max_approach_mps > 0.0, "max_approach_mps", "a speed > 0 m/s",
        p.max_approach_mps);
  check(std::isfinite(p.lookahead_m) && p.lookahead_m > 0.0, "lookahead_m", "a distance > 0 m", p.lookahead_m);
  check(std::isfinite(p.hold_buffer_m) && p.hold_buffer_m >= 0.0, "hold_buffer_m", "a distance >= 0 m",
        p.hold_buffer_m);
  check(std::isfinite(p.approach_m) && p.approach_m > 0.0, "approach_m", "a distance > 0 m", p.approach_m);
  check(std::isfinite(p.approach_radius_m) && p.approach_radius_m > 0.0, "approach_radius_m", "a distance > 0 m",
        p.approach_radius_m);
  check(p.slack_fraction >= 0.0 && p.slack_fraction < 1.0, "slack_fraction", "a fraction >= 0 and < 1",
        p.slack_fraction);
}

AlignCommand align_command(const Ellipse& object, const AlignParams& params, AlignMemory& memory, const Vec2& p,
                           double course, const Vec2& current_mps, std::span<const Ellipse> others) {
  validate(params);
  if (!p.allFinite() || !current_mps.allFinite() || !std::isfinite(course)) {
    throw InputError("aligning: position, course and current: expected finite values");
  }
  const Ellipse safety = security_ellipse(object, params.standoff_m);
  if (!memory.direction) memory.direction = align_direction(current_mps, params.still_mps, object.centre, p);
  // A current that turns (the tide) turns the lee side with it.
  if (current_mps.norm() > params.still_mps) memory.direction = current_mps.normalized();
  memory.strongest = std::max(memory.strongest, current_mps.norm());
  const Vec2 e = *memory.direction;
  AlignCommand cmd;
  cmd.goal = lee_goal_point(safety, e) + params.hold_buffer_m * e;
  cmd.goal_error_m = (p - cmd.goal).norm();
  // No point can be held: say so instead of spinning.
  if (current_mps.norm() >= params.max_speed_mps) {
    cmd.overpowered = true;
    cmd.course = math_angle(-current_mps);
    cmd.speed_mps = params.max_speed_mps;
    return cmd;
  }
  // Positioning starts once the vehicle is in the shade and faces upstream
  // (it has reached the approach point down the axis, or turned there), and
  // ends only when it leaves the shade.
  const Vec2 approach = cmd.goal + params.approach_m * e;
  const bool in_shade = align_area(safety, e, p) == AlignArea::positioning;
  const bool upstream = std::cos(course - math_angle(-e)) > 0.0;
  AlignArea area = memory.mode;
  if (!in_shade)
    area = AlignArea::evasive;
  else if (area == AlignArea::evasive && (upstream || (p - approach).norm() < params.approach_radius_m)) {
    area = AlignArea::positioning;
  }
  if (area != memory.mode) ++memory.switches;
  memory.mode = cmd.mode = area;
  if (area == AlignArea::evasive) {
    ReactiveParams rp;
    rp.margin_m = params.standoff_m + params.hold_buffer_m;
    rp.speed_mps = params.speed_mps;
    rp.arrival_radius_m = 0.0;
    std::vector<Ellipse> objects{object};
    objects.insert(objects.end(), others.begin(), others.end());
    ReactiveInput in;
    in.position = p;
    in.course = course;
    in.speed_mps = params.speed_mps;
    in.target = approach;
    in.objects = objects;
    const ReactiveCommand r = reactive_command(ReactiveMethod::geometric, rp, memory.reactive, in);
    cmd.course = r.course;
    cmd.speed_mps = r.speed_mps;
    return cmd;
  }
  cmd.slack = memory.strongest > params.still_mps && current_mps.norm() < params.slack_fraction * memory.strongest;
  const Vec2 d = p - (cmd.slack ? approach : cmd.goal);
  if (current_mps.norm() > params.still_mps) {
    // In a current: ask for the ground velocity u = -k (p - g) (at most
    // max_approach_mps); the water velocity that makes it good is u - c. Near
    // g that is -c: the bow stays into the current however u turns, since
    // the autopilot crabs the small u out of it (autopilot.hpp).
    Vec2 u = -params.position_gain_per_s * d;
    if (u.norm() > params.max_approach_mps) u *= params.max_approach_mps / u.norm();
    const Vec2 w = u - current_mps;
    cmd.speed_mps = std::min(w.norm(), params.max_speed_mps);
    cmd.course = w.norm() > 0.0 ? math_angle(w) : math_angle(-current_mps);
    cmd.is_heading = true;
    return cmd;
  }
  // Still water: bow to the object, closing the distance along the axis
  // slowly (the speed loop lags by its time constant and there is no
  // astern), a line of sight towards the axis for the offset across it.
  const Vec2 n(-e.y(), e.x());
  const double along = d.dot(e), across = d.dot(n);
  cmd.speed_mps = std::clamp(params.position_gain_per_s * along, 0.0, params.max_speed_mps);
  cmd.course = math_angle(-e - (across / params.lookahead_m) * n);
  // A heading: at a creep the course over ground is the drift's (the tide
  // slackening), and a course set-point turned the bow with it.
  cmd.is_heading = true;
  return cmd;
}

}  // namespace deepguide
