#pragma once
// Polyanya (Cui, Harabor and Grastien, "Compromise-free Pathfinding on a
// Navigation Mesh", IJCAI 2017): the exact shortest route between two points
// of a navigation mesh (nav_mesh.hpp), by a best-first search over intervals
// of the mesh's edges rather than over a graph.
//
// A search node is a root r and an interval I = [left, right] on one edge,
// every point of which r sees; r is the start or a corner the route turns
// round. g is the length of the shortest route found to r, and
// h = min over p in I of |r p| + |p t|, with the goal t mirrored across I's
// line when it lies on r's side (a route through I cannot reach t without
// crossing the line again). f = g + h never overestimates and never
// decreases from a node to its successors (the paper's lemmas), so the first
// time a route to the goal leaves the open list, it is the shortest.
//
// The mesh's faces here are its convex cells (convex_cells.hpp): the
// triangles merged, so an interval crosses fewer of them on its way.
//
// Expanding a node projects I through the cell beyond it. The part of the
// cell's far edges between the rays r -> left and r -> right is seen from r:
// a successor per far edge with root r ("observable"). What lies beyond a
// ray is seen only by turning round the interval's end, so it becomes a
// successor with that end as root when the end is a corner of the water
// (NavMesh::corner); otherwise the taut route does not turn there, and other
// intervals reach it. A cell that holds the goal adds the final node: the
// goal seen from r, or round an end of I that is a corner.
//
// Root-level pruning (the paper's): a corner reached again with a longer g
// is dropped, and a node whose root has since been reached by a shorter
// route is skipped when popped. An interval that is a single point, or lies
// on a line through its root, leads nowhere a neighbouring interval does not
// and is not generated.
//
// The search keeps its own open list rather than Boost.Graph's A*
// (graph_search.hpp): its nodes are made as it goes, not numbered beforehand.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"
#include "deepguide/planning/route.hpp"

namespace DEEPGUIDE_API deepguide {

struct PolyanyaResult {
  bool found = false;
  std::vector<Vec2> path;  ///< start, the corners turned round, goal
  double length = 0.0;
  std::size_t expanded = 0;  ///< nodes taken from the open list and projected
  std::size_t generated = 0;
  SearchStop stopped = SearchStop::none;  ///< the budget ran out, or the search was cancelled
};

/// The shortest route from start to goal within the mesh's water; found is
/// false when none joins them (or start or goal lies in no face). With
/// `heuristic` false, h is 0: the same route in Dijkstra's order (`--search
/// dijkstra`), for comparison.
PolyanyaResult polyanya(const NavMesh& mesh, const Vec2& start, const Vec2& goal, const SearchBudget& budget = {},
                        bool heuristic = true);

}  // namespace deepguide
