#include "deepguide/planning/depth_planning.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {

std::pair<Vec2, Vec2> depth_planning_area(const Vec2& start, const Vec2& goal, const DepthPlanOptions& options) {
  const double slope = std::tan(options.octree.max_dive_deg * M_PI / 180.0);
  const double width = options.octree.min_cell_m / std::min(1.0, slope);
  const double pad = std::max(0.5 * (goal - start).norm(), 10.0 * (std::isfinite(width) ? width : 0.0));
  return {start.cwiseMin(goal) - Vec2::Constant(pad), start.cwiseMax(goal) + Vec2::Constant(pad)};
}

DepthPlan plan_in_depth(const ObstacleSet& obstacles, std::shared_ptr<const SeaFloor> floor, const Vec3& start,
                        const Vec3& goal, const DepthPlanOptions& options) {
  DepthPlan plan;
  std::tie(plan.area_min, plan.area_max) = depth_planning_area(start.head<2>(), goal.head<2>(), options);
  plan.field = std::make_shared<const ObstacleField>(obstacles, options.margin);
  plan.floor = std::move(floor);
  plan.volume = std::make_shared<const WaterVolume>(*plan.field, plan.floor.get(), options.volume);
  OctreeOptions octree = options.octree;
  octree.area_min = plan.area_min;
  octree.area_max = plan.area_max;
  plan.graph = std::make_shared<const OctreeGraph>(*plan.volume, octree);
  plan.cells = plan.graph->tree().leaves().size();
  plan.free_cells = plan.graph->vertex_count();
  plan.memory_bytes = plan.graph->memory_bytes();
  plan.min_cell = plan.graph->min_cell();
  plan.result = plan.graph->solve(start, goal, options.search);
  if (plan.result.found) plan.check = check_route_in_depth(plan.result.route, *plan.volume, octree.max_dive_deg);
  return plan;
}

}  // namespace deepguide
