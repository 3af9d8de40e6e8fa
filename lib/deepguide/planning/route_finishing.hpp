#pragma once
// What a polygon graph's route goes through before the Planner returns it
// (planner.hpp): in a current that changes from place to place, a time or
// energy route refined off the graph's vertices to the continuous optimum
// near it (route_refinement.hpp); within a turning radius, its corners
// rounded on circles of that radius (corner_fillets.hpp). Apart from the
// Planner, so that a graph that wants either can ask for it.

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/planner_options.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace DEEPGUIDE_API deepguide {

/// "the visibility route cannot turn at 20 m at (x, y): `why` (try `graph` tangent)".
std::string unrounded_message(const PlannerOptions& options, const Vec2& at, const std::string& why);

/// The route's corners rounded on options.turn_radius_m, keeping field's
/// margin (close corners joined, a corner too tight cut or merged where the
/// margin allows). False, with result.found false and the message, when a
/// corner cannot be rounded.
bool round_corners(PlanResult& result, const ObstacleField& field, const PlannerOptions& options);

/// Refined where options ask for it (refine, a cost a changing current
/// prices), then rounded within a turning radius; the graph's route stays
/// when the refined one cannot be rounded. False when no route can be rounded.
bool refine_and_round(PlanResult& result, const ObstacleField& field, const PlannerOptions& options);

}  // namespace deepguide
