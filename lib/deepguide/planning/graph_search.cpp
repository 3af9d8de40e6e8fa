#include "deepguide/planning/graph_search.hpp"

#include <algorithm>
#include <boost/graph/astar_search.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <limits>
#include <unordered_map>
#include <utility>

namespace deepguide {
namespace {

struct TargetReached {};
struct Stopped {
  SearchStop why;
};

// Counts examined vertices and stops the search at the target, or when the
// budget runs out (Boost's documented way to end a search early is to throw
// from a visitor). One template for both searches' visitor bases.
template <class Base>
class StopAtTarget : public Base {
 public:
  StopAtTarget(GraphVertex target, std::size_t& expanded, const SearchBudget& budget)
      : target_(target), expanded_(&expanded), budget_(&budget) {}
  template <class Graph>
  void examine_vertex(GraphVertex v, const Graph&) const {
    if (v == target_) {
      ++*expanded_;
      throw TargetReached{};
    }
    if (budget_->max_expansions > 0 && *expanded_ >= budget_->max_expansions) throw Stopped{SearchStop::budget};
    if (budget_->cancelled && *expanded_ % 256 == 0 && budget_->cancelled()) throw Stopped{SearchStop::cancelled};
    ++*expanded_;
  }

 private:
  GraphVertex target_;
  std::size_t* expanded_;
  const SearchBudget* budget_;
};

template <class Graph>
struct Heuristic : public boost::astar_heuristic<Graph, double> {
  const std::function<double(GraphVertex)>* h;
  double operator()(GraphVertex v) const { return (*h)(v); }
};

}  // namespace

namespace {

// The one search, for stored and implicit graphs alike.
template <class Graph, class WeightMap>
void run_search(const Graph& graph, GraphVertex source, GraphVertex target, SearchAlgorithm algorithm,
                const std::function<double(GraphVertex)>& heuristic, WeightMap weight, std::vector<GraphVertex>& pred,
                std::vector<double>& dist, const SearchBudget& budget, SearchResult& result) {
  std::size_t& expanded = result.expanded;
  try {
    if (algorithm == SearchAlgorithm::astar) {
      std::vector<double> rank(dist.size(), std::numeric_limits<double>::infinity());
      Heuristic<Graph> h;
      h.h = &heuristic;
      boost::astar_search(graph, source, h,
                          boost::vertex_index_map(boost::typed_identity_property_map<GraphVertex>())
                              .predecessor_map(pred.data())
                              .distance_map(dist.data())
                              .rank_map(rank.data())
                              .weight_map(weight)
                              .visitor(StopAtTarget<boost::default_astar_visitor>(target, expanded, budget)));
    } else {
      boost::dijkstra_shortest_paths(
          graph, source,
          boost::vertex_index_map(boost::typed_identity_property_map<GraphVertex>())
              .predecessor_map(pred.data())
              .distance_map(dist.data())
              .weight_map(weight)
              .visitor(StopAtTarget<boost::default_dijkstra_visitor>(target, expanded, budget)));
    }
  } catch (const TargetReached&) {
  } catch (const Stopped& s) {
    result.stopped = s.why;
  }
}

// The path from the predecessors, when the target was reached.
SearchResult finish(GraphVertex source, GraphVertex target, const std::vector<GraphVertex>& pred,
                    const std::vector<double>& dist, SearchResult& result) {
  // Boost initialises distances to numeric_limits::max() as its infinity.
  if (result.stopped != SearchStop::none || !(dist[target] < std::numeric_limits<double>::max())) return result;
  result.found = true;
  result.cost = dist[target];
  for (GraphVertex v = target;; v = pred[v]) {
    result.path.push_back(v);
    if (v == source || pred[v] == v) break;
  }
  std::reverse(result.path.begin(), result.path.end());
  return result;
}

}  // namespace

SearchResult shortest_path(const PlanningGraph& graph, GraphVertex source, GraphVertex target,
                           SearchAlgorithm algorithm, const std::function<double(GraphVertex)>& heuristic,
                           const EdgeCostFn& edge_cost, const SearchBudget& budget) {
  const std::size_t n = boost::num_vertices(graph);
  std::vector<GraphVertex> pred(n);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  SearchResult result;
  if (!edge_cost) {
    run_search(graph, source, target, algorithm, heuristic, boost::get(boost::edge_weight, graph), pred, dist, budget,
               result);
  } else {
    // Boost reads an edge's weight several times (the negative-weight check,
    // then the relaxation); a priced edge is kept with the label it was priced at.
    using Edge = boost::graph_traits<PlanningGraph>::edge_descriptor;
    std::unordered_map<const void*, std::pair<double, double>> priced;
    const auto weight = [&](const Edge& e) {
      const GraphVertex u = boost::source(e, graph);
      const double label = dist[u];
      auto [it, fresh] = priced.try_emplace(e.get_property(), label, 0.0);
      if (fresh || it->second.first != label) {
        it->second = {label, edge_cost(u, boost::target(e, graph), label)};
      }
      return it->second.second;
    };
    run_search(graph, source, target, algorithm, heuristic, boost::make_function_property_map<Edge, double>(weight),
               pred, dist, budget, result);
  }
  return finish(source, target, pred, dist, result);
}

SearchResult shortest_path(const ImplicitGraph& graph, GraphVertex source, GraphVertex target,
                           SearchAlgorithm algorithm, const std::function<double(GraphVertex)>& heuristic,
                           const SearchBudget& budget) {
  const std::size_t n = graph.vertex_count;
  std::vector<GraphVertex> pred(n);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  SearchResult result;
  const auto weight = [](const ImplicitEdge& e) { return e.cost; };
  run_search(graph, source, target, algorithm, heuristic,
             boost::make_function_property_map<ImplicitEdge, double>(weight), pred, dist, budget, result);
  return finish(source, target, pred, dist, result);
}

std::string search_stop_message(SearchStop stop, std::size_t expanded) {
  switch (stop) {
    case SearchStop::none: return "";
    case SearchStop::budget:
      return "the search stopped after " + std::to_string(expanded) +
             " vertices, its budget; no route is proven missing";
    case SearchStop::cancelled: return "the search was cancelled after " + std::to_string(expanded) + " vertices";
  }
  return "";
}

PlanResult search_outcome(const SearchResult& found, const std::string& unreachable) {
  PlanResult result;
  result.found = found.found;
  result.cost = found.cost;
  result.stats.expanded = found.expanded;
  result.stats.stopped = found.stopped;
  if (!found.found) {
    result.message =
        found.stopped != SearchStop::none ? search_stop_message(found.stopped, found.expanded) : unreachable;
  }
  return result;
}

}  // namespace deepguide
