#pragma once
// The two-level guidance of a whole mission in simulation (the seed's Fig. 4).
//
// Plan level: the vehicle follows the planned mission's lines and arcs one
// after another by path following (path_following.hpp: line of sight on the
// leg being followed, the arcs' turning as the autopilot's feed-forward,
// the current crabbed into), at the manoeuvre's speed and depth. Where two
// legs meet at a corner (an evasion's, a track's corner too tight to round)
// the turn begins at the tangent point of a turn of the vehicle's radius.
// A hold (GPS fix, alignment) is sailed by waiting at its point: the clock
// runs on, the vehicle stays.
//
// Reactive level: the forward-looking sonar scans all the while
// (vehicle/sonar.hpp) and its contacts are remembered (contacts.hpp). A contact
// no known obstacle explains (its centre farther than the known footprint's
// semi-major axis + 10 m from every known centre) that endangers the
// remaining plan (collision observation on what lies ahead, the contact as a
// column-filling cylinder) is handed to mission control, which plans the
// evasion (mission_control.hpp, the contact added to the known obstacles)
// for `planning_delay_s`, the planner's time on the vehicle. Where the danger
// is in view ahead (within the sonar's range plus the lead) the reactive
// level has control meanwhile: the geometric construction (reactive/)
// steers towards the rendezvous past it; danger farther along waits for the
// planner. Then the new plan is spliced in and the plan level follows it
// from the vehicle's place on it. When no evasion can be planned the
// reactive level keeps control to the rendezvous, and the run says so loudly.
//
// A contact is a known obstacle when it lies within 10 m of a known footprint
// and is no bigger than it + 10 m. The sonar models elliptic objects only:
// an unknown polygon is never seen.
//
// The vehicle's place on the plan is its place on the leg it follows; the
// legs are taken in order, so laps and tracks that pass near themselves are
// sailed in order. Where the plan changes (an evasion spliced in, the
// rendezvous reached) the leg is the one nearest the vehicle within a window
// (2 m behind the place, 60 m and 15 m ahead of it). When the danger begins before the
// planner could be done, the reactive level alone evades it to the
// rendezvous past it (goal points on the contact) and hands back there; holds
// it cut across are alarms. An evasion that cannot be planned yet, the danger
// still far, is tried again every 10 s as it comes nearer.
//
// The run ends when the vehicle reaches the plan's end (within 5 m; holds
// there are sailed), or at max_time_s. A collision (the vehicle, at its
// simulated depth, inside an obstacle below its top, or under the sea floor)
// does not stop it; each is an event with time and place.

#include <cstdint>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/mission_control.hpp"

namespace DEEPGUIDE_API deepguide {

struct MissionRunOptions {
  double lookahead_m =
      0.0;  ///< the path follower's; 0: 0.3 x the turn radius at the manoeuvre's speed (path_lookahead)
  double planning_delay_s = 5.0;  ///< the evasion planner's time on the vehicle
  double max_time_s = 0.0;        ///< 0: twice the plan's time + 600 s
  std::uint64_t seed = 1;         ///< the sonar's noise
  double sample_every_s = 1.0;    ///< track samples kept (every step is simulated)
};

struct MissionSample {
  double time_s = 0.0;
  Vec2 position{0.0, 0.0};
  double depth_m = 0.0;
  double heading = 0.0;   ///< math rad
  double along_m = 0.0;   ///< the vehicle's place on the plan of the time
  bool reactive = false;  ///< the reactive level had control
};

struct MissionEvent {
  double time_s = 0.0;
  Vec2 where{0.0, 0.0};
  std::string what;    ///< one line
  bool alarm = false;  ///< a collision, or an evasion that could not be planned
};

struct MissionRun {
  bool completed = false;
  bool collided = false;
  double time_s = 0.0;
  double length_m = 0.0;  ///< over ground
  double min_clearance_m =
      0.0;  ///< to the footprints of true obstacles the vehicle is not above (within 100 m; +inf if none)
  std::vector<MissionSample> track;
  std::vector<MissionEvent> events;
  MissionPlan plan;      ///< the plan at the end (with the evasions planned on the way)
  ObstacleSet detected;  ///< unknown objects the sonar found, as their contacts' estimates
  std::size_t replans = 0;
};

/// Runs the mission `plan` (planned: its known conflicts resolved) in the
/// world of `environment` plus `unknown` (the objects nobody knew). Throws
/// InputError for a mission whose current is a field (not simulated yet).
MissionRun run_mission(const Mission& mission, const MissionEnvironment& environment, const MissionPlan& plan,
                       const ObstacleSet& unknown, const MissionRunOptions& options = {});

}  // namespace deepguide
