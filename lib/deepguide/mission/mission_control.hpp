#pragma once
// The seed's Mission Control for a planned mission: every part of the plan
// an obstacle or shoal endangers (mission/collision_observation.hpp) is
// either evaded or identified, by the mission's rules (ControlRules), and
// the result is spliced into the plan.
//
// For each conflict in order along the mission:
//   1. Goal-point generation (mission/goal_point.hpp) picks the departure
//      and the rendezvous on the remaining route past the obstacle.
//   2. The evasion's depth is the deepest the plan goes between them; the 2-D
//      planner (mission/evasion_planner.hpp: the visibility graph, or a
//      navigation mesh with `control.evasion_graph: navmesh`) routes at that
//      depth around every obstacle whose top it does not clear and around the
//      sea floor's no-go polygons there (charts/no_go.hpp, from the same sea
//      floor the checkers use). The zone is the corridor (margin + half the
//      vehicle's width) plus 0.2 m, so that arcs drawn as chords and rounding
//      stay outside what observation watches.
//   3. evade: the route's lines replace the stretch; the first line changes
//      depth from the departure's to the evasion's, the last one back to the
//      rendezvous's (both shallower or equal: safe at the evasion's depth).
//      identify: a route to the lap round the object at the identification
//      distance, the lap, and a route on to the rendezvous.
//   4. The new plan is observed again; a route that still meets anything
//      between departure and rendezvous is undone.
// A conflict that cannot be resolved (no route, the danger lasting to the
// mission's end, a hold inside the stretch) is kept with why, and planning
// goes on past it: it is never dropped silently.
// Corners of an evasion stay corners (the autopilot turns at its largest
// rate there): rounding them would cut into the zone it wraps around.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/mission/mission_environment.hpp"

namespace DEEPGUIDE_API deepguide {

class EvasionPlanner;

struct Resolution {
  Conflict conflict;  ///< as observed on the plan of the time (along_m in that plan)
  ControlRules::Reaction reaction = ControlRules::Reaction::evade;
  bool resolved = false;
  double depart_m = 0.0;      ///< along the final plan
  double rendezvous_m = 0.0;  ///< along the final plan (end of the replacement)
  double depth_m = 0.0;       ///< the evasion's depth
  double added_m = 0.0;       ///< length added to the mission
  double time_s = 0.0;        ///< when along the mission the danger began (at the planned speeds and holds)
  std::string problem;        ///< why it is not resolved, one line
  std::string note;  ///< e.g. "evaded with rock-1 (their dangers join)" for a conflict another's stretch took care of
};

struct PlannedMission {
  MissionPlan plan;
  std::vector<Resolution> resolutions;
  std::vector<Conflict> remaining;  ///< what observation still finds on the final plan
};

/// The observation settings of a mission (its margin and clearance).
ObservationOptions observation_options(const Mission& mission);

/// The reaction the rules choose for an obstacle (by id; a sea-floor
/// conflict, or an object that is not an elliptic cylinder, is evaded).
ControlRules::Reaction choose_reaction(const ControlRules& rules, const ObstacleSet& obstacles, std::size_t obstacle);

/// Resolves the conflicts of `initial` (the header) that begin `from_m` or
/// more along it (a vehicle under way replans only what lies ahead of it;
/// evasions leave from there at the earliest).
PlannedMission plan_mission(const Mission& mission, const MissionEnvironment& environment, const MissionPlan& initial,
                            double from_m = 0.0);
/// The same with what `evasions` keeps (its environment, its meshes): a
/// vehicle under way plans again as it finds obstacles without building
/// every depth's mesh anew.
PlannedMission plan_mission(const Mission& mission, EvasionPlanner& evasions, const MissionPlan& initial,
                            double from_m = 0.0);

}  // namespace deepguide
