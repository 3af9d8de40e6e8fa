#pragma once
// Editing a plan of basic manoeuvres by distance along the mission: where it
// is at a given distance, and the plan with a stretch of it replaced (an
// evasive route spliced in between its departure and its rendezvous).
//
// Cutting a line keeps its straight track and interpolates its depth;
// cutting an arc keeps its circle. Points (holds) have no length: one at the
// stretch's start stays before the replacement, one at its end stays after.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"

namespace DEEPGUIDE_API deepguide {

/// Where the plan is `along_m` metres along the mission.
struct PlanPosition {
  std::size_t basic = 0;  ///< the basic manoeuvre sailing there (the last one at the end)
  Vec2 xy{0.0, 0.0};
  double depth_m = 0.0;
  double speed_mps = 0.0;
  double time_s = 0.0;  ///< since the mission's start, at the planned speeds and holds
};
PlanPosition position_at(const MissionPlan& plan, double along_m);

/// Whether a point manoeuvre (a hold: a GPS fix, an alignment) lies strictly
/// inside (from_m, to_m): replacing that stretch would drop it.
bool holds_within(const MissionPlan& plan, double from_m, double to_m);

/// The plan with [from_m, to_m] replaced by `replacement`, which must run
/// from the plan's position at from_m to its position at to_m (its first
/// `from` and last `to`; its start_m values are set here). Distances along
/// are renumbered. Precondition: !holds_within(plan, from_m, to_m).
MissionPlan splice_plan(const MissionPlan& plan, double from_m, double to_m, std::vector<BasicManoeuvre> replacement);

}  // namespace deepguide
