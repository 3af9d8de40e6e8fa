#include "deepguide/planning/graphs/builtin_graphs.hpp"

#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/graphs/octree/octree_graph.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/graphs/tangent/tangent_graph.hpp"
#include "deepguide/planning/graphs/visibility/zone_visibility_graph.hpp"

namespace deepguide {

std::vector<GraphEntry> builtin_graph_entries() {
  return {visibility_graph_entry(VisibilityVariant::reduced),
          visibility_graph_entry(VisibilityVariant::full),
          tangent_graph_entry(),
          nav_mesh_graph_entry(),
          quadtree_graph_entry(),
          octree_graph_entry()};
}

}  // namespace deepguide
