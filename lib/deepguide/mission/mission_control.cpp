#include "deepguide/mission/mission_control.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/evasion_planner.hpp"
#include "deepguide/mission/goal_point.hpp"
#include "deepguide/mission/plan_splice.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "deepguide/world/water_volume.hpp"

namespace deepguide {
namespace {

constexpr double kStep = 2.0;  // m: pieces of the danger scan, steps of the goal-point search
constexpr int kAttempts = 4;

double deepest_between(const TrackDanger& danger, const MissionPlan& plan, double from_m, double to_m) {
  double d = std::max(position_at(plan, from_m).depth_m, position_at(plan, to_m).depth_m);
  for (const TrackPoint& p : danger.points) {
    if (p.along_m >= from_m && p.along_m <= to_m) d = std::max(d, p.depth_m);
  }
  return d;
}

// Lines through `points` at `depth`, the first from the departure's depth,
// the last to the rendezvous's; `lap` marks which legs go round the object.
std::vector<BasicManoeuvre> evasion_lines(const std::vector<Vec2>& points, const std::vector<CircleArc>& lap,
                                          const std::vector<Vec2>& after, const PlanPosition& from,
                                          const PlanPosition& to, double depth, std::size_t source) {
  std::vector<BasicManoeuvre> out;
  const auto add_line = [&](const Vec2& a, const Vec2& b, BasicManoeuvre::Role role) {
    if ((b - a).norm() <= 1e-9) return;
    BasicManoeuvre m;
    m.kind = BasicManoeuvre::Kind::line;
    m.from = a;
    m.to = b;
    m.length_m = (b - a).norm();
    m.role = role;
    out.push_back(m);
  };
  for (std::size_t k = 1; k < points.size(); ++k) add_line(points[k - 1], points[k], BasicManoeuvre::Role::evasion);
  for (const CircleArc& a : lap) {
    BasicManoeuvre m;
    m.kind = BasicManoeuvre::Kind::arc;
    m.from = a.from;
    m.to = a.to;
    m.centre = a.centre;
    m.radius_m = a.radius_m;
    m.turn = a.turn;
    m.length_m = a.length_m();
    m.role = BasicManoeuvre::Role::identification;
    out.push_back(m);
  }
  for (std::size_t k = 1; k < after.size(); ++k) add_line(after[k - 1], after[k], BasicManoeuvre::Role::evasion);
  // The first line leaves from the departure's depth, the last one rejoins at
  // the rendezvous's; arcs keep the depth they begin at.
  double depth_now = from.depth_m;
  std::size_t last_line = out.size();
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (out[k].kind == BasicManoeuvre::Kind::line) last_line = k;
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    BasicManoeuvre& m = out[k];
    m.from_depth_m = depth_now;
    m.depth_m = m.kind == BasicManoeuvre::Kind::arc ? depth_now : k == last_line ? to.depth_m : depth;
    m.speed_mps = from.speed_mps;
    m.source = source;
    depth_now = m.depth_m;
  }
  return out;
}

}  // namespace

ObservationOptions observation_options(const Mission& mission) {
  ObservationOptions o;
  o.margin_m = mission.margin_m;
  o.vertical_clearance_m = mission.vertical_clearance_m;
  return o;
}

ControlRules::Reaction choose_reaction(const ControlRules& rules, const ObstacleSet& obstacles, std::size_t obstacle) {
  if (obstacle >= obstacles.ellipses.size()) return ControlRules::Reaction::evade;
  const std::string& id = obstacles.ellipses[obstacle].id;
  return std::find(rules.identify.begin(), rules.identify.end(), id) != rules.identify.end()
             ? ControlRules::Reaction::identify
             : ControlRules::Reaction::evade;
}

namespace {

// One attempt at resolving `next` on `plan` (the header's steps 1 to 4);
// fills r and returns the new plan, or none with r.problem set.
std::optional<MissionPlan> resolve(const Mission& mission, const MissionEnvironment& env, EvasionPlanner& evasions,
                                   const MissionPlan& plan, const Conflict& next, double not_before, Resolution& r) {
  const PlanPosition at_conflict = position_at(plan, next.along_m);
  const double speed = std::max(at_conflict.speed_mps, 1e-3);
  const double lead = 2.0 * turn_radius(mission.vehicle, speed) + evasions.zone_margin();
  // The vehicle climbs at most this much per metre ahead; the last leg must leave it room.
  const double climb_per_m = mission.vehicle.max_vertical_speed_mps / speed;
  const TrackDanger danger = track_danger(plan, evasions.volume(), kStep);
  std::string why;
  const std::optional<EvasionStretch> stretch = goal_points(danger, next.along_m, lead, not_before, &why);
  if (!stretch) {
    r.problem = why;
    return std::nullopt;
  }
  double depart = stretch->depart_m, rendezvous = stretch->rendezvous_m;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    // The evasion's depth, and departure and rendezvous free at it (moving
    // them may reach deeper water: then again).
    double depth = deepest_between(danger, plan, depart, rendezvous);
    for (int settle = 0; settle < kAttempts; ++settle) {
      while (!evasions.free_at(depth, position_at(plan, depart).xy) && depart > not_before) {
        depart = std::max(not_before, depart - kStep);
      }
      while (!evasions.free_at(depth, position_at(plan, rendezvous).xy) && rendezvous < plan.length_m) {
        rendezvous = std::min(plan.length_m, rendezvous + kStep);
      }
      const double deeper = deepest_between(danger, plan, depart, rendezvous);
      if (deeper <= depth) break;
      depth = deeper;
    }
    const PlanPosition from = position_at(plan, depart), to = position_at(plan, rendezvous);
    if (deepest_between(danger, plan, depart, rendezvous) > depth || !evasions.free_at(depth, from.xy) ||
        !evasions.free_at(depth, to.xy)) {
      r.problem =
          "no free water at " + fixed(depth, 1) + " m" + " on the route before or after it to leave from or rejoin at";
      return std::nullopt;
    }
    if (holds_within(plan, depart, rendezvous)) {
      r.problem = "evading it would skip a hold (a GPS fix or an alignment) between " + point_text(from.xy) + " and " +
                  point_text(to.xy);
      return std::nullopt;
    }
    std::vector<Vec2> points, onward;
    IdentificationLap lap;
    if (r.reaction == ControlRules::Reaction::identify) {
      const Ellipse& object = env.obstacles.ellipses[next.obstacle].footprint;
      lap = identification_lap(object, mission.control.identify_distance_m, from.xy);
      points = evasions.route(depth, from.xy, lap.start, r.problem);
      if (!points.empty()) onward = evasions.route(depth, lap.start, to.xy, r.problem);
      if (points.empty() || onward.empty()) return std::nullopt;
    } else {
      points = evasions.route(depth, from.xy, to.xy, r.problem);
    }
    std::vector<BasicManoeuvre> lines =
        evasion_lines(points, lap.arcs, onward, from, to, depth, plan.basics[from.basic].source);
    if (lines.empty()) {
      if (r.problem.empty()) r.problem = "the evasion has no length (departure and rendezvous coincide)";
      return std::nullopt;
    }
    // Climbing back to the rendezvous's depth on the last line must suit the vehicle.
    const BasicManoeuvre& last = lines.back();
    const double climb = last.from_depth_m - last.depth_m;
    if (climb > climb_per_m * last.length_m + 1e-9 && rendezvous < plan.length_m && attempt + 1 < kAttempts) {
      rendezvous = std::min(plan.length_m, rendezvous + climb / climb_per_m - last.length_m + kStep);
      continue;
    }
    double length = 0.0;
    for (const BasicManoeuvre& b : lines) length += b.length_m;
    MissionPlan spliced = splice_plan(plan, depart, rendezvous, std::move(lines));
    const double rejoin = depart + length;
    // The evasion must leave nothing between departure and rendezvous.
    const std::vector<Conflict> after = observe_collisions(spliced, env.obstacles, env.floor.get(), evasions.observe());
    const auto still = std::find_if(after.begin(), after.end(), [&](const Conflict& c) {
      return c.along_m >= depart - 1e-6 && c.along_m <= rejoin + 1e-6;
    });
    if (still != after.end()) {
      r.problem = "the evasive route still meets " + still->with + " at " + point_text(still->where);
      return std::nullopt;
    }
    r.resolved = true;
    r.depart_m = depart;
    r.rendezvous_m = rejoin;
    r.depth_m = depth;
    r.added_m = length - (rendezvous - depart);
    r.problem.clear();
    return spliced;
  }
  if (r.problem.empty()) r.problem = "no evasion found that lets the vehicle climb back to the route in time";
  return std::nullopt;
}

}  // namespace

PlannedMission plan_mission(const Mission& mission, const MissionEnvironment& environment, const MissionPlan& initial,
                            double from_m) {
  EvasionPlanner evasions(mission, environment);
  return plan_mission(mission, evasions, initial, from_m);
}

PlannedMission plan_mission(const Mission& mission, EvasionPlanner& evasions, const MissionPlan& initial,
                            double from_m) {
  const MissionEnvironment& env = evasions.environment();
  PlannedMission out;
  out.plan = initial;
  double not_before = std::max(0.0, from_m);  // the end of the last evasion
  // Conflicts found unresolvable, by obstacle and where they begin: the plan
  // before not_before no longer changes, so these stay valid.
  std::set<std::pair<std::size_t, double>> given_up;
  for (;;) {
    const std::vector<Conflict> conflicts =
        observe_collisions(out.plan, env.obstacles, env.floor.get(), evasions.observe());
    const auto next = std::find_if(conflicts.begin(), conflicts.end(), [&](const Conflict& c) {
      return c.along_m >= not_before && !given_up.count({c.obstacle, c.along_m});
    });
    if (next == conflicts.end()) break;
    Resolution r;
    r.conflict = *next;
    r.reaction = next->obstacle == kSeaFloor ? ControlRules::Reaction::evade
                                             : choose_reaction(mission.control, env.obstacles, next->obstacle);
    r.time_s = position_at(out.plan, next->along_m).time_s;
    std::optional<MissionPlan> resolved;
    try {
      resolved = resolve(mission, env, evasions, out.plan, *next, not_before, r);
    } catch (const InputError& e) {  // e.g. the sea floor's no-go polygons at that depth
      r.problem = e.what();
    }
    if (!resolved) {
      given_up.insert({next->obstacle, next->along_m});
      out.resolutions.push_back(r);
      continue;
    }
    // Conflicts the same stretch took care of (their dangers joined this one's) are said so.
    const double rendezvous_before = r.rendezvous_m - r.added_m;  // in the plan before the splice
    for (const Conflict& c : conflicts) {
      if (&c == &*next || c.along_m < r.depart_m || c.along_m > rendezvous_before) continue;
      if (given_up.count({c.obstacle, c.along_m})) continue;
      Resolution with = r;
      with.conflict = c;
      with.time_s = position_at(out.plan, c.along_m).time_s;
      with.added_m = 0.0;
      const bool wanted = c.obstacle != kSeaFloor && choose_reaction(mission.control, env.obstacles, c.obstacle) ==
                                                         ControlRules::Reaction::identify;
      with.note = std::string(wanted && r.reaction != ControlRules::Reaction::identify ? "to identify, but " : "") +
                  (r.reaction == ControlRules::Reaction::identify ? "passed" : "evaded") + " with " + next->with +
                  " (their dangers join)";
      with.reaction = r.reaction;
      out.resolutions.push_back(with);
    }
    out.resolutions.push_back(r);
    std::stable_sort(out.resolutions.begin(), out.resolutions.end(),
                     [](const Resolution& a, const Resolution& b) { return a.time_s < b.time_s; });
    out.plan = std::move(*resolved);
    not_before = r.rendezvous_m;
  }
  out.remaining = observe_collisions(out.plan, env.obstacles, env.floor.get(), evasions.observe());
  std::erase_if(out.remaining, [&](const Conflict& c) { return c.along_m < from_m; });
  return out;
}

}  // namespace deepguide
