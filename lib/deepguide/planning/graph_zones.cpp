#include "deepguide/planning/graph_zones.hpp"

#include "deepguide/planning/turn_rounding.hpp"
#include "deepguide/planning/zone_polygons.hpp"

namespace deepguide {

BgMultiPolygon graph_zone_polygons(const GraphBuild& in) {
  const PlannerOptions& o = in.options;
  BgMultiPolygon zones = merged_zone_polygons(in.obstacles, {in.margin, o.tolerance});
  if (o.turn_radius_m > 0.0)
    zones = rounded_zone_polygons(zones, in.obstacles, in.margin, o.turn_radius_m, o.tolerance);
  return zones;
}

PlanResult solve_from_zone_boundary(const PlanningProblem& problem, const std::function<bool(const Vec2&)>& inside,
                                    const std::function<Vec2(const Vec2&)>& closest,
                                    const std::function<PlanResult(const PlanningProblem&)>& solve) {
  PlanningProblem banded = problem;
  const bool start_in_band = inside(problem.start);
  const bool goal_in_band = inside(problem.goal);
  if (start_in_band) banded.start = closest(problem.start);
  if (goal_in_band) banded.goal = closest(problem.goal);
  PlanResult result = solve(banded);
  if (result.found) {
    auto& points = result.route.points;
    if (start_in_band) points.insert(points.begin(), problem.start);
    if (goal_in_band) points.push_back(problem.goal);
  }
  return result;
}

}  // namespace deepguide
