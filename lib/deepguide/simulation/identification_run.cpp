#include "deepguide/simulation/identification_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/simulation/plant.hpp"

namespace deepguide {
namespace {

// On the path means going along it too: course over ground within this of the path's.
const double kAlongPath = deg_to_rad(20.0);

// Running RMS and max |x|.
class ErrorAccumulator {
 public:
  void add(double x) {
    sum_sq_ += x * x;
    ++n_;
    s_.max_abs = std::max(s_.max_abs, std::abs(x));
  }
  ErrorStats stats() const {
    ErrorStats s = s_;
    s.rms = n_ ? std::sqrt(sum_sq_ / static_cast<double>(n_)) : 0.0;
    return s;
  }

 private:
  ErrorStats s_;
  double sum_sq_ = 0.0;
  std::size_t n_ = 0;
};

// What one unit's step gives the loop.
struct UnitStep {
  double course = 0.0, speed_mps = 0.0;
  double course_rate = 0.0;  // feed-forward for the autopilot (rad/s)
  bool is_heading = false;   // `course` is a heading set-point
  bool on_track = true;      // going around: the course over ground is along the path (header)
  bool overpowered = false;  // aligning: the unit says the current beats it
  IdentifyPhase phase = IdentifyPhase::evasive;
  double cross_track_m = 0.0, goal_error_m = 0.0, laps = 0.0;
  double requested_m = 0.0;  // the distance to the object's footprint asked for
  Vec2 goal{0.0, 0.0};
};

// The perimeter of the offset path (Ramanujan's ellipse perimeter + 2 pi D).
double around_length(const Ellipse& e, double d) {
  const double a = e.a, b = e.b, h = (a - b) * (a - b) / ((a + b) * (a + b));
  return std::numbers::pi * (a + b) * (1.0 + 3.0 * h / (10.0 + std::sqrt(4.0 - 3.0 * h))) + 2.0 * std::numbers::pi * d;
}

// Aligning's held point inside a true obstacle (the object's safety ellipse
// keeps it off the object; nothing keeps it off the others): said with a
// failure, as its cause.
std::string held_point_note(const std::vector<EllipticCylinder>& obstacles, const Vec2& g) {
  for (const EllipticCylinder& o : obstacles) {
    const double d = signed_distance(o.footprint, g);
    if (d < 0.0) {
      return printf_text("; the held point (x %.1f, y %.1f m) lies %.2f m inside obstacle '%s'", g.x(), g.y(), -d,
                         printable(o.id).c_str());
    }
  }
  return {};
}

std::string where(double t, const Vec2& p) {
  char text[96];
  std::snprintf(text, sizeof text, "at t %.1f s, x %.1f, y %.1f m", t, p.x(), p.y());
  return text;
}

}  // namespace

std::string_view to_string(IdentifyPhase phase) {
  switch (phase) {
    case IdentifyPhase::evasive: return "evasive";
    case IdentifyPhase::positioning: return "positioning";
    case IdentifyPhase::steering: return "steering";
    case IdentifyPhase::tracking: return "tracking";
    case IdentifyPhase::done: return "done";
    case IdentifyPhase::overpowered: return "overpowered";
  }
  return "?";
}

std::string_view to_string(IdentifyEnd end) {
  switch (end) {
    case IdentifyEnd::held: return "held";
    case IdentifyEnd::laps_done: return "laps_done";
    case IdentifyEnd::overpowered: return "overpowered";
    case IdentifyEnd::collided: return "collided";
    case IdentifyEnd::time_out: return "time_out";
  }
  return "?";
}

double identify_max_time_s(const Scenario& sc) {
  if (!std::isnan(sc.max_time_s)) return sc.max_time_s;
  const IdentifySpec& id = *sc.identify;
  const double approach = (id.object.centre - sc.start).norm();
  double t = 0.0;
  if (id.mode == IdentifyMode::align) {
    t = 3.0 * approach / id.align.speed_mps + 300.0 + id.hold_time_s;
  } else {
    t = 3.0 * (approach + id.around.laps * around_length(id.object, id.around.distance_m)) / id.around.speed_mps +
        300.0;
  }
  return std::min(t, kMaxSimulationTime_s);
}

namespace {

// One step of the identification's unit (aligning, or going around): its
// command and what it says about the errors.
UnitStep unit_step(const IdentifySpec& id, const VehicleState& state, const Vec2& current,
                   const std::vector<Ellipse>& others, AlignMemory& align_memory, AroundMemory& around_memory) {
  const Ellipse& object = id.object;
  const bool aligning = id.mode == IdentifyMode::align;
  UnitStep u;
  const Vec2 p = state.position;
  if (aligning) {
    const AlignCommand c = align_command(object, id.align, align_memory, p, course_over_ground(state), current, others);
    const Vec2 e = *align_memory.direction;
    u = {.course = c.course,
         .speed_mps = c.speed_mps,
         .is_heading = c.is_heading,
         .overpowered = c.overpowered,
         .phase = c.mode == AlignArea::positioning ? IdentifyPhase::positioning : IdentifyPhase::evasive,
         .cross_track_m = (p - c.goal).dot(Vec2(-e.y(), e.x())),
         .goal_error_m = c.goal_error_m,
         .requested_m = signed_distance(object, c.goal),
         .goal = c.goal};
    return u;
  }
  const Vec2 ground = state.speed_mps * Vec2(std::cos(state.heading), std::sin(state.heading)) + current;
  const AroundCommand c = around_command(object, id.around, around_memory, p, ground);
  const IdentifyPhase phase = c.mode == AroundMode::steering   ? IdentifyPhase::steering
                              : c.mode == AroundMode::tracking ? IdentifyPhase::tracking
                                                               : IdentifyPhase::done;
  const bool along = std::abs(wrap_pi(math_angle(ground) - c.path_course)) <= kAlongPath;
  u = {.course = c.course,
       .speed_mps = c.speed_mps,
       .course_rate = c.course_rate,
       .on_track = along,
       .phase = phase,
       .cross_track_m = c.cross_track_m,
       .goal_error_m = std::abs(c.cross_track_m),
       .laps = around_memory.laps_done(),
       .requested_m = id.around.distance_m};
  return u;
}

}  // namespace

IdentifyResult simulate_identification(const Scenario& sc, const SimulationOptions& options) {
  validate(sc);
  if (!sc.identify) {
    throw input_error({sc.source, "", "identify"},
                      "an identify section naming the object (data/scenarios/align_in_current.yaml)");
  }
  const IdentifySpec& id = *sc.identify;
  const Ellipse& object = id.object;
  const bool aligning = id.mode == IdentifyMode::align;
  const double h = sc.vehicle.step_s;
  const auto max_steps = static_cast<std::size_t>(std::ceil(identify_max_time_s(sc) / h - 1e-9));

  const double speed0 = aligning ? id.align.speed_mps : id.around.speed_mps;
  const double heading0 = sc.start_heading.value_or(math_angle(object.centre - sc.start));
  Plant plant(sc, sc.start, heading0, speed0);
  const VehicleState& state = plant.state();
  NearestClearance clearance(sc.obstacles);
  StatsOptions so = stats_options(sc);
  so.arrival_radius_m = 5.0;
  StatsAccumulator vehicle_stats(so);
  AlignMemory align_memory;
  std::vector<Ellipse> others;  // every true obstacle but the object: the evasive mode keeps clear of them
  for (const EllipticCylinder& o : sc.obstacles)
    if (o.id != id.object_id) others.push_back(o.footprint);
  AroundMemory around_memory;

  IdentifyResult result;
  result.mode = id.mode;
  if (options.record_trajectory) result.trajectory.reserve(std::min<std::size_t>(max_steps + 1, std::size_t{1} << 20));
  ErrorAccumulator station, cross, distance;
  const double top_speed = aligning ? id.align.max_speed_mps : sc.vehicle.max_speed_mps;
  bool holding = false;     // in position now (header): the hold runs
  double hold_start = 0.0;  // when the current hold began
  double last_course_cmd = 0.0;
  IdentifyPhase last_phase = IdentifyPhase::evasive;
  for (std::size_t k = 0;; ++k) {
    plant.at_step(k);
    const double t = plant.time_s();
    const Vec2 current = plant.current();
    // The unit runs even when the current wins, so that aligning's held point is still known.
    UnitStep u = unit_step(id, state, current, others, align_memory, around_memory);
    const bool overpowered = current.norm() >= top_speed || u.overpowered;
    if (overpowered) {
      u.phase = IdentifyPhase::overpowered;
      u.course = math_angle(-current);
      u.speed_mps = top_speed;
      u.course_rate = 0.0;
      u.is_heading = false;
    }
    const AutopilotOutput ap = plant.steer({u.course, u.speed_mps, sc.depth_m, u.course_rate, u.is_heading});
    const double object_distance = signed_distance(object, state.position);
    const IdentifySample x{.vehicle = {.time_s = t,
                                       .position = state.position,
                                       .heading = state.heading,
                                       .course_cmd = u.course,
                                       .rate_cmd = k == 0 ? 0.0 : wrap_pi(u.course - last_course_cmd) / h,
                                       .rate_ref = ap.rate_ref,
                                       .rate = state.yaw_rate,
                                       .speed_mps = state.speed_mps,
                                       .clearance_m = clearance.at(state.position),
                                       .course_unreachable = ap.course_unreachable},
                           .phase = u.phase,
                           .object_distance_m = object_distance,
                           .distance_error_m = object_distance - u.requested_m,
                           .cross_track_m = u.cross_track_m,
                           .goal_error_m = u.goal_error_m,
                           .laps = u.laps};
    last_course_cmd = u.course;
    if (k == 0) result.start_phase = u.phase;
    if (k > 0 && u.phase != last_phase) result.switches.push_back({t, state.position, last_phase, u.phase});
    last_phase = u.phase;
    vehicle_stats.add(x.vehicle);
    if (options.record_trajectory) result.trajectory.push_back(x);
    result.samples = k + 1;
    result.goal = u.goal;

    IdentifyStats& s = result.stats;
    const bool holding_phase = aligning ? u.phase == IdentifyPhase::positioning : u.phase == IdentifyPhase::tracking;
    if (holding && !holding_phase) {  // pushed out of the shade, or off the path: the hold starts again
      holding = false;
      ++s.position_lost;
    }
    if (!holding && holding_phase && u.goal_error_m <= id.position_tolerance_m && u.on_track) {
      holding = true;
      hold_start = t;
      if (!s.in_position) {
        s.in_position = true;
        s.time_to_position_s = t;
        s.requested_distance_m = u.requested_m;
      }
    }
    if (s.in_position && !overpowered) {
      if (aligning) station.add(u.goal_error_m);
      cross.add(u.cross_track_m);
      distance.add(x.distance_error_m);
    }
    if (overpowered) {
      result.end = IdentifyEnd::overpowered;
      char text[160];
      std::snprintf(text, sizeof text,
                    "the current (%.2f m/s) is at least the vehicle's top speed (%.2f m/s) %s: it cannot %s",
                    current.norm(), top_speed, where(t, state.position).c_str(),
                    aligning ? "hold a position" : "keep to the path");
      result.failure = text;
      break;
    }
    if (x.vehicle.clearance_m < 0.0) {
      result.end = IdentifyEnd::collided;
      const EllipticCylinder& hit = sc.obstacles[clearance.nearest()];
      result.failure = printf_text("the vehicle is inside obstacle '%s' (%.3f m deep) %s", printable(hit.id).c_str(),
                                   -x.vehicle.clearance_m, where(t, state.position).c_str()) +
                       (aligning ? held_point_note(sc.obstacles, u.goal) : std::string());
      break;
    }
    if (aligning && holding && t - hold_start >= id.hold_time_s - 1e-9) {
      result.end = IdentifyEnd::held;
      break;
    }
    if (!aligning && u.phase == IdentifyPhase::done) {
      result.end = IdentifyEnd::laps_done;
      break;
    }
    if (k >= max_steps) {
      result.end = IdentifyEnd::time_out;
      result.failure = std::string(aligning ? "not held for hold_time_s" : "laps not completed") +
                       " by the time limit " + where(t, state.position) +
                       (aligning ? held_point_note(sc.obstacles, u.goal) : std::string());
      break;
    }
    plant.advance();
  }
  IdentifyStats& s = result.stats;
  s.vehicle = vehicle_stats.stats();
  s.vehicle.reached = result.end == IdentifyEnd::held || result.end == IdentifyEnd::laps_done;
  if (s.in_position) s.hold_s = s.vehicle.time_s - s.time_to_position_s;
  s.station_keeping_m = station.stats();
  s.cross_track_m = cross.stats();
  s.distance_error_m = distance.stats();
  s.laps = aligning ? 0.0 : around_memory.laps_done();
  s.mode_switches = result.switches.size();
  return result;
}

Scenario read_identification_scenario(const std::string& path, const std::string& mode, const std::string& what_mode) {
  std::optional<IdentifyMode> chosen;
  if (!mode.empty()) {
    chosen = parse_identify_mode(mode);
    if (!chosen) throw InputError(what_mode + ": expected align or around, got '" + printable(mode) + "'");
  }
  Scenario scenario = read_scenario_file(path);
  if (!scenario.identify) {
    throw InputError(path +
                     ": field 'identify': expected an identify section naming the object "
                     "(see data/scenarios/align_in_current.yaml)");
  }
  if (chosen) {
    scenario.identify->mode = *chosen;
    validate(scenario);  // the other mode has its own rules (a path the vehicle can turn on)
  }
  return scenario;
}

}  // namespace deepguide
