#pragma once
// The one contract every planning graph in the plane keeps (graph_registry.hpp
// registers them by name, the Planner solves with them): built once for an
// environment, it answers any number of queries, each with the problem, the
// search and its budget, and the cost; a PlanResult out.
//
// What a graph offers beyond the contract (the quadtree's cells, for D* Lite
// and drawings; the visibility graphs' zone polygons) is reached by type, as
// OMPL's planners are: `planner.graph().as<QuadtreeGraph>()`, null when the
// graph is of another kind.

#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/route.hpp"

namespace DEEPGUIDE_API deepguide {

class RouteGraph {
 public:
  virtual ~RouteGraph() = default;
  /// A route from start to goal, both outside every safety zone (the Planner
  /// has checked), weighed by `cost` when it is not null (else by length;
  /// the Planner gives a graph that prices by length only no other cost);
  /// found == false with a one-line message when the graph has none. Its
  /// searches keep to `budget` (shortest_path takes it; stats.stopped says
  /// when one ran out).
  virtual PlanResult solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel* cost,
                           const SearchBudget& budget) = 0;
  /// Its edges, for drawings (`plan --render-graph`).
  virtual std::vector<std::pair<Vec2, Vec2>> edges() const = 0;

  /// This graph as a T, or null when it is not one.
  template <class T>
  T* as() {
    return dynamic_cast<T*>(this);
  }
  template <class T>
  const T* as() const {
    return dynamic_cast<const T*>(this);
  }

 protected:
  RouteGraph() = default;
  RouteGraph(const RouteGraph&) = default;
  RouteGraph(RouteGraph&&) = default;
  RouteGraph& operator=(const RouteGraph&) = default;
  RouteGraph& operator=(RouteGraph&&) = default;
};

}  // namespace deepguide
