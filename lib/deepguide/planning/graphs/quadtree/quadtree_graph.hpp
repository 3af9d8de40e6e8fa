#pragma once
// The seed's second planning graph: a quadtree over the work area, its free
// leaves' centres as vertices (the seed's Fig. 7), searched with the same
// Boost.Graph search as the visibility graph (graph_search.hpp).
//
// Cells (cell_tree.hpp) are classified from the obstacle field's signed
// clearance d at the cell's centre, which changes by at most the distance
// moved (1-Lipschitz): with r the half diagonal, d - r >= margin makes every
// point of the cell free, d + r < margin every point occupied; anything else
// is mixed and split, and a mixed cell of the minimum size counts as occupied.
// So a free cell really is free, and the graph is conservative near zones.
//
// Edges join neighbouring free leaves across levels: face neighbours always
// (the segment between their centres crosses the shared face, so it stays in
// the two cells), edge and corner neighbours when the obstacle field says the
// segment between the centres is free. Start and goal join the centre of the
// free leaf that holds them (a segment inside one convex free cell), or, when
// their own cell is occupied by the conservative rule, the free cells they
// see among the nearest rings of neighbours; and each other when the straight
// line is free. Cells wholly outside the work area count as occupied: the
// root square reaches past the area's far sides, and a cell straddling the
// edge is split until its centre lies in the area, so every vertex does
// (a route reaches at most half a cell beyond the edge).
//
// `smooth` (plan --smooth) shortcuts the route afterwards: from each anchor
// it jumps to the farthest later waypoint it sees (segment_free), so the
// centre-to-centre zig-zag becomes any-angle legs (string_pulling.hpp; greedy, not
// optimal). Costs other than length are priced per directed edge like the
// visibility graph's (cost_model.hpp).

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/cell_tree.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_options.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/planning/route_graph.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace DEEPGUIDE_API deepguide {

class QuadtreeGraph : public RouteGraph {
 public:
  /// Decomposes the area around the field's obstacles. Throws InputError for a
  /// minimum cell <= 0, an empty or non-finite area, more than max_cells cells,
  /// and an area without a free cell.
  QuadtreeGraph(const ObstacleField& field, const QuadtreeOptions& options);
  /// The same over a field the graph keeps (the registry's, within a turning radius).
  QuadtreeGraph(std::unique_ptr<const ObstacleField> field, const QuadtreeOptions& options);

  /// Cheapest route from start to goal over the free cells (see the header).
  /// Throws NoRouteError when start or goal lies outside the area.
  PlanResult solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel* cost = nullptr,
                   const SearchBudget& budget = {}) override;

  /// For incremental replanning (dstar_lite.hpp): start and goal joined to
  /// the graph as vertices start_vertex() and goal_vertex() until detach()
  /// (or the next attach); returns how many edges joined them.
  std::size_t attach(const PlanningProblem& problem);
  void detach();
  GraphVertex start_vertex() const { return free_.size(); }
  GraphVertex goal_vertex() const { return free_.size() + 1; }
  PlanningGraph& graph() { return graph_; }
  /// A vertex's position: a free cell's centre, or the attached start or goal.
  Vec2 position(GraphVertex v) const;
  /// The directed edges whose segment passes within the margin of one of
  /// `newcomers` (obstacles the sonar found): what a new obstacle blocks.
  std::vector<std::pair<GraphVertex, GraphVertex>> edges_blocked_by(const ObstacleField& newcomers) const;

  const CellTree<2>& tree() const { return *tree_; }
  std::size_t vertex_count() const { return free_.size(); }
  std::size_t edge_count() const { return edges_; }
  double build_ms() const { return build_ms_; }
  /// Graph edges between free cell centres (for drawings).
  std::vector<std::pair<Vec2, Vec2>> edges() const override;

 private:
  const ObstacleField* field_;
  std::unique_ptr<const ObstacleField> own_field_;  // set by the second constructor
  QuadtreeOptions options_;
  std::unique_ptr<CellTree<2>> tree_;
  std::vector<std::size_t> free_;       // graph vertex -> leaf
  std::vector<std::size_t> vertex_of_;  // leaf -> graph vertex (npos: occupied)
  std::vector<Vec2> centres_;           // graph vertex -> its cell's centre (searches ask often)
  PlanningGraph graph_;
  std::array<Vec2, 2> ends_{Vec2::Zero(), Vec2::Zero()};  // the attached start and goal
  struct EdgeIndex;                                       // R-tree of the cell edges' boxes (edges_blocked_by)
  void index_edges();
  std::shared_ptr<const EdgeIndex> edge_index_;
  std::size_t edges_ = 0;
  double build_ms_ = 0.0;
};

/// The registry's entry (`--graph quadtree`): its cells keep out of the
/// turning circles within a turning radius; single queries cover the
/// start-goal box (quadtree_entry.cpp).
GraphEntry quadtree_graph_entry();

}  // namespace deepguide
