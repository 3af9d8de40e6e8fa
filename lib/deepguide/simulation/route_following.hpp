#pragma once
// A planned route sailed by the vehicle: the plan level of the two-level
// guidance (mission_run.hpp) on one route, with the plant, samples,
// statistics and stop rules of the reactive simulation (simulation.hpp), so
// a planner's route and a reactive method's run are measured alike (path
// over ground, energy, clearance, turning rates; evaluation/).
//
// Exact lines and arcs (PlanResult::legs, routes within the turning radius)
// are sailed by path following (path_following.hpp: curved-path line of
// sight with the path's turning as the autopilot's feed-forward; lookahead
// 0.3 x the turn radius at the reactive speed, the feed-forward leading by
// V / (2 w_r)): corners are never cut. A polyline (the polygon graphs'
// routes, which still have corners) is sailed leg by leg by line of sight
// with the turn radius as lookahead, the next leg taken within the lookahead
// of this one's end, so a corner is cut as a vehicle rounds a waypoint (a
// hairpin, as quadtree routes have, is one wide turn). Both at the scenario's
// reactive speed and depth, homing on the target past the last leg's end.
// No sonar: the route already avoids what the planner knew. The run starts
// at the scenario's start and ends, by the usual rules, at its target (the
// route's last point); but progress is made along the route, which may lead
// away from the target for a while, so the no-progress rule is off and the
// time limit, unless the scenario sets one, is 3 x the route's time + 300 s.

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace DEEPGUIDE_API deepguide {

/// How far the vehicle strays from a route within route_turn_radius()
/// (basic_manoeuvres.hpp) where its curvature changes: the course reference
/// takes a few seconds to take up or drop a turning rate. Planners whose
/// routes are sailed by follow_route plan with the margin plus this much
/// (measured: docs/SIMULATION.md, "Following a route").
inline constexpr double kPathTrackingAllowance_m = 1.0;

/// The path follower's defaults for a vehicle at `speed_mps` (above):
/// lookahead 0.3 x turn_radius(), and the feed-forward's lead V / (2 w_r),
/// the course reference's time constant in metres of way.
double path_lookahead(const VehicleParams& vehicle, double speed_mps);
double path_lead(const VehicleParams& vehicle, double speed_mps);

struct RouteFollowing {
  double lookahead_m = 0.0;  ///< 0: the default above (for legs, for a polyline)
  double lead_m = -1.0;      ///< PathFollower::lead_m; < 0: the default (route_following.cpp)
  SimulationOptions simulation = {};
};

/// Sails `route` (local frame, from the scenario's start to its target;
/// InputError otherwise). The result's method field is meaningless.
SimulationResult follow_route(const Scenario& scenario, const Route& route, const RouteFollowing& options = {});
/// The same along exact lines and arcs (PlanResult::legs), which must join.
SimulationResult follow_route(const Scenario& scenario, const std::vector<RouteLeg>& legs,
                              const RouteFollowing& options = {});

}  // namespace deepguide
