#pragma once
// The visibility graphs as the registry builds them (`--graph visibility`
// and `visibility-full`): the visibility graph (visibility_graph.hpp) over
// the corners of the zone polygons (graph_zones.hpp).
// A start or goal in the thin band between a zone and its polygon steps to
// the polygon first (solve_from_zone_boundary).

#include <memory>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graphs/visibility/visibility_graph.hpp"

namespace DEEPGUIDE_API deepguide {

class ZoneVisibilityGraph : public RouteGraph {
 public:
  ZoneVisibilityGraph(const GraphBuild& in, VisibilityVariant variant);

  PlanResult solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel* cost,
                   const SearchBudget& budget) override;
  std::vector<std::pair<Vec2, Vec2>> edges() const override { return graph_->edges(); }

  /// The polygons the graph is built over (for drawings).
  const BgMultiPolygon& zones() const { return zones_; }
  const VisibilityGraph& graph() const { return *graph_; }

 private:
  BgMultiPolygon zones_;
  std::unique_ptr<VisibilityGraph> graph_;
};

/// The registry's entry of the reduced (`visibility`) or the seed's full
/// (`visibility-full`) graph.
GraphEntry visibility_graph_entry(VisibilityVariant variant);

}  // namespace deepguide
