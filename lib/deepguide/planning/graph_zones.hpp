#pragma once
// The polygons the polygon graphs (visibility, navmesh) plan around: the
// safety zones merged into polygons that enclose them by at most the
// tolerance (zone_polygons.hpp) and, within a turning radius, widened to hold
// the turning circles (turn_rounding.hpp), so the Planner can round every
// corner of the route (route_finishing.hpp).

#include <functional>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/planning/graph_registry.hpp"

namespace DEEPGUIDE_API deepguide {

BgMultiPolygon graph_zone_polygons(const GraphBuild& in);

/// A start or goal outside the true zone can still lie in the thin band
/// between a zone and the polygon round it (`inside`: strictly inside some
/// polygon): the query steps along the shortest way to the polygon's
/// boundary (`closest`) first, `solve` plans from there, and the route keeps
/// the steps.
PlanResult solve_from_zone_boundary(const PlanningProblem& problem, const std::function<bool(const Vec2&)>& inside,
                                    const std::function<Vec2(const Vec2&)>& closest,
                                    const std::function<PlanResult(const PlanningProblem&)>& solve);

}  // namespace deepguide
