#include "deepguide/simulation/mission_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/evasion_planner.hpp"
#include "deepguide/mission/goal_point.hpp"
#include "deepguide/mission/plan_splice.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/simulation/contacts.hpp"
#include "deepguide/simulation/path_following.hpp"
#include "deepguide/simulation/plant.hpp"
#include "deepguide/simulation/route_following.hpp"
#include "deepguide/simulation/simulation.hpp"
#include "deepguide/world/current_field.hpp"
#include "deepguide/world/water_volume.hpp"

namespace deepguide {
namespace {

constexpr double kArrival_m = 5.0;
constexpr double kKnownSlack_m = 10.0;  // a contact this near a known footprint is that obstacle
constexpr double kSameContact_m = 10.0;
constexpr double kTrackWindow_m = 15.0;  // per step the vehicle moves well under a metre
constexpr double kRetry_s = 10.0;        // an evasion that cannot be planned yet is tried again after this

// The plan level: the plan's lines and arcs followed one after another
// (path_following.hpp; corners turned on the vehicle's radius), and the
// vehicle's place along the plan, which only moves on.
class PlanTrack {
 public:
  // Follows `plan` from its leg nearest `pos` within [along - 2 m, along + ahead].
  void reset(const MissionPlan& plan, double along, const Vec2& pos, double ahead) {
    follower_.legs.clear();
    start_.clear();
    for (const BasicManoeuvre& b : plan.basics) {
      if (b.kind == BasicManoeuvre::Kind::point || b.length_m <= 1e-9) continue;
      if (b.kind == BasicManoeuvre::Kind::line) {
        follower_.legs.push_back(line_leg(b.from, b.to));
      } else {
        const Vec2 r = b.from - b.centre;
        follower_.legs.push_back(
            circle_leg(b.centre, b.radius_m, std::atan2(r.y(), r.x()), b.turn * b.length_m / b.radius_m));
      }
      start_.push_back(b.start_m);
    }
    along_ = along;
    double best = std::numeric_limits<double>::infinity();
    follower_.leg = 0;
    for (std::size_t k = 0; k < start_.size(); ++k) {
      if (start_[k] + follower_.legs[k].length_m < along - kBehind_m || start_[k] > along + ahead) continue;
      const double d = (nearest_on_leg(follower_.legs[k], pos).point - pos).norm();
      if (d < best) {
        best = d;
        follower_.leg = k;
      }
    }
  }
  double along() const { return along_; }
  // The command at `pos`; the place along the plan moves on with it.
  PathFollower::Command steer(const Vec2& pos, const Vec2& ground_velocity, const VehicleParams& vehicle,
                              double speed_mps, double lookahead_m) {
    if (follower_.legs.empty()) return {.at_end = true};
    follower_.lookahead_m = lookahead_m > 0.0 ? lookahead_m : path_lookahead(vehicle, speed_mps);
    follower_.lead_m = path_lead(vehicle, speed_mps);
    follower_.corner_radius_m = turn_radius(vehicle, speed_mps);
    const PathFollower::Command c = follower_.steer(pos, ground_velocity);
    along_ = std::max(along_, start_[follower_.leg] + follower_.legs[follower_.leg].length_m - c.to_end_m);
    return c;
  }

 private:
  static constexpr double kBehind_m = 2.0;
  PathFollower follower_;
  std::vector<double> start_;  // along the plan where each leg begins
  double along_ = 0.0;
};

Vec2 local_current(const Mission& mission) {
  if (!mission.current_file.empty()) {
    throw InputError(mission.source +
                     ": environment.current_file: the mission simulation takes a constant current "
                     "(current: SPEED_MPS,DIR_DEG) for now");
  }
  return constant_current(mission);
}

}  // namespace

MissionRun run_mission(const Mission& mission, const MissionEnvironment& env, const MissionPlan& initial,
                       const ObstacleSet& unknown, const MissionRunOptions& options) {
  MissionRun run;
  run.plan = initial;
  if (initial.basics.empty()) return run;
  // The world: what is known plus what nobody knew.
  ObstacleSet truth = env.obstacles;
  truth.ellipses.insert(truth.ellipses.end(), unknown.ellipses.begin(), unknown.ellipses.end());
  truth.polygons.insert(truth.polygons.end(), unknown.polygons.begin(), unknown.polygons.end());
  const ObstacleField truth_field(truth, 0.0);
  const WaterVolume truth_volume(truth_field, env.floor.get(), {0.0, 0.0, std::numeric_limits<double>::infinity()});

  Scenario sc;
  sc.name = mission.name;
  sc.source = mission.source;
  sc.vehicle = mission.vehicle;
  sc.sonar.seed = options.seed;
  sc.obstacles = truth.ellipses;
  sc.current = local_current(mission);
  sc.depth_m = mission.start_depth_m;
  sc.reactive.margin_m = mission.margin_m + 0.5;
  const double max_time = options.max_time_s > 0.0 ? options.max_time_s : 2.0 * plan_duration(initial) + 600.0;

  const BasicManoeuvre& first = initial.basics.front();
  const Vec2 first_to = position_at(initial, std::min(initial.length_m, 10.0)).xy;
  Plant plant(sc, mission.start, std::atan2((first_to - mission.start).y(), (first_to - mission.start).x()),
              first.speed_mps);
  Sonar sonar(sc.sonar);
  ContactMemory contacts(sc.contacts, sc.sonar);
  ReactiveMemory memory;
  PlanTrack plan_track;
  plan_track.reset(run.plan, 0.0, mission.start, kTrackWindow_m);
  double plan_speed = first.speed_mps;  // the plan's speed where the vehicle was a step ago
  const ObservationOptions observe = observation_options(mission);
  // Mission control's evasions, kept across detections: a contact it plans
  // round is cut into the kept meshes (EvasionPlanner::add). One it only
  // waits on (a later, nearer estimate replaces it) leaves them stale: then
  // they are made again from the chart and the contacts handled.
  std::unique_ptr<EvasionPlanner> evasions;
  bool evasions_stale = true;

  bool reactive = false;
  double reactive_until = 0.0;
  double pending_at = 0.0;  // when the planner's evasion is ready
  Vec2 reactive_target{0.0, 0.0};
  std::optional<PlannedMission> pending;         // the evasion planned, spliced in when the planner is done
  std::vector<Vec2> handled;                     // centres of unknown contacts already reacted to
  std::vector<std::pair<Vec2, double>> waiting;  // contacts whose evasion could not be planned yet, and when to retry
  double rendezvous_m = -1.0;                    // where the reactive level hands back, on the plan of the time
  const double zone_margin = mission.margin_m + 0.7;
  const ObstacleField known_field(env.obstacles, 0.0);
  // A contact is a known obstacle when it lies within kKnownSlack_m of a known
  // footprint and is no bigger than it (+ the slack): a small object beside a
  // big wreck is not the wreck.
  const auto is_known = [&](const Ellipse& c) {
    for (std::size_t i : known_field.near(c.centre, c.centre, kKnownSlack_m)) {
      if (known_field.distance_to(i, c.centre) > kKnownSlack_m) continue;
      if (i < env.obstacles.ellipses.size() && c.a > env.obstacles.ellipses[i].footprint.a + kKnownSlack_m) continue;
      return true;
    }
    return false;
  };
  std::vector<char> held(run.plan.basics.size(), 0);
  double held_s = 0.0;  // time spent holding (the plant's clock stops meanwhile)
  bool inside = false;
  double next_sample = 0.0;
  run.min_clearance_m = std::numeric_limits<double>::infinity();
  Vec2 last = mission.start;

  const auto event = [&](double t, const Vec2& where, std::string what, bool alarm = false) {
    run.events.push_back({t, where, std::move(what), alarm});
  };

  for (std::size_t k = 0;; ++k) {
    plant.at_step(k);
    const VehicleState& s = plant.state();
    const double t = s.time_s + held_s;
    const Vec2 pos = s.position;
    run.length_m += (pos - last).norm();
    last = pos;
    if (!reactive)
      plan_track.steer(pos, s.ground_velocity, mission.vehicle, std::max(plan_speed, 0.1), options.lookahead_m);
    const PlanPosition here = position_at(run.plan, plan_track.along());
    plan_speed = here.speed_mps;

    // Truth: clearance and collisions.
    for (std::size_t i : truth_field.near(pos, pos, 100.0)) {
      if (truth_volume.zone_top(i) < s.depth_m)
        run.min_clearance_m = std::min(run.min_clearance_m, truth_field.distance_to(i, pos));
    }
    const WaterVolume::Verdict v = truth_volume.check_point({pos.x(), pos.y(), s.depth_m});
    if (v.blocked && !inside) {
      run.collided = true;
      event(t, pos, "COLLISION: the vehicle " + v.reason, true);
    }
    inside = v.blocked;
    if (t >= next_sample) {
      run.track.push_back({t, pos, s.depth_m, s.heading, plan_track.along(), reactive});
      next_sample = t + options.sample_every_s;
    }
    // Holds: wait at the point (the clock runs on, the vehicle stays).
    for (std::size_t i = 0; !reactive && i < run.plan.basics.size(); ++i) {
      const BasicManoeuvre& b = run.plan.basics[i];
      if (b.start_m > plan_track.along()) break;
      if (b.kind != BasicManoeuvre::Kind::point || held[i]) continue;
      held[i] = 1;
      if (b.hold_s > 0.0) {
        char what[96];
        std::snprintf(what, sizeof what, "hold %.0f s at %.1f m depth", b.hold_s, b.depth_m);
        event(t, pos, what);
        held_s += b.hold_s;
      }
    }

    if (!reactive && plan_track.along() >= run.plan.length_m - kArrival_m) {
      for (std::size_t i = 0; i < run.plan.basics.size(); ++i) {  // holds at the very end
        const BasicManoeuvre& b = run.plan.basics[i];
        if (b.kind != BasicManoeuvre::Kind::point || held[i]) continue;
        held[i] = 1;
        if (b.hold_s > 0.0) {
          event(t, pos, "hold " + fixed(b.hold_s, 0) + " s at " + fixed(b.depth_m, 1) + " m depth");
          held_s += b.hold_s;
        }
      }
      run.completed = true;
      event(s.time_s + held_s, pos, "reached the end of the plan");
      break;
    }
    if (t >= max_time) {
      event(t, pos, "time out: the plan's end was not reached", true);
      break;
    }

    // The sonar, and what it finds that nobody knew.
    if (sonar.update(t, pos, s.heading, sc.obstacles)) {
      contacts.update(sonar.detections(), t);
      for (const Ellipse& c : contacts.ellipses()) {
        const auto near = [&](const Vec2& p) { return (p - c.centre).norm() <= kSameContact_m; };
        if (reactive || is_known(c) || std::any_of(handled.begin(), handled.end(), near)) continue;
        if (std::any_of(waiting.begin(), waiting.end(), [&](const auto& w) { return near(w.first) && t < w.second; })) {
          continue;
        }
        EllipticCylinder object;
        object.id = "unknown-" + std::to_string(run.detected.size() + 1);
        object.footprint = c;
        ObstacleSet contact;
        contact.ellipses.push_back(object);
        const std::vector<Conflict> ahead = observe_collisions(run.plan, contact, nullptr, observe);
        const auto danger =
            std::find_if(ahead.begin(), ahead.end(), [&](const Conflict& x) { return x.along_m > plan_track.along(); });
        if (danger == ahead.end()) continue;
        const double speed = std::max(here.speed_mps, 0.1);
        const double lead = 2.0 * turn_radius(mission.vehicle, speed) + zone_margin;
        // Mission control plans the evasion, the contact among the known obstacles.
        Mission rules = mission;
        if (mission.control.unknown_objects == ControlRules::Reaction::identify)
          rules.control.identify.push_back(object.id);
        if (evasions_stale) {
          MissionEnvironment seen_env = env;
          seen_env.obstacles.ellipses.insert(seen_env.obstacles.ellipses.end(), run.detected.ellipses.begin(),
                                             run.detected.ellipses.end());
          evasions = std::make_unique<EvasionPlanner>(mission, std::move(seen_env));
          evasions_stale = false;
        }
        evasions->add(contact);
        const double from_m = plan_track.along() + speed * options.planning_delay_s + lead;
        PlannedMission planned = plan_mission(rules, *evasions, run.plan, from_m);
        const auto mine = std::find_if(planned.resolutions.begin(), planned.resolutions.end(),
                                       [&](const Resolution& r) { return r.conflict.with == object.id; });
        const bool ok = mine != planned.resolutions.end() && planned.remaining.empty() &&
                        std::all_of(planned.resolutions.begin(), planned.resolutions.end(),
                                    [](const Resolution& r) { return r.resolved; });
        // In view ahead, before the planner can be done, the reactive level must act now.
        const bool imminent = danger->along_m - plan_track.along() <= speed * options.planning_delay_s + 2.0 * lead;
        if (!ok && !imminent) {
          waiting.emplace_back(c.centre, t + kRetry_s);  // try again as it comes nearer
          evasions_stale = true;
          continue;
        }
        handled.push_back(c.centre);
        run.detected.ellipses.push_back(object);
        event(t, pos,
              object.id + " at " + point_text(c.centre) + " is on no chart and endangers the plan " +
                  fixed(danger->along_m - plan_track.along(), 0) + " m ahead");
        if (ok) {
          // The rendezvous is on the route as written, so the new plan's point for it is the place.
          reactive_target = position_at(planned.plan, mine->rendezvous_m).xy;
          pending = std::move(planned);
          pending_at = t + options.planning_delay_s;
          if (!imminent) {
            event(
                t, pos,
                object.id + " lies farther along the plan: the planner repairs it while the plan level keeps control");
            break;
          }
          event(t, pos, "the reactive level takes over until the evasion is planned");
        } else {
          // The rendezvous past the danger, from goal points on the contact alone.
          const ObstacleField contact_field(contact, zone_margin);
          const WaterVolume contact_volume(
              contact_field, nullptr, {mission.vertical_clearance_m, 0.0, std::numeric_limits<double>::infinity()});
          std::string why;
          const std::optional<EvasionStretch> stretch =
              goal_points(track_danger(run.plan, contact_volume, 2.0), danger->along_m, lead, plan_track.along(), &why);
          rendezvous_m = stretch ? stretch->rendezvous_m : run.plan.length_m;
          const bool planner_failed = mine != planned.resolutions.end() && !mine->resolved;
          if (planner_failed || !stretch) {
            event(t, pos,
                  "no evasion could be planned (" + (planner_failed ? mine->problem : why) +
                      "): the reactive level steers to the rendezvous " +
                      point_text(position_at(run.plan, rendezvous_m).xy),
                  true);
          } else {
            event(t, pos,
                  object.id + " is too near for the planner: the reactive level evades it to the rendezvous " +
                      point_text(position_at(run.plan, rendezvous_m).xy));
          }
        }
        if (ok) {
          rendezvous_m = -1.0;  // the new plan takes over
        } else {
          reactive_target = position_at(run.plan, rendezvous_m).xy;
        }
        reactive = true;
        reactive_until = t + options.planning_delay_s;
        memory = {};
        break;
      }
    }

    // Guidance: the reactive level, or the plan.
    AutopilotSetpoint set;
    set.depth_m = here.depth_m;
    if (pending && t >= pending_at) {
      {
        // Before the departure the plan is unchanged, so the vehicle's place on it holds.
        run.plan = pending->plan;
        double added = 0.0;
        for (const Resolution& r : pending->resolutions) added += r.added_m;
        plan_track.reset(run.plan, plan_track.along(), pos, 60.0);
        held.assign(run.plan.basics.size(), 0);
        for (std::size_t i = 0; i < run.plan.basics.size(); ++i) {
          held[i] = run.plan.basics[i].start_m < plan_track.along() - 1e-6 ? 1 : 0;
        }
        ++run.replans;
        char what[128];
        std::snprintf(what, sizeof what, "evasion planned and spliced in (%+.0f m)%s", added,
                      reactive ? ": the plan level again" : "");
        event(t, pos, what);
        pending.reset();
        reactive = false;
      }
    } else if (reactive) {
      if (t >= reactive_until && rendezvous_m >= 0.0 && (pos - reactive_target).norm() <= 2.0 * kArrival_m) {
        // Holds between the place the reactive level took over and the rendezvous were not sailed: say so.
        for (std::size_t i = 0; i < run.plan.basics.size(); ++i) {
          const BasicManoeuvre& b = run.plan.basics[i];
          if (b.kind != BasicManoeuvre::Kind::point || held[i] || b.start_m > rendezvous_m) continue;
          held[i] = 1;
          if (b.hold_s > 0.0)
            event(t, pos, "the hold at " + point_text(b.from) + " was skipped by the reactive level", true);
        }
        plan_track.reset(run.plan, rendezvous_m, pos, kTrackWindow_m);
        rendezvous_m = -1.0;
        event(t, pos, "at the rendezvous: the plan level again");
        reactive = false;
      }
    }
    if (reactive) {
      ReactiveParams params = sailing_params(sc.reactive, sc.vehicle);
      params.speed_mps = std::max(here.speed_mps, 0.1);
      const double cog =
          s.ground_velocity.squaredNorm() > 0.0 ? std::atan2(s.ground_velocity.y(), s.ground_velocity.x()) : s.heading;
      const ReactiveCommand cmd =
          reactive_command(ReactiveMethod::geometric, params, memory,
                           {t, pos, cog, s.speed_mps, reactive_target, contacts.ellipses(), s.yaw_rate});
      if (cmd.status == ReactiveStatus::target_in_zone && !pending) {
        // The rendezvous lies inside an object's zone: no way on. Stop short and say so.
        event(t, pos,
              "the rendezvous " + point_text(reactive_target) +
                  " lies inside an object's security zone: the vehicle stops short, the mission cannot go on",
              true);
        break;
      }
      set.course = cmd.course;
      set.speed_mps = cmd.speed_mps;
    } else {
      set.speed_mps = std::max(here.speed_mps, 0.1);
      const PathFollower::Command c =
          plan_track.steer(pos, s.ground_velocity, mission.vehicle, set.speed_mps, options.lookahead_m);
      if (c.at_end) {
        // Past the last leg's end, short of arriving: home on the plan's end.
        const Vec2 end = position_at(run.plan, run.plan.length_m).xy - pos;
        set.course = end.norm() > 1e-6 ? std::atan2(end.y(), end.x()) : s.heading;
      } else {
        set.course = c.course;
        set.course_rate = c.course_rate;
      }
    }
    plant.steer(set);
    plant.advance();
  }
  run.time_s = run.track.empty() ? 0.0 : run.events.back().time_s;
  return run;
}

}  // namespace deepguide
