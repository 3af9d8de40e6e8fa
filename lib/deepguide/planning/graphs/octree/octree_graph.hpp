#pragma once
// The seed's quadtree graph in space: an octree over the water volume
// (world/water_volume.hpp: the depth band, the sea floor with its clearance,
// obstacles with their tops), its free leaves' centres as vertices, searched
// with the same Boost.Graph A* / Dijkstra (graph_search.hpp).
//
// Cells and the dive angle. A vehicle cannot go straight up or down; it
// changes depth along legs no steeper than its dive (climb) angle theta. On a
// grid of cubes the only depth-changing moves are 45 deg and steeper, so the
// cells are flattened: the smallest cell is min_cell_m high and
// min_cell_m / min(1, tan theta) wide, and a cell's diagonal to its stacked
// neighbour is exactly theta (45 deg for cubes when theta >= 45 deg). Edges
// steeper than theta are left out, so every leg of a route can be flown.
//
// Classification (conservative, as the quadtree's): a cell is occupied when it
// lies wholly outside the area or the band (one straddling the area's edge
// with its centre outside is split, so every vertex lies in the area), or wholly deeper than the floor's
// deepest point over its footprint less the clearance, or wholly inside one
// obstacle's zone (footprint distance + half diagonal < margin, and its top
// face deeper than the zone's top); free when it lies in the band, above the
// floor's shallowest point less the clearance, and above or beside every
// obstacle's zone; mixed otherwise. Where the floor alone makes a cell mixed
// the obstacles are not looked at (it splits either way), which keeps the
// obstacle queries to the cells above the floor.
//
// The graph is implicit (implicit_graph.hpp): no edge is stored, a cell's
// neighbours come from the linear octree when the search expands it. Face
// neighbours join (their segment stays in the two cells); edge and corner
// neighbours join when the volume says the segment is free. Start and goal
// join the free cells they see among their own cell and the nearest rings of
// neighbours, within the dive angle.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/cell_tree.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/world/water_volume.hpp"

namespace DEEPGUIDE_API deepguide {

struct OctreeOptions {
  double min_cell_m = 1.0;     ///< height of the smallest cell (m), > 0; its width follows the dive angle
  double max_dive_deg = 30.0;  ///< steepest dive or climb, degrees from horizontal, in (0, 90)
  Vec2 area_min{0.0, 0.0};     ///< the horizontal work area (local frame)
  Vec2 area_max{0.0, 0.0};
  bool smooth = false;  ///< shortcut the cell-centre route where the straight leg is free and flyable
  /// Refused above this many cells classified (InputError); a leaf costs
  /// 16 bytes in the tree and 4 in the vertex map.
  std::size_t max_cells = 60'000'000;
};

/// Throws InputError for a minimum cell that is not finite and > 0 or a dive
/// angle outside (0, 90) degrees (the constructor checks the same; callers
/// check first before costly work such as reading a chart).
void validate(const OctreeOptions& options);

class OctreeGraph {
 public:
  /// Decomposes the volume between the band's top and its bottom (or the
  /// floor's deepest point when the band has none). Throws InputError for a
  /// minimum cell <= 0, a dive angle outside (0, 90), an empty area, a volume
  /// with no bottom, more than max_cells cells, and a volume without a free cell.
  OctreeGraph(const WaterVolume& volume, const OctreeOptions& options);

  /// Shortest route from start to goal (x, y local, z depth). Throws
  /// InputError for a start or goal outside the band or in the floor's
  /// clearance (and outside the work area), NoRouteError for one inside an
  /// obstacle's zone. The route's points carry depth_m.
  PlanResult solve(const Vec3& start, const Vec3& goal, SearchAlgorithm algorithm = SearchAlgorithm::astar) const;

  const CellTree<3>& tree() const { return *tree_; }
  std::size_t vertex_count() const { return free_.size(); }
  double build_ms() const { return build_ms_; }
  /// Bytes held by the decomposition (leaves and vertex maps).
  std::size_t memory_bytes() const;
  /// The dive angle's slope tan(theta), and the smallest cell's width and height.
  double max_slope() const { return slope_; }
  Vec3 min_cell() const { return tree_->side(tree_->max_depth()); }

 private:
  Vec3 centre(std::uint32_t vertex) const;
  bool flyable(const Vec3& a, const Vec3& b) const;
  std::vector<std::pair<std::uint32_t, double>> joins(const Vec3& p) const;

  const WaterVolume* volume_;
  OctreeOptions options_;
  double slope_ = 1.0;
  std::unique_ptr<CellTree<3>> tree_;
  std::vector<std::uint32_t> free_;       // graph vertex -> leaf
  std::vector<std::uint32_t> vertex_of_;  // leaf -> graph vertex (kNone: occupied)
  double build_ms_ = 0.0;
};

/// The registry's entry (`--graph octree`): a name, a phrase and `in_depth`;
/// no build function, for it plans in depth (depth_planning.hpp).
GraphEntry octree_graph_entry();

}  // namespace deepguide
