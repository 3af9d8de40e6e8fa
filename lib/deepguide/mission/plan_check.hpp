#pragma once
// The independent checker for a whole mission plan, the basic manoeuvres as
// sailed: every leg of the track (arcs as chords at most 5 cm inside them,
// the corridor widened by that much) against the water volume
// (world/water_volume.hpp): each obstacle's zone (the margin plus half the
// vehicle's width) below its top less the vertical clearance, and the sea
// floor exactly (its lowest gap under each leg). It shares no code with
// mission control's planner (zone polygons and the visibility graph) nor
// with collision observation's first-contact search.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission_environment.hpp"

namespace DEEPGUIDE_API deepguide {

struct MissionPlanCheck {
  bool safe = true;
  std::size_t legs = 0;       ///< legs checked
  double along_m = 0.0;       ///< where the first bad leg begins (when !safe)
  std::size_t basic = 0;      ///< its basic manoeuvre
  Vec3 where{0.0, 0.0, 0.0};  ///< the first bad point (x, y, depth)
  std::string problem;        ///< why, one line ("" when safe)
  /// The smallest floor depth minus the plan's depth (+inf without a floor).
  double min_floor_gap_m = std::numeric_limits<double>::infinity();
};

/// Also fails the plan where the environment's current beats the vehicle
/// (legs_beaten_by_current), after any leg that meets an obstacle or the floor.
MissionPlanCheck check_mission_plan(const MissionPlan& plan, const MissionEnvironment& environment,
                                    const ObservationOptions& options);

/// A basic manoeuvre that no heading holds in the current: at its speed
/// through the water v, along a piece of direction d, v < |d x c| (the
/// current pushes it off sideways) or d.c + sqrt(v^2 - (d x c)^2) <= 0 (it
/// goes backwards). The vehicle then drifts off the track, into whatever
/// lies beside it, and the plan's times are untrue.
struct BeatenLeg {
  std::size_t basic = 0;
  double along_m = 0.0;  ///< where its first such piece begins
  Vec2 where{0.0, 0.0};
};

/// Every basic manoeuvre (lines, arcs as chords of 5 cm) the constant
/// `current` (m/s, local frame) beats, in plan order; none in still water.
std::vector<BeatenLeg> legs_beaten_by_current(const MissionPlan& plan, const Vec2& current);

}  // namespace deepguide
