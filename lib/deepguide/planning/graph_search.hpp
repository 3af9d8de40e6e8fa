#pragma once
// The one graph search every graph planner uses: Boost.Graph's A* or
// Dijkstra on a planning graph whose vertices have positions. Graphs are
// bidirectional so edge costs may differ by direction (sea currents) and so
// per-query start/goal edges can be removed cheaply again.

#include <boost/graph/adjacency_list.hpp>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/planning/implicit_graph.hpp"
#include "deepguide/planning/route.hpp"  // SearchBudget, SearchStop

namespace DEEPGUIDE_API deepguide {

using PlanningGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, boost::no_property,
                                            boost::property<boost::edge_weight_t, double>>;
using GraphVertex = boost::graph_traits<PlanningGraph>::vertex_descriptor;

enum class SearchAlgorithm { astar, dijkstra };

struct SearchResult {
  bool found = false;
  SearchStop stopped = SearchStop::none;  ///< not none: found is false, and no route is proven missing
  std::vector<GraphVertex> path;          ///< source ... target
  double cost = 0.0;
  std::size_t expanded = 0;  ///< vertices examined (popped from the queue)
};

/// The cost of the directed edge from -> to for a search that reached `from`
/// with cost `label_from` (so a cost may depend on when the vehicle leaves:
/// time-dependent currents); +inf makes the edge unusable.
using EdgeCostFn = std::function<double(GraphVertex from, GraphVertex to, double label_from)>;

/// Cheapest path from source to target. `heuristic(v)` must be admissible and
/// consistent for A* (it is ignored by Dijkstra). Both stop once the target is
/// examined, so the cost is exact for both. Edge costs are the graph's weights,
/// or `edge_cost` when given: it is called lazily, once per edge the search
/// looks at (the search asks more than once; answers are kept). The label of
/// a vertex is final when its edges are looked at, so a time-dependent cost is
/// exact when leaving later never arrives earlier (FIFO: Kaufman & Smith 1993; it holds
/// for legs in a current, see docs/PLANNING.md).
SearchResult shortest_path(const PlanningGraph& graph, GraphVertex source, GraphVertex target,
                           SearchAlgorithm algorithm, const std::function<double(GraphVertex)>& heuristic,
                           const EdgeCostFn& edge_cost = {}, const SearchBudget& budget = {});
/// The same search over a graph found on demand (implicit_graph.hpp); its
/// edges carry their costs.
SearchResult shortest_path(const ImplicitGraph& graph, GraphVertex source, GraphVertex target,
                           SearchAlgorithm algorithm, const std::function<double(GraphVertex)>& heuristic,
                           const SearchBudget& budget = {});

/// "the search stopped after N vertices, its budget" (or "was cancelled after
/// N vertices"): why a graph without a route proves nothing; "" for none.
std::string search_stop_message(SearchStop stop, std::size_t expanded);

/// A graph's answer from its search: found, cost, the vertices expanded and,
/// without a route, why (the stop's message, else `unreachable`). The route's
/// points and the graph's own counts are the caller's to fill in.
PlanResult search_outcome(const SearchResult& found, const std::string& unreachable);

}  // namespace deepguide
