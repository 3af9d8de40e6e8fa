#pragma once
// Planning in depth, one query (plan --graph octree): the octree over the
// start-goal box, the volume of the band, the sea floor and the obstacles'
// tops, and the route checked in 3-D. The facade the CLI and other programs
// call; octree_graph.hpp does the work.
//
// The work area is the start-goal box padded by half the start-goal distance
// and at least 10 of the smallest cells each way (as the quadtree's single
// query): a route leaving it would be longer than half the distance again.

#include <memory>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graphs/octree/octree_graph.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

struct DepthPlanOptions {
  double margin = 5.0;        ///< horizontal safety margin to every footprint (m)
  VolumeOptions volume = {};  ///< band and vertical clearance
  OctreeOptions octree = {};  ///< cells, dive angle, smoothing (the area is set here)
  SearchAlgorithm search = SearchAlgorithm::astar;
};

/// The horizontal work area for a query (see the header), for reading the floor before planning.
std::pair<Vec2, Vec2> depth_planning_area(const Vec2& start, const Vec2& goal, const DepthPlanOptions& options);

struct DepthPlan {
  PlanResult result;      ///< route.depth_m holds each waypoint's depth
  DepthRouteCheck check;  ///< the 3-D checker's verdict
  std::size_t cells = 0, free_cells = 0, memory_bytes = 0;
  Vec3 min_cell{0.0, 0.0, 0.0};  ///< the smallest cell: width, width, height
  Vec2 area_min{0.0, 0.0}, area_max{0.0, 0.0};
  /// What the route was planned in, kept for drawings (the cells along the
  /// route's vertical section) and further checks; the graph points into both.
  std::shared_ptr<const SeaFloor> floor;
  std::shared_ptr<const ObstacleField> field;
  std::shared_ptr<const WaterVolume> volume;
  std::shared_ptr<const OctreeGraph> graph;
};

/// Plans from start to goal (x, y local, z depth) over the sea floor (may be null)
/// and the obstacles. Throws what OctreeGraph and WaterVolume throw:
/// InputError for bad options, a start or goal in the floor or outside the
/// band; NoRouteError for one in an obstacle's zone. A search that finds
/// nothing returns result.found == false.
DepthPlan plan_in_depth(const ObstacleSet& obstacles, std::shared_ptr<const SeaFloor> floor, const Vec3& start,
                        const Vec3& goal, const DepthPlanOptions& options);

}  // namespace deepguide
