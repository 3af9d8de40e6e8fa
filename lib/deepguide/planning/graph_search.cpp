#include "deepguide/planning/graph_search.hpp"

#include <boost/graph/astar_search.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <algorithm>
#include <limits>

namespace deepguide {
namespace {

struct TargetReached {};

// Counts examined vertices and stops the search at the target (Boost's
// documented way to end a search early is to throw from a visitor). One
// template for both searches' visitor bases.
template <class Base>
class StopAtTarget : public Base {
 public:
  StopAtTarget(GraphVertex target, std::size_t& expanded) : target_(target), expanded_(&expanded) {}
  void examine_vertex(GraphVertex v, const PlanningGraph&) const {
    ++*expanded_;
    if (v == target_) throw TargetReached{};
  }

 private:
  GraphVertex target_;
  std::size_t* expanded_;
};

struct Heuristic : public boost::astar_heuristic<PlanningGraph, double> {
  const std::function<double(GraphVertex)>* h;
  double operator()(GraphVertex v) const { return (*h)(v); }
};

}  // namespace

SearchResult shortest_path(const PlanningGraph& graph, GraphVertex source, GraphVertex target,
                           SearchAlgorithm algorithm, const std::function<double(GraphVertex)>& heuristic) {
  const std::size_t n = boost::num_vertices(graph);
  std::vector<GraphVertex> pred(n);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  SearchResult result;
  try {
    if (algorithm == SearchAlgorithm::astar) {
      std::vector<double> rank(n, std::numeric_limits<double>::infinity());
      Heuristic h;
      h.h = &heuristic;
      boost::astar_search(graph, source, h,
                          boost::predecessor_map(pred.data())
                              .distance_map(dist.data())
                              .rank_map(rank.data())
                              .visitor(StopAtTarget<boost::default_astar_visitor>(target, result.expanded)));
    } else {
      boost::dijkstra_shortest_paths(graph, source,
                                     boost::predecessor_map(pred.data())
                                         .distance_map(dist.data())
                                         .visitor(StopAtTarget<boost::default_dijkstra_visitor>(target, result.expanded)));
    }
  } catch (const TargetReached&) {
  }
  // Boost initialises distances to numeric_limits::max() as its infinity.
  if (!(dist[target] < std::numeric_limits<double>::max())) return result;
  result.found = true;
  result.cost = dist[target];
  for (GraphVertex v = target;; v = pred[v]) {
    result.path.push_back(v);
    if (v == source || pred[v] == v) break;
  }
  std::reverse(result.path.begin(), result.path.end());
  return result;
}

}  // namespace deepguide
