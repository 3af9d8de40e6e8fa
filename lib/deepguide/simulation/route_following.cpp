#include "deepguide/simulation/route_following.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/simulation/path_following.hpp"

namespace deepguide {

namespace {

// Whether a segment is done: the vehicle is past its end along it.
bool passed(const Vec2& p, const Vec2& a, const Vec2& b) { return (p - a).dot(b - a) >= (b - a).squaredNorm(); }

// Progress is made along the route, which may lead away from the target for
// a while: the no-progress rule (distance to the target) is off, and the
// time limit, unless the scenario sets one, is 3 x the route's time + 300 s.
SimulationResult sail(const Scenario& sc, double length, const Guidance& guidance, const RouteFollowing& options) {
  Scenario run = sc;
  if (std::isnan(run.max_time_s)) {
    run.max_time_s = std::min(kMaxSimulationTime_s, 3.0 * length / sc.reactive.speed_mps + 300.0);
  }
  run.no_progress_s = kMaxSimulationTime_s;
  return simulate_guided(run, guidance, options.simulation);
}

void check_ends(const Scenario& sc, const Vec2& first, const Vec2& last) {
  constexpr double kEnds_m = 1e-6;
  if ((first - sc.start).norm() > kEnds_m || (last - sc.target).norm() > kEnds_m) {
    throw InputError(sc.source + ": route: expected a route from the start " + point_text(sc.start) +
                     " to the target " + point_text(sc.target) + ", got " + point_text(first) + " to " +
                     point_text(last));
  }
}

}  // namespace

double path_lookahead(const VehicleParams& vehicle, double speed_mps) { return 0.3 * turn_radius(vehicle, speed_mps); }

// The course reference takes up a new turning rate with a time constant of
// about 1 / (2 w_r): lead by that many seconds of way.
double path_lead(const VehicleParams& vehicle, double speed_mps) {
  return speed_mps / (2.0 * vehicle.autopilot.reference_natural_frequency_rad_s);
}

// A polyline: line of sight leg by leg, the next leg taken within the
// lookahead of this one's end (so a corner is cut, as a vehicle rounds a
// waypoint), past the last leg's end homing on the target. Kept for the
// polygon graphs' routes until they turn within the vehicle's radius.
SimulationResult follow_route(const Scenario& sc, const Route& route, const RouteFollowing& options) {
  if (route.points.size() < 2) throw InputError(sc.source + ": route: expected at least two points");
  check_ends(sc, route.points.front(), route.points.back());
  // Legs of zero length are dropped: they have no direction.
  std::vector<Vec2> legs{route.points.front()};
  double length = 0.0;
  for (const Vec2& q : route.points) {
    if ((q - legs.back()).norm() > 1e-9) {
      length += (q - legs.back()).norm();
      legs.push_back(q);
    }
  }
  if (legs.size() < 2) legs.push_back(route.points.back());
  const double lookahead =
      options.lookahead_m > 0.0 ? options.lookahead_m : turn_radius(sc.vehicle, sc.reactive.speed_mps);
  std::size_t leg = 0;  // steering along legs[leg] -> legs[leg + 1]
  const Guidance line_of_sight = [&](double, const VehicleState& state) {
    const Vec2& p = state.position;
    while (leg + 2 < legs.size() && (passed(p, legs[leg], legs[leg + 1]) || (p - legs[leg + 1]).norm() < lookahead)) {
      ++leg;
    }
    const Vec2 a = legs[leg], b = legs[leg + 1];
    ReactiveCommand cmd;
    cmd.speed_mps = sc.reactive.speed_mps;
    if (leg + 2 == legs.size() && passed(p, a, b)) {
      // Past the target's abeam on the last leg: home on it.
      const Vec2 to = b - p;
      cmd.course = to.norm() > 1e-9 ? math_angle(to) : course_over_ground(state);
      return cmd;
    }
    const Vec2 t = (b - a).normalized();
    const double cross = t.x() * (p - a).y() - t.y() * (p - a).x();  // left of the leg > 0
    cmd.course = wrap_pi(math_angle(t) - std::atan2(cross, lookahead));
    return cmd;
  };
  return sail(sc, length, line_of_sight, options);
}

SimulationResult follow_route(const Scenario& sc, const std::vector<RouteLeg>& legs, const RouteFollowing& options) {
  if (legs.empty()) throw InputError(sc.source + ": route: expected at least one leg");
  check_ends(sc, legs.front().from, legs.back().to);
  double length = 0.0;
  for (const RouteLeg& leg : legs) length += leg.length_m;
  const double lead = options.lead_m >= 0.0 ? options.lead_m : path_lead(sc.vehicle, sc.reactive.speed_mps);
  PathFollower follower{
      legs, options.lookahead_m > 0.0 ? options.lookahead_m : path_lookahead(sc.vehicle, sc.reactive.speed_mps), lead};
  const Guidance along_the_path = [&](double, const VehicleState& state) {
    ReactiveCommand cmd;
    cmd.speed_mps = sc.reactive.speed_mps;
    const PathFollower::Command c = follower.steer(state.position, state.ground_velocity);
    if (c.at_end) {
      // Past the target's abeam on the last leg: home on it.
      const Vec2 to = sc.target - state.position;
      cmd.course = to.norm() > 1e-9 ? math_angle(to) : course_over_ground(state);
      return cmd;
    }
    cmd.course = c.course;
    cmd.course_rate = c.course_rate;
    return cmd;
  };
  return sail(sc, length, along_the_path, options);
}

}  // namespace deepguide
