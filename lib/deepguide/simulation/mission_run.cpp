#include "deepguide/simulation/mission_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/mission/evasion_planner.hpp"
#include "deepguide/mission/goal_point.hpp"
#include "deepguide/mission/plan_splice.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/simulation/contacts.hpp"
#include "deepguide/simulation/path_following.hpp"
#include "deepguide/simulation/plant.hpp"
#include "deepguide/simulation/route_following.hpp"
#include "deepguide/simulation/simulation.hpp"
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

// One run of a mission: the plant sailing the plan level's track, the truth
// judging clearance and collisions, the sonar finding what nobody knew, and
// mission control or the reactive level answering it. One step of the loop
// is observe (truth, holds), detect (sonar and contacts), then steer.
class MissionRunner {
 public:
  MissionRunner(const Mission& mission, const MissionEnvironment& env, const MissionPlan& initial,
                const ObstacleSet& unknown, const MissionRunOptions& options)
      : mission_(mission),
        env_(env),
        options_(options),
        truth_(with(env.obstacles, unknown)),
        truth_field_(truth_, 0.0),
        truth_volume_(truth_field_, env.floor.get(), {0.0, 0.0, std::numeric_limits<double>::infinity()}),
        sc_(scenario_of(mission, truth_, options)),
        plant_(sc_, mission.start, first_heading(mission, initial), initial.basics.front().speed_mps),
        sonar_(sc_.sonar),
        contacts_(sc_.contacts, sc_.sonar),
        observe_(observation_options(mission)),
        zone_margin_(mission.margin_m + 0.7),
        known_field_(env.obstacles, 0.0),
        max_time_(options.max_time_s > 0.0 ? options.max_time_s : 2.0 * plan_duration(initial) + 600.0) {
    run_.plan = initial;
    plan_track_.reset(run_.plan, 0.0, mission.start, kTrackWindow_m);
    plan_speed_ = initial.basics.front().speed_mps;
    held_.assign(run_.plan.basics.size(), 0);
    run_.min_clearance_m = std::numeric_limits<double>::infinity();
    last_ = mission.start;
  }

  MissionRun run() {
    for (std::size_t k = 0;; ++k) {
      plant_.at_step(k);
      const VehicleState& s = plant_.state();
      const double t = s.time_s + held_s_;
      const Vec2 pos = s.position;
      run_.length_m += (pos - last_).norm();
      last_ = pos;
      if (!reactive_)
        plan_track_.steer(pos, s.ground_velocity, mission_.vehicle, std::max(plan_speed_, 0.1), options_.lookahead_m);
      const PlanPosition here = position_at(run_.plan, plan_track_.along());
      plan_speed_ = here.speed_mps;
      observe_truth(s, t);
      hold_points(t, pos);
      if (!reactive_ && plan_track_.along() >= run_.plan.length_m - kArrival_m) {
        hold_points(t, pos, true);  // holds at the very end
        run_.completed = true;
        event(s.time_s + held_s_, pos, "reached the end of the plan");
        break;
      }
      if (t >= max_time_) {
        event(t, pos, "time out: the plan's end was not reached", true);
        break;
      }
      if (sonar_.update(t, pos, s.heading, sc_.obstacles)) detect(t, pos, here);
      const std::optional<AutopilotSetpoint> set = guidance(s, t, here);
      if (!set) break;
      plant_.steer(*set);
      plant_.advance();
    }
    run_.time_s = run_.track.empty() ? 0.0 : run_.events.back().time_s;
    return std::move(run_);
  }

 private:
  static ObstacleSet with(ObstacleSet known, const ObstacleSet& unknown) {
    known.ellipses.insert(known.ellipses.end(), unknown.ellipses.begin(), unknown.ellipses.end());
    known.polygons.insert(known.polygons.end(), unknown.polygons.begin(), unknown.polygons.end());
    return known;
  }
  static Scenario scenario_of(const Mission& mission, const ObstacleSet& truth, const MissionRunOptions& options) {
    Scenario sc;
    sc.name = mission.name;
    sc.source = mission.source;
    sc.vehicle = mission.vehicle;
    sc.sonar.seed = options.seed;
    sc.obstacles = truth.ellipses;
    sc.current = local_current(mission);
    sc.depth_m = mission.start_depth_m;
    sc.reactive.margin_m = mission.margin_m + 0.5;
    return sc;
  }
  static double first_heading(const Mission& mission, const MissionPlan& initial) {
    const Vec2 first_to = position_at(initial, std::min(initial.length_m, 10.0)).xy;
    return std::atan2((first_to - mission.start).y(), (first_to - mission.start).x());
  }

  void event(double t, const Vec2& where, std::string what, bool alarm = false) {
    run_.events.push_back({t, where, std::move(what), alarm});
  }

  // A contact is a known obstacle when it lies within kKnownSlack_m of a known
  // footprint and is no bigger than it (+ the slack): a small object beside a
  // big wreck is not the wreck.
  bool is_known(const Ellipse& c) const {
    for (std::size_t i : known_field_.near(c.centre, c.centre, kKnownSlack_m)) {
      if (known_field_.distance_to(i, c.centre) > kKnownSlack_m) continue;
      if (i < env_.obstacles.ellipses.size() && c.a > env_.obstacles.ellipses[i].footprint.a + kKnownSlack_m) continue;
      return true;
    }
    return false;
  }

  // Truth: clearance and collisions, and the track's samples.
  void observe_truth(const VehicleState& s, double t) {
    const Vec2 pos = s.position;
    for (std::size_t i : truth_field_.near(pos, pos, 100.0)) {
      if (truth_volume_.zone_top(i) < s.depth_m)
        run_.min_clearance_m = std::min(run_.min_clearance_m, truth_field_.distance_to(i, pos));
    }
    const WaterVolume::Verdict v = truth_volume_.check_point({pos.x(), pos.y(), s.depth_m});
    if (v.blocked && !inside_) {
      run_.collided = true;
      event(t, pos, "COLLISION: the vehicle " + v.reason, true);
    }
    inside_ = v.blocked;
    if (t >= next_sample_) {
      run_.track.push_back({t, pos, s.depth_m, s.heading, plan_track_.along(), reactive_});
      next_sample_ = t + options_.sample_every_s;
    }
  }

  // Holds: wait at the point (the clock runs on, the vehicle stays). At the
  // plan's end every hold not yet taken is taken.
  void hold_points(double t, const Vec2& pos, bool at_end = false) {
    for (std::size_t i = 0; (at_end || !reactive_) && i < run_.plan.basics.size(); ++i) {
      const BasicManoeuvre& b = run_.plan.basics[i];
      if (!at_end && b.start_m > plan_track_.along()) break;
      if (b.kind != BasicManoeuvre::Kind::point || held_[i]) continue;
      held_[i] = 1;
      if (b.hold_s > 0.0) {
        if (at_end) {
          event(t, pos, "hold " + fixed(b.hold_s, 0) + " s at " + fixed(b.depth_m, 1) + " m depth");
        } else {
          char what[96];
          std::snprintf(what, sizeof what, "hold %.0f s at %.1f m depth", b.hold_s, b.depth_m);
          event(t, pos, what);
        }
        held_s_ += b.hold_s;
      }
    }
  }

  // What the sonar finds that nobody knew: the first new contact that
  // endangers the plan is answered by mission control's evasion, or by the
  // reactive level until it is planned or when it cannot be.
  void detect(double t, const Vec2& pos, const PlanPosition& here) {
    contacts_.update(sonar_.detections(), t);
    for (const Ellipse& c : contacts_.ellipses()) {
      const auto near = [&](const Vec2& p) { return (p - c.centre).norm() <= kSameContact_m; };
      if (reactive_ || is_known(c) || std::any_of(handled_.begin(), handled_.end(), near)) continue;
      if (std::any_of(waiting_.begin(), waiting_.end(), [&](const auto& w) { return near(w.first) && t < w.second; })) {
        continue;
      }
      if (answer(c, t, pos, here)) break;
    }
  }

  // Answers contact c; false when it does not endanger the plan or its
  // evasion is put off (try the next contact).
  bool answer(const Ellipse& c, double t, const Vec2& pos, const PlanPosition& here) {
    EllipticCylinder object;
    object.id = "unknown-" + std::to_string(run_.detected.size() + 1);
    object.footprint = c;
    ObstacleSet contact;
    contact.ellipses.push_back(object);
    const std::vector<Conflict> ahead = observe_collisions(run_.plan, contact, nullptr, observe_);
    const auto danger =
        std::find_if(ahead.begin(), ahead.end(), [&](const Conflict& x) { return x.along_m > plan_track_.along(); });
    if (danger == ahead.end()) return false;
    const double speed = std::max(here.speed_mps, 0.1);
    const double lead = 2.0 * turn_radius(mission_.vehicle, speed) + zone_margin_;
    // Mission control plans the evasion, the contact among the known obstacles.
    Mission rules = mission_;
    if (mission_.control.unknown_objects == ControlRules::Reaction::identify)
      rules.control.identify.push_back(object.id);
    if (evasions_stale_) {
      MissionEnvironment seen_env = env_;
      seen_env.obstacles.ellipses.insert(seen_env.obstacles.ellipses.end(), run_.detected.ellipses.begin(),
                                         run_.detected.ellipses.end());
      evasions_ = std::make_unique<EvasionPlanner>(mission_, std::move(seen_env));
      evasions_stale_ = false;
    }
    evasions_->add(contact);
    const double from_m = plan_track_.along() + speed * options_.planning_delay_s + lead;
    PlannedMission planned = plan_mission(rules, *evasions_, run_.plan, from_m);
    const auto mine = std::find_if(planned.resolutions.begin(), planned.resolutions.end(),
                                   [&](const Resolution& r) { return r.conflict.with == object.id; });
    const bool ok = mine != planned.resolutions.end() && planned.remaining.empty() &&
                    std::all_of(planned.resolutions.begin(), planned.resolutions.end(),
                                [](const Resolution& r) { return r.resolved; });
    // In view ahead, before the planner can be done, the reactive level must act now.
    const bool imminent = danger->along_m - plan_track_.along() <= speed * options_.planning_delay_s + 2.0 * lead;
    if (!ok && !imminent) {
      waiting_.emplace_back(c.centre, t + kRetry_s);  // try again as it comes nearer
      evasions_stale_ = true;
      return false;
    }
    handled_.push_back(c.centre);
    run_.detected.ellipses.push_back(object);
    event(t, pos,
          object.id + " at " + point_text(c.centre) + " is on no chart and endangers the plan " +
              fixed(danger->along_m - plan_track_.along(), 0) + " m ahead");
    if (ok) {
      // The rendezvous is on the route as written, so the new plan's point for it is the place.
      reactive_target_ = position_at(planned.plan, mine->rendezvous_m).xy;
      pending_ = std::move(planned);
      pending_at_ = t + options_.planning_delay_s;
      if (!imminent) {
        event(t, pos,
              object.id + " lies farther along the plan: the planner repairs it while the plan level keeps control");
        return true;
      }
      event(t, pos, "the reactive level takes over until the evasion is planned");
      rendezvous_m_ = -1.0;  // the new plan takes over
    } else {
      react_to_rendezvous(contact, *danger, lead, mine != planned.resolutions.end() && !mine->resolved,
                          mine != planned.resolutions.end() ? mine->problem : std::string(), t, pos, object.id);
    }
    reactive_ = true;
    reactive_until_ = t + options_.planning_delay_s;
    memory_ = {};
    return true;
  }

  // No evasion planned: the reactive level steers to the rendezvous past the
  // danger, from goal points on the contact alone.
  void react_to_rendezvous(const ObstacleSet& contact, const Conflict& danger, double lead, bool planner_failed,
                           const std::string& problem, double t, const Vec2& pos, const std::string& id) {
    const ObstacleField contact_field(contact, zone_margin_);
    const WaterVolume contact_volume(contact_field, nullptr,
                                     {mission_.vertical_clearance_m, 0.0, std::numeric_limits<double>::infinity()});
    std::string why;
    const std::optional<EvasionStretch> stretch =
        goal_points(track_danger(run_.plan, contact_volume, 2.0), danger.along_m, lead, plan_track_.along(), &why);
    rendezvous_m_ = stretch ? stretch->rendezvous_m : run_.plan.length_m;
    if (planner_failed || !stretch) {
      event(t, pos,
            "no evasion could be planned (" + (planner_failed ? problem : why) +
                "): the reactive level steers to the rendezvous " +
                point_text(position_at(run_.plan, rendezvous_m_).xy),
            true);
    } else {
      event(t, pos,
            id + " is too near for the planner: the reactive level evades it to the rendezvous " +
                point_text(position_at(run_.plan, rendezvous_m_).xy));
    }
    reactive_target_ = position_at(run_.plan, rendezvous_m_).xy;
  }

  // The evasion planned is spliced in when the planner is done; the reactive
  // level hands back at the rendezvous.
  void hand_over(double t, const Vec2& pos) {
    if (pending_ && t >= pending_at_) {
      // Before the departure the plan is unchanged, so the vehicle's place on it holds.
      run_.plan = pending_->plan;
      double added = 0.0;
      for (const Resolution& r : pending_->resolutions) added += r.added_m;
      plan_track_.reset(run_.plan, plan_track_.along(), pos, 60.0);
      held_.assign(run_.plan.basics.size(), 0);
      for (std::size_t i = 0; i < run_.plan.basics.size(); ++i) {
        held_[i] = run_.plan.basics[i].start_m < plan_track_.along() - 1e-6 ? 1 : 0;
      }
      ++run_.replans;
      char what[128];
      std::snprintf(what, sizeof what, "evasion planned and spliced in (%+.0f m)%s", added,
                    reactive_ ? ": the plan level again" : "");
      event(t, pos, what);
      pending_.reset();
      reactive_ = false;
    } else if (reactive_ && t >= reactive_until_ && rendezvous_m_ >= 0.0 &&
               (pos - reactive_target_).norm() <= 2.0 * kArrival_m) {
      // Holds between the place the reactive level took over and the rendezvous were not sailed: say so.
      for (std::size_t i = 0; i < run_.plan.basics.size(); ++i) {
        const BasicManoeuvre& b = run_.plan.basics[i];
        if (b.kind != BasicManoeuvre::Kind::point || held_[i] || b.start_m > rendezvous_m_) continue;
        held_[i] = 1;
        if (b.hold_s > 0.0)
          event(t, pos, "the hold at " + point_text(b.from) + " was skipped by the reactive level", true);
      }
      plan_track_.reset(run_.plan, rendezvous_m_, pos, kTrackWindow_m);
      rendezvous_m_ = -1.0;
      event(t, pos, "at the rendezvous: the plan level again");
      reactive_ = false;
    }
  }

  // Guidance: the reactive level, or the plan. Nothing when the mission cannot go on.
  std::optional<AutopilotSetpoint> guidance(const VehicleState& s, double t, const PlanPosition& here) {
    const Vec2 pos = s.position;
    AutopilotSetpoint set;
    set.depth_m = here.depth_m;
    hand_over(t, pos);
    if (reactive_) {
      ReactiveParams params = sailing_params(sc_.reactive, sc_.vehicle);
      params.speed_mps = std::max(here.speed_mps, 0.1);
      const double cog =
          s.ground_velocity.squaredNorm() > 0.0 ? std::atan2(s.ground_velocity.y(), s.ground_velocity.x()) : s.heading;
      const ReactiveCommand cmd =
          reactive_command(ReactiveMethod::geometric, params, memory_,
                           {t, pos, cog, s.speed_mps, reactive_target_, contacts_.ellipses(), s.yaw_rate});
      if (cmd.status == ReactiveStatus::target_in_zone && !pending_) {
        // The rendezvous lies inside an object's zone: no way on. Stop short and say so.
        event(t, pos,
              "the rendezvous " + point_text(reactive_target_) +
                  " lies inside an object's security zone: the vehicle stops short, the mission cannot go on",
              true);
        return std::nullopt;
      }
      set.course = cmd.course;
      set.speed_mps = cmd.speed_mps;
      return set;
    }
    set.speed_mps = std::max(here.speed_mps, 0.1);
    const PathFollower::Command c =
        plan_track_.steer(pos, s.ground_velocity, mission_.vehicle, set.speed_mps, options_.lookahead_m);
    if (c.at_end) {
      // Past the last leg's end, short of arriving: home on the plan's end.
      const Vec2 end = position_at(run_.plan, run_.plan.length_m).xy - pos;
      set.course = end.norm() > 1e-6 ? std::atan2(end.y(), end.x()) : s.heading;
    } else {
      set.course = c.course;
      set.course_rate = c.course_rate;
    }
    return set;
  }

  const Mission& mission_;
  const MissionEnvironment& env_;
  const MissionRunOptions& options_;
  MissionRun run_;
  // The world: what is known plus what nobody knew.
  const ObstacleSet truth_;
  const ObstacleField truth_field_;
  const WaterVolume truth_volume_;
  Scenario sc_;
  Plant plant_;
  Sonar sonar_;
  ContactMemory contacts_;
  const ObservationOptions observe_;
  const double zone_margin_;
  const ObstacleField known_field_;
  const double max_time_;
  ReactiveMemory memory_;
  PlanTrack plan_track_;
  double plan_speed_ = 0.0;  // the plan's speed where the vehicle was a step ago
  // Mission control's evasions, kept across detections: a contact it plans
  // round is cut into the kept meshes (EvasionPlanner::add). One it only
  // waits on (a later, nearer estimate replaces it) leaves them stale: then
  // they are made again from the chart and the contacts handled.
  std::unique_ptr<EvasionPlanner> evasions_;
  bool evasions_stale_ = true;
  bool reactive_ = false;
  double reactive_until_ = 0.0;
  double pending_at_ = 0.0;  // when the planner's evasion is ready
  Vec2 reactive_target_{0.0, 0.0};
  std::optional<PlannedMission> pending_;         // the evasion planned, spliced in when the planner is done
  std::vector<Vec2> handled_;                     // centres of unknown contacts already reacted to
  std::vector<std::pair<Vec2, double>> waiting_;  // contacts whose evasion could not be planned yet, and when to retry
  double rendezvous_m_ = -1.0;                    // where the reactive level hands back, on the plan of the time
  std::vector<char> held_;
  double held_s_ = 0.0;  // time spent holding (the plant's clock stops meanwhile)
  bool inside_ = false;
  double next_sample_ = 0.0;
  Vec2 last_{0.0, 0.0};
};

}  // namespace

MissionRun run_mission(const Mission& mission, const MissionEnvironment& env, const MissionPlan& initial,
                       const ObstacleSet& unknown, const MissionRunOptions& options) {
  if (initial.basics.empty()) {
    MissionRun run;
    run.plan = initial;
    return run;
  }
  return MissionRunner(mission, env, initial, unknown, options).run();
}

}  // namespace deepguide
