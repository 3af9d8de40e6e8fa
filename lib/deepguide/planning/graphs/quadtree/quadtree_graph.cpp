#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_set>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/string_pulling.hpp"

namespace deepguide {
namespace {

constexpr std::size_t kNoVertex = static_cast<std::size_t>(-1);
constexpr int kMaxDepth = 24;
constexpr int kAttachRings = 4;

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

QuadtreeGraph::QuadtreeGraph(std::unique_ptr<const ObstacleField> field, const QuadtreeOptions& options)
    : QuadtreeGraph(*field, options) {
  own_field_ = std::move(field);
}

QuadtreeGraph::QuadtreeGraph(const ObstacleField& field, const QuadtreeOptions& options)
    : field_(&field), options_(options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(options.min_cell_m > 0.0) || !std::isfinite(options.min_cell_m)) {
    throw InputError("`min_cell_m`: expected a cell size > 0 m, got " + general(options.min_cell_m));
  }
  const Vec2 extent = options.area_max - options.area_min;
  if (!options.area_min.allFinite() || !options.area_max.allFinite() || !(extent.minCoeff() > 0.0)) {
    throw InputError("quadtree: expected a work area with a positive, finite extent");
  }
  // The root: a square of min_cell * 2^depth over the area (compared in
  // doubles first: a tiny cell over a wide area overflows an int).
  const double need = extent.maxCoeff() / options.min_cell_m;
  if (!(need < std::ldexp(1.0, kMaxDepth))) {
    throw InputError("`min_cell_m`: " + general(options.min_cell_m) + " m over a " + general(extent.maxCoeff()) +
                     " m area needs more than " + std::to_string(kMaxDepth) + " levels; give a larger cell");
  }
  // Strictly more than the extent: cells are half-open, and a point on the
  // area's far side must still lie in a cell.
  const int depth = std::max(0, static_cast<int>(std::floor(std::log2(need))) + 1);
  const double root = std::ldexp(options.min_cell_m, depth);
  std::size_t cells = 0;
  const double margin = field.margin();
  const auto classify = [&](const CellTree<2>::Box& box) {
    if (++cells > options.max_cells) {
      throw InputError("`min_cell_m`: " + general(options.min_cell_m) + " m cells over this area make more than " +
                       std::to_string(options.max_cells) + " cells; give a larger cell or a smaller area");
    }
    // The root square reaches past the area on its far sides: cells wholly
    // out of the area are occupied, and a cell that straddles its edge with
    // its centre outside is split (a mixed cell of the minimum size is then
    // occupied), so every vertex lies in the area. Straddling cells with
    // their centre inside stay whole: lining the edge with a band of minimum
    // cells would serve nothing.
    if ((box.min.array() >= options.area_max.array()).any()) return CellState::occupied;
    if ((box.centre().array() > options.area_max.array()).any()) return CellState::mixed;
    const double d = field.clearance(box.centre());
    const double r = 0.5 * (box.max - box.min).norm();
    if (d - r >= margin) return CellState::free;
    if (d + r < margin) return CellState::occupied;
    return CellState::mixed;
  };
  tree_ = std::make_unique<CellTree<2>>(options.area_min, root, depth, classify);

  const auto& leaves = tree_->leaves();
  vertex_of_.assign(leaves.size(), kNoVertex);
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    if (leaves[i].state != CellState::free) continue;
    vertex_of_[i] = free_.size();
    free_.push_back(i);
    centres_.push_back(tree_->box(i).centre());
  }
  if (free_.empty()) {
    throw InputError("quadtree: no free cell in the work area (every cell lies within " + general(margin) +
                     " m of an obstacle)");
  }
  graph_ = PlanningGraph(free_.size() + 2);  // + start and goal
  for (std::size_t v = 0; v < free_.size(); ++v) {
    const std::size_t leaf = free_[v];
    const Vec2 a = centres_[v];
    for (const auto& [other, face] : tree_->neighbours(leaf)) {
      const std::size_t w = vertex_of_[other];
      if (w == kNoVertex || w < v) continue;  // occupied, or the pair is done from the other side
      const Vec2 b = tree_->box(other).centre();
      if (!face && !field.segment_free(a, b)) continue;
      const double len = (b - a).norm();
      boost::add_edge(v, w, len, graph_);
      boost::add_edge(w, v, len, graph_);
      ++edges_;
    }
  }
  index_edges();
  build_ms_ = elapsed_ms(t0);
}

Vec2 QuadtreeGraph::position(GraphVertex v) const {
  if (v < free_.size()) return centres_[v];
  return v == start_vertex() ? ends_[0] : ends_[1];
}

std::size_t QuadtreeGraph::attach(const PlanningProblem& problem) {
  const GraphVertex sv = start_vertex(), gv = goal_vertex();
  detach();
  ends_ = {problem.start, problem.goal};
  std::size_t attached = 0;
  // Start and goal: their own free cell, else the free neighbours they see.
  for (const auto& [point, vertex, name] :
       {std::tuple{problem.start, sv, "the start"}, std::tuple{problem.goal, gv, "the goal"}}) {
    const std::optional<std::size_t> leaf = tree_->locate(point);
    if (!leaf) throw NoRouteError(std::string(name) + " lies outside the quadtree's work area");
    std::vector<std::size_t> joins;
    if (vertex_of_[*leaf] != kNoVertex) {
      joins.push_back(vertex_of_[*leaf]);
    } else {
      // Its own cell is occupied by the conservative rule (the point itself
      // is free: the planner checked): the free cells it sees, ring by ring
      // outwards through the neighbours, until a ring has some (at most
      // kAttachRings rings; a free neighbour may be two cells away where a
      // zone's edge runs along the grid).
      std::vector<std::size_t> ring{*leaf};
      std::unordered_set<std::size_t> seen{*leaf};
      for (int r = 0; r < kAttachRings && joins.empty() && !ring.empty(); ++r) {
        std::vector<std::size_t> next;
        for (std::size_t cell : ring) {
          for (const auto& [other, face] : tree_->neighbours(cell)) {
            if (!seen.insert(other).second) continue;
            next.push_back(other);
            const std::size_t w = vertex_of_[other];
            if (w != kNoVertex && field_->segment_free(point, tree_->box(other).centre())) joins.push_back(w);
          }
        }
        ring = std::move(next);
      }
    }
    for (std::size_t w : joins) {
      const double len = (position(w) - point).norm();
      if (vertex == sv)
        boost::add_edge(sv, w, len, graph_);
      else
        boost::add_edge(w, gv, len, graph_);
      ++attached;
    }
  }
  if (field_->segment_free(problem.start, problem.goal)) {
    boost::add_edge(sv, gv, (problem.goal - problem.start).norm(), graph_);
    ++attached;
  }
  return attached;
}

void QuadtreeGraph::detach() {
  boost::clear_vertex(start_vertex(), graph_);
  boost::clear_vertex(goal_vertex(), graph_);
}

PlanResult QuadtreeGraph::solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel* cost,
                                const SearchBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = free_.size();
  const GraphVertex sv = start_vertex(), gv = goal_vertex();
  const Vec2 g = problem.goal;
  const std::size_t attached = attach(problem);
  const auto position = [this](GraphVertex v) { return this->position(v); };
  if (cost != nullptr && cost->kind == CostKind::length) cost = nullptr;
  const double per_metre = cost != nullptr ? cost_per_metre_lower_bound(*cost) : 1.0;
  const std::function<double(GraphVertex)> h = [&](GraphVertex v) { return per_metre * (position(v) - g).norm(); };
  EdgeCostFn priced;
  if (cost != nullptr) {
    priced = [&](GraphVertex from, GraphVertex to, double label) {
      return edge_weight(*cost, price_leg(*cost, position(from), position(to), departure_after(*cost, label)));
    };
  }
  const SearchResult found = shortest_path(graph_, sv, gv, algorithm, h, priced, budget);
  detach();

  PlanResult result =
      search_outcome(found, "the goal cannot be reached from the start through the quadtree's free cells");
  result.stats.graph_vertices = n + 2;
  result.stats.graph_edges = edges_ + attached;
  result.stats.build_ms = build_ms_;
  if (!found.found) {
    result.stats.query_ms = elapsed_ms(t0);
    return result;
  }
  std::vector<Vec2> points;
  for (GraphVertex v : found.path) points.push_back(position(v));
  if (options_.smooth && points.size() > 2) {
    const auto sees = [this](const Vec2& a, const Vec2& b) { return field_->segment_free(a, b); };
    // Greedy jumps, then corners cut until the route is taut round the zones
    // (string_pulling.hpp): a large cell's centre beyond the goal that the
    // start sees would otherwise leave a V to the goal.
    const std::vector<Vec2> pulled = tighten_string(pull_string(points, sees), sees);
    // Shorter is not always cheaper in a current: keep the pulled route only if it costs no more.
    const double pulled_cost = cost != nullptr ? price_route(*cost, pulled).cost : Route{pulled}.length();
    if (pulled_cost <= result.cost) {
      points = std::move(pulled);
      result.cost = pulled_cost;
    }
  }
  result.route.points = std::move(points);
  result.stats.query_ms = elapsed_ms(t0);
  return result;
}

struct QuadtreeGraph::EdgeIndex {
  using Item = std::pair<BgBox, std::pair<GraphVertex, GraphVertex>>;
  boost::geometry::index::rtree<Item, boost::geometry::index::rstar<16>> tree;
};

// The cell edges (both directions of a pair share one box) in an R-tree, for
// edges_blocked_by; start and goal edges change with every attach and are few.
void QuadtreeGraph::index_edges() {
  std::vector<EdgeIndex::Item> items;
  for (auto [it, end] = boost::edges(graph_); it != end; ++it) {
    const GraphVertex a = boost::source(*it, graph_), b = boost::target(*it, graph_);
    if (a > b || b >= free_.size()) continue;
    const Vec2 p = position(a), q = position(b);
    items.push_back({BgBox(to_bg(p.cwiseMin(q)), to_bg(p.cwiseMax(q))), {a, b}});
  }
  auto index = std::make_shared<EdgeIndex>();
  index->tree = decltype(index->tree)(items);  // bulk load (packing)
  edge_index_ = std::move(index);
}

std::vector<std::pair<GraphVertex, GraphVertex>> QuadtreeGraph::edges_blocked_by(const ObstacleField& newcomers) const {
  namespace bgi = boost::geometry::index;
  // A box around the newcomers' zones: only edges whose box meets it can be blocked.
  auto [lo, hi] = footprint_box(newcomers.obstacles());
  lo -= Vec2::Constant(newcomers.margin());
  hi += Vec2::Constant(newcomers.margin());
  std::vector<std::pair<GraphVertex, GraphVertex>> out;
  std::vector<EdgeIndex::Item> near;
  edge_index_->tree.query(bgi::intersects(BgBox(to_bg(lo), to_bg(hi))), std::back_inserter(near));
  for (const auto& [box, ends] : near) {
    if (newcomers.segment_free(position(ends.first), position(ends.second))) continue;
    out.emplace_back(ends.first, ends.second);
    out.emplace_back(ends.second, ends.first);
  }
  // Start and goal edges: the attached ones (none when detached).
  for (GraphVertex end : {start_vertex(), goal_vertex()}) {
    for (auto [it, stop] = boost::out_edges(end, graph_); it != stop; ++it) {
      const GraphVertex t = boost::target(*it, graph_);
      if (!newcomers.segment_free(position(end), position(t))) out.emplace_back(end, t);
    }
    for (auto [it, stop] = boost::in_edges(end, graph_); it != stop; ++it) {
      const GraphVertex f = boost::source(*it, graph_);
      if (f >= free_.size()) continue;  // start -> goal, seen above
      if (!newcomers.segment_free(position(f), position(end))) out.emplace_back(f, end);
    }
  }
  return out;
}

std::vector<std::pair<Vec2, Vec2>> QuadtreeGraph::edges() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  for (auto [it, end] = boost::edges(graph_); it != end; ++it) {
    const GraphVertex a = boost::source(*it, graph_), b = boost::target(*it, graph_);
    if (a < b && b < free_.size()) out.emplace_back(position(a), position(b));
  }
  return out;
}

}  // namespace deepguide
