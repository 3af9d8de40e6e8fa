#pragma once
// D* Lite (Koenig & Likhachev, AAAI 2002; docs/PLANNING.md, "Replanning on new detections"):
// incremental replanning on a planning graph whose edge costs change while
// the vehicle follows its route (a sonar reports an obstacle nobody knew).
//
// The search runs backwards from the goal: g(s) is the cost-to-goal found so
// far and rhs(s) = min over successors s' of c(s, s') + g(s') its one-step
// lookahead (rhs(goal) = 0). Vertices whose g and rhs differ wait in a queue
// ordered by the key [min(g, rhs) + h(start, s) + k_m; min(g, rhs)]
// (lexicographic). When the vehicle moves, k_m grows by h(last, start), so
// the queue keeps its order without re-keying; when an edge's cost changes,
// only the rhs of its tail is repaired and the search resumes from the
// queue: the work is proportional to the part of the graph the change
// touches, not to the graph.
//
// h must be consistent (the planners' c |x - y|). Infinite costs are plain
// +inf (never INT_MAX + c). The graph is the caller's Boost adjacency_list;
// update_edge() writes the new cost into its edge weight, so an A* over the
// same graph afterwards (graph_search.hpp) sees the same costs.
//
// The vehicle's next vertex is the successor s' minimising c(s, s') + g(s');
// ties go to the successor with the smaller g, then the smaller index, so
// a vehicle never steps back onto the vertex it came from while a strictly
// better way exists (the shuttling pitfall of D* variants).

#include <functional>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graph_search.hpp"

namespace DEEPGUIDE_API deepguide {

class DStarLite {
 public:
  using Heuristic = std::function<double(GraphVertex, GraphVertex)>;

  /// Plans from `start` to `goal` on `graph` (kept by reference; it must
  /// outlive this object and keep its vertices).
  DStarLite(PlanningGraph& graph, GraphVertex start, GraphVertex goal, Heuristic heuristic);

  /// Brings g up to date for the current start (ComputeShortestPath). Returns
  /// false when the goal cannot be reached from the start.
  bool compute();
  /// The cost from the current start to the goal (+inf when unreachable); valid after compute().
  /// It is rhs(start): the search stops once the start is no longer
  /// underconsistent, possibly before it settles g(start) (the optimised
  /// loop of the paper's Fig. 4).
  double cost() const { return rhs_[start_]; }
  /// The route the vehicle would follow from the start: greedy on c + g. Empty when unreachable.
  std::vector<GraphVertex> path() const;
  /// The best next vertex from `v` (see the header), or v itself when none leads on.
  GraphVertex next_from(GraphVertex v) const;

  /// The vehicle is now at `v` (call compute() after the edge changes that came with the move).
  void move_to(GraphVertex v);
  /// The directed edge u -> v now costs `cost` (+inf: blocked); the graph's
  /// weight changes too. Returns false when there is no such edge or its cost
  /// was that already.
  bool update_edge(GraphVertex u, GraphVertex v, double cost);

  /// For tests: the first vertex (or none) that breaks D* Lite's invariants:
  /// rhs(s) = min over successors of c + g (s not the goal), and g = rhs for
  /// every vertex out of the queue. Returns -1 when all hold.
  long long first_inconsistent() const;

  GraphVertex start() const { return start_; }
  std::size_t expanded() const { return expanded_; }

 private:
  using Key = std::pair<double, double>;
  struct Entry {
    Key key;
    GraphVertex vertex;
    bool operator>(const Entry& other) const { return key > other.key || (key == other.key && vertex > other.vertex); }
  };
  Key key(GraphVertex s) const;
  void push(GraphVertex u);
  /// Drops stale entries from the top of the heap; false when it is empty.
  bool clean_top();
  void update_vertex(GraphVertex u);
  double edge_cost(GraphVertex u, GraphVertex v) const;
  double best_successor_rhs(GraphVertex u) const;

  PlanningGraph* graph_;
  GraphVertex start_, goal_, last_;
  Heuristic h_;
  double k_m_ = 0.0;
  std::vector<double> g_, rhs_;
  // The queue: a binary min-heap with lazy deletion. A vertex's live entry is
  // the one with its queued_key_ while in_queue_; others are stale and are
  // dropped when they surface (cheaper than a balanced tree's erase).
  std::vector<Entry> heap_;
  std::vector<Key> queued_key_;  // the key a vertex is queued with
  std::vector<bool> in_queue_;
  std::size_t expanded_ = 0;
};

}  // namespace deepguide
