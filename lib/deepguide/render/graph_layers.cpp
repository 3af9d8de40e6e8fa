#include "deepguide/render/graph_layers.hpp"

#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/graphs/visibility/zone_visibility_graph.hpp"

namespace deepguide {

void add_graph_layers(const Planner& planner, RouteScene& scene) {
  if (const auto* quadtree = planner.graph().as<QuadtreeGraph>()) {
    const CellTree<2>& tree = quadtree->tree();
    for (const auto& leaf : tree.leaves()) {
      auto& cells = leaf.state == CellState::free ? scene.free_cells : scene.occupied_cells;
      const auto box = tree.box(leaf);
      cells.emplace_back(box.min, box.max);
    }
  }
  if (const auto* visibility = planner.graph().as<ZoneVisibilityGraph>()) {
    if (!visibility->zones().empty()) scene.zone_polygons = &visibility->zones();
  }
  scene.graph_edges = planner.graph_edges();
}

}  // namespace deepguide
