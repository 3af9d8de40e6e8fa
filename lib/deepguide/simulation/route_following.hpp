#pragma once
// A planned route sailed by the vehicle: the plan level of the two-level
// guidance (mission_run.hpp) on one route, with the plant, samples,
// statistics and stop rules of the reactive simulation (simulation.hpp), so
// a planner's route and a reactive method's run are measured alike (path
// over ground, energy, clearance, turning rates; evaluation/).
//
// Line-of-sight guidance leg by leg (Fossen's LOS): along the leg a -> b,
// with e the vehicle's signed distance left of it, the course is the leg's
// direction - atan(e / lookahead_m) (default lookahead: the turn radius at
// the reactive speed), at the scenario's reactive speed and depth; the next
// leg is taken once the vehicle is within the lookahead of this one's end
// (the turn starts a turn radius early, as a vehicle rounds a waypoint) or
// past it, measured along it; past the last leg's end it homes on the target. Every leg's field
// leads onto the leg from anywhere, so a hairpin (a leg doubling back, as
// quadtree routes do) is one wide turn; a carrot a fixed distance along the
// route (mission_run.hpp) can sit inside the vehicle's turning circle there
// and be circled for ever. No sonar: the route already avoids
// what the planner knew. The run starts at the scenario's start and ends, by
// the usual rules, at its target (the route's last point); but progress is
// made along the route, which may lead away from the target for a while, so
// the no-progress rule is off and the time limit, unless the scenario sets
// one, is 3 x the route's time + 300 s.

#include "deepguide/planning/route.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace deepguide {

struct RouteFollowing {
  double lookahead_m = 0.0;  ///< 0: the vehicle's turn radius at the reactive speed
  SimulationOptions simulation = {};
};

/// Sails `route` (local frame, from the scenario's start to its target;
/// InputError otherwise). The result's method field is meaningless.
SimulationResult follow_route(const Scenario& scenario, const Route& route, const RouteFollowing& options = {});

}  // namespace deepguide
