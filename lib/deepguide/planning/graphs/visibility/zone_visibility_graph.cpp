#include "deepguide/planning/graphs/visibility/zone_visibility_graph.hpp"

#include "deepguide/planning/graph_zones.hpp"

namespace deepguide {

ZoneVisibilityGraph::ZoneVisibilityGraph(const GraphBuild& in, VisibilityVariant variant)
    : zones_(graph_zone_polygons(in)),
      graph_(std::make_unique<VisibilityGraph>(zones_, variant, in.focus, in.options.grid)) {}

PlanResult ZoneVisibilityGraph::solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel* cost,
                                      const SearchBudget& budget) {
  return solve_from_zone_boundary(
      problem, [&](const Vec2& p) { return graph_->strictly_inside(p); },
      [&](const Vec2& p) { return graph_->closest_boundary_point(p); },
      [&](const PlanningProblem& banded) { return graph_->solve(banded, search, cost, budget); });
}

GraphEntry visibility_graph_entry(VisibilityVariant variant) {
  GraphEntry e;
  const bool full = variant == VisibilityVariant::full;
  e.name = full ? GraphKind::visibility_full.name : GraphKind::visibility.name;
  e.help = full ? "the seed's" : "reduced polygon graph";
  e.can = {.weighs_cost = true, .open_water_grid = true, .turn_radius = true, .finished_by_planner = true};
  e.build = [variant](const GraphBuild& in) -> std::unique_ptr<RouteGraph> {
    return std::make_unique<ZoneVisibilityGraph>(in, variant);
  };
  return e;
}

}  // namespace deepguide
