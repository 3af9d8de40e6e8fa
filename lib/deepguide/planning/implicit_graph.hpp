#pragma once
// A graph that Boost.Graph searches without it being stored: out_edges(v)
// asks a function for v's successors and their costs when the search
// expands v. The octree graph uses it (millions of cells, edges found from
// the linear octree on demand), so its queries run the same Boost A* and
// Dijkstra as the stored graphs (graph_search.hpp), with memory for the
// search labels only.
//
// Boost's concepts met: IncidenceGraph (out_edges, source, target,
// out_degree) and VertexListGraph (vertices, num_vertices); vertices are
// 0 .. n - 1, their own index. An edge carries its cost; the successors of
// one expansion live as long as its iterators (a shared buffer).

#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/iterator_facade.hpp>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct ImplicitGraph {
  using Successors = std::vector<std::pair<std::size_t, double>>;  ///< (target, cost)
  std::size_t vertex_count = 0;
  /// Fills `out` (empty on entry) with v's successors.
  std::function<void(std::size_t v, Successors& out)> successors;
};

struct ImplicitEdge {
  std::size_t source = 0, target = 0;
  double cost = 0.0;
  bool operator==(const ImplicitEdge& other) const { return source == other.source && target == other.target; }
};

class ImplicitOutEdgeIterator
    : public boost::iterator_facade<ImplicitOutEdgeIterator, ImplicitEdge, boost::forward_traversal_tag, ImplicitEdge> {
 public:
  ImplicitOutEdgeIterator() = default;
  ImplicitOutEdgeIterator(std::size_t source, std::shared_ptr<const ImplicitGraph::Successors> list, std::size_t at)
      : source_(source), list_(std::move(list)), at_(at) {}

 private:
  friend class boost::iterator_core_access;
  ImplicitEdge dereference() const { return {source_, (*list_)[at_].first, (*list_)[at_].second}; }
  bool equal(const ImplicitOutEdgeIterator& other) const { return at_ == other.at_; }
  void increment() { ++at_; }

  std::size_t source_ = 0;
  std::shared_ptr<const ImplicitGraph::Successors> list_;
  std::size_t at_ = 0;
};

struct ImplicitGraphTraversal : boost::incidence_graph_tag, boost::vertex_list_graph_tag {};

inline std::pair<ImplicitOutEdgeIterator, ImplicitOutEdgeIterator> out_edges(std::size_t v, const ImplicitGraph& g) {
  auto list = std::make_shared<ImplicitGraph::Successors>();
  g.successors(v, *list);
  const std::size_t n = list->size();
  return {ImplicitOutEdgeIterator(v, list, 0), ImplicitOutEdgeIterator(v, list, n)};
}
inline std::size_t out_degree(std::size_t v, const ImplicitGraph& g) {
  ImplicitGraph::Successors list;
  g.successors(v, list);
  return list.size();
}
inline std::size_t source(const ImplicitEdge& e, const ImplicitGraph&) { return e.source; }
inline std::size_t target(const ImplicitEdge& e, const ImplicitGraph&) { return e.target; }
inline std::pair<boost::counting_iterator<std::size_t>, boost::counting_iterator<std::size_t>> vertices(
    const ImplicitGraph& g) {
  return {boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(g.vertex_count)};
}
inline std::size_t num_vertices(const ImplicitGraph& g) { return g.vertex_count; }

}  // namespace deepguide

namespace boost {

template <>
struct graph_traits<deepguide::ImplicitGraph> {
  using vertex_descriptor = std::size_t;
  using edge_descriptor = deepguide::ImplicitEdge;
  using out_edge_iterator = deepguide::ImplicitOutEdgeIterator;
  using vertex_iterator = boost::counting_iterator<std::size_t>;
  using directed_category = directed_tag;
  using edge_parallel_category = disallow_parallel_edge_tag;
  using traversal_category = deepguide::ImplicitGraphTraversal;
  using vertices_size_type = std::size_t;
  using edges_size_type = std::size_t;
  using degree_size_type = std::size_t;
  static vertex_descriptor null_vertex() { return static_cast<std::size_t>(-1); }
};

}  // namespace boost
