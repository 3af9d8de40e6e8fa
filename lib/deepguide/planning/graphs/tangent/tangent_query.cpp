// A query on the tangent graph: start and goal (and their heading circles)
// joined to the environment's graph within a growing informed bound, the one
// search, and the path turned into the route's exact legs.

#include <algorithm>
#include <functional>
#include <iterator>
#include <numbers>
#include <optional>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graphs/tangent/tangent_graph_impl.hpp"
#include "deepguide/planning/informed_bound.hpp"

namespace deepguide {

using tangent_detail::elapsed_ms;
using tangent_detail::orientation;
using tangent_detail::unit;

namespace {

// The first informed bound (informed_bound.hpp): a little more than the straight line.
constexpr double kFirstBoundStretch = 1.05;

}  // namespace

// What one query adds to the environment's graph (edges, spare vertices, the
// ends' heading circles as pieces) comes out again when it ends, however it
// ends: the graph is searched in place instead of copied.
struct TangentGraph::Impl::Query {
  Impl& m;
  const PlanningProblem& problem;
  Vec2 s, g;  // start and goal in the shifted frame
  std::size_t env_pieces;
  std::vector<std::size_t> used;  // spare vertices taken
  std::vector<Node> end_nodes;    // the ends' own points on their heading circles
  std::vector<Arc> arcs;          // the query's own arcs, and their index
  std::unordered_map<std::uint64_t, std::size_t> arc_of;

  Query(Impl& impl, const PlanningProblem& p)
      : m(impl), problem(p), s(p.start - impl.origin), g(p.goal - impl.origin), env_pieces(impl.pieces.size()) {
    m.nodes[0].p = s;
    m.nodes[1].p = g;
  }
  ~Query() {
    clean();
    m.pieces.resize(env_pieces);
    m.piece_names.resize(env_pieces);
    m.needs_arc_check.resize(env_pieces);
    m.on_piece.resize(env_pieces);
    m.end_way.resize(env_pieces);
    m.end_is_start.resize(env_pieces);
  }
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;

  void clean() {
    boost::clear_vertex(0, m.base);
    boost::clear_vertex(1, m.base);
    for (std::size_t v : used) boost::clear_vertex(v, m.base);
    used.clear();
    m.nodes.resize(m.env_nodes);
    arcs.clear();
    arc_of.clear();
  }

  std::size_t new_vertex(const Node& n) {
    const std::size_t v = m.nodes.size();
    if (v >= boost::num_vertices(m.base)) boost::add_vertex(m.base);  // stays, isolated, for later queries
    m.nodes.push_back(n);
    used.push_back(v);
    return v;
  }

  // Dubins ends. On the circle through p turning `way` round (left of the
  // heading for anticlockwise), p's outward normal is heading - way pi/2.
  void add_end_circles() {
    for (const bool at_start : {true, false}) {
      const std::optional<double>& heading = at_start ? problem.start_heading : problem.goal_heading;
      if (!heading) continue;
      if (!(m.heading_radius > 0.0) || !std::isfinite(*heading)) {
        throw InputError("a start or goal heading: expected a finite angle and a turning radius > 0");
      }
      const Vec2 p = at_start ? s : g;
      for (const int way : {+1, -1}) {
        ZonePiece z;
        z.kind = ZonePiece::Kind::capsule;
        z.a = z.b = p + m.heading_radius * unit(*heading + way * std::numbers::pi / 2.0);
        z.margin = m.heading_radius;
        m.pieces.push_back(z);
        m.piece_names.push_back(at_start ? "start heading" : "goal heading");
        m.needs_arc_check.push_back(true);
        m.on_piece.emplace_back();
        m.end_way.push_back(way);
        m.end_is_start.push_back(at_start);
        end_nodes.push_back(Node{m.pieces.size() - 1, wrap_two_pi(*heading - way * std::numbers::pi / 2.0), p, way});
      }
    }
  }

  // A tangent point within rounding of its end's own point is that point, so
  // the route goes straight on instead of once round the circle.
  Node snapped(Node n) const {
    for (const Node& e : end_nodes) {
      if (e.piece == n.piece && std::abs(wrap_pi(n.phi - e.phi)) < 1e-9) {
        n.phi = e.phi;
        n.p = e.p;
      }
    }
    return n;
  }

  // Start and goal without a heading: their tangents to the pieces within
  // the bound, away from the start and towards the goal.
  void join_ends(const std::vector<double>& low, double bound, std::vector<std::vector<std::size_t>>& added) {
    for (std::size_t end = 0; end < 2; ++end) {
      if (end == 0 ? problem.start_heading.has_value() : problem.goal_heading.has_value()) continue;
      std::vector<Segment> tangents;
      m.add_point_tangents(end == 0 ? s : g, tangents, low, bound);
      for (const Segment& seg : tangents) {
        // A point on the boundary itself may go either way round.
        const Vec2 d = end == 0 ? Vec2(seg.b.p - seg.a.p) : Vec2(seg.a.p - seg.b.p);
        const double w = d.norm();
        const std::vector<int> ways = m.one_way ? std::vector<int>{0}
                                      : w > 0.0 ? std::vector<int>{orientation(unit(seg.b.phi), d)}
                                                : std::vector<int>{+1, -1};
        for (int orient : ways) {
          const int way = m.end_way[seg.b.piece];
          if (way != 0 && orient != way) continue;  // the other end's circle, sailed the wrong way round
          Node n = snapped(seg.b);
          n.orient = orient;
          const std::size_t v = new_vertex(n);
          added[seg.b.piece].push_back(v);
          if (end == 0) {
            boost::add_edge(0, v, w, m.base);
          } else {
            boost::add_edge(v, 1, w, m.base);
          }
        }
      }
    }
  }

  // An end with a heading is on its circles, and leaves (is reached) along
  // them; the circles' tangents to the pieces within the bound, and from the
  // start's to the goal's, each kept the way round its end circle goes.
  void join_end_circles(const std::vector<double>& low, double bound, std::vector<std::vector<std::size_t>>& added) {
    for (const Node& e : end_nodes) {
      const std::size_t v = new_vertex(e);
      added[e.piece].push_back(v);
      if (m.end_is_start[e.piece]) {
        boost::add_edge(0, v, 0.0, m.base);
      } else {
        boost::add_edge(v, 1, 0.0, m.base);
      }
    }
    for (std::size_t q = env_pieces; q < m.pieces.size(); ++q) {
      for (std::size_t j = 0; j < m.pieces.size(); ++j) {
        // A goal circle's tangents with the start's circles are found from those.
        const bool other_end = j >= env_pieces;
        if (other_end ? !(m.end_is_start[q] && !m.end_is_start[j]) : low[j] > bound) continue;
        std::vector<Segment> segs;
        m.common_tangents(q, j, segs);
        for (const Segment& seg : segs) {
          const Vec2 d = seg.b.p - seg.a.p;
          const int oa = orientation(unit(seg.a.phi), d), ob = orientation(unit(seg.b.phi), d);
          // From q to j, departing q oa round and reaching j ob round; or back, -ob and -oa.
          const bool forward = m.end_is_start[q];
          if (forward ? oa != m.end_way[q] || (other_end && ob != m.end_way[j]) : -oa != m.end_way[q]) continue;
          Node a = snapped(seg.a), b = snapped(seg.b);
          a.orient = forward ? oa : -oa;
          b.orient = forward ? ob : -ob;
          const std::size_t va = new_vertex(a), vb = new_vertex(b);
          added[q].push_back(va);
          added[j].push_back(vb);
          if (forward) {
            boost::add_edge(va, vb, d.norm(), m.base);
          } else {
            boost::add_edge(vb, va, d.norm(), m.base);
          }
        }
      }
    }
  }

  // New tangent points split the pieces' arcs: join them to their neighbours.
  void split_arcs(std::vector<std::vector<std::size_t>>& added) {
    for (std::size_t i = 0; i < m.pieces.size(); ++i) {
      if (added[i].empty()) continue;
      // The piece's own vertices are sorted once, at the build: only the
      // query's few are sorted here (a full sort per piece and query was an
      // eighth of the prebuilt solve).
      const auto by_phi = [&](std::size_t x, std::size_t y) { return m.nodes[x].phi < m.nodes[y].phi; };
      std::sort(added[i].begin(), added[i].end(), by_phi);
      std::vector<std::size_t> ids;
      ids.reserve(m.on_piece[i].size() + added[i].size());
      std::merge(m.on_piece[i].begin(), m.on_piece[i].end(), added[i].begin(), added[i].end(), std::back_inserter(ids),
                 by_phi);
      m.add_arcs(
          i, ids, m.nodes, [&](std::size_t a, std::size_t b) { return a >= m.env_nodes || b >= m.env_nodes; }, m.base,
          arcs, arc_of);
    }
  }

  // The arc the search took from u to v (two tangent points of one piece are
  // joined only by arcs; the indexes hold the cheaper one), or null for a line.
  const Arc* arc_between(std::size_t u, std::size_t v) const {
    const Node& a = m.nodes[u];
    if (a.piece == kNoPiece || a.piece != m.nodes[v].piece) return nullptr;
    const Arc* arc = nullptr;
    if (auto it = arc_of.find(Impl::key(u, v)); it != arc_of.end()) arc = &arcs[it->second];
    if (auto it = m.arc_of.find(Impl::key(u, v)); it != m.arc_of.end() && (!arc || m.arcs[it->second].w < arc->w)) {
      arc = &m.arcs[it->second];
    }
    return arc;
  }

  // The path's legs (lines, and arcs along the pieces) and points, unshifted.
  void trace(const std::vector<std::size_t>& path, PlanResult& result) const {
    std::vector<Vec2>& pts = result.route.points;
    pts.push_back(s + m.origin);
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      const Node& a = m.nodes[path[k]];
      const Node& b = m.nodes[path[k + 1]];
      if (const Arc* arc = arc_between(path[k], path[k + 1])) {
        const int turn = arc->turn;
        double phi_to = b.phi;
        if (turn > 0) {
          while (phi_to < a.phi) phi_to += kTwoPi;
        } else {
          while (phi_to > a.phi) phi_to -= kTwoPi;
        }
        for (RouteLeg& part : m.arc_legs(a.piece, a.phi, phi_to, turn, a.p, b.p)) {
          result.exact_length_m += part.length_m;
          result.legs.push_back(std::move(part));
        }
        for (const Vec2& q : m.arc_polyline(a.piece, a.phi, phi_to, turn)) pts.push_back(q + m.origin);
      } else {
        RouteLeg leg;
        leg.from = a.p + m.origin;
        leg.to = b.p + m.origin;
        leg.length_m = (b.p - a.p).norm();
        result.exact_length_m += leg.length_m;
        result.legs.push_back(leg);
      }
      pts.push_back(b.p + m.origin);
    }
    // Drop repeated points (zero-length legs at touching pieces).
    pts.erase(std::unique(pts.begin(), pts.end(), [](const Vec2& x, const Vec2& y) { return (x - y).norm() < 1e-12; }),
              pts.end());
  }
};

namespace {

// One arc per turn round one curve: the tangent points a route passes on a
// piece split its turn into arcs that continue one another. Arcs of no
// length (a tangent that only touches a piece, an end's step onto its
// circle) go, and the lines on either side become one.
std::vector<RouteLeg> merged_legs(std::vector<RouteLeg> in) {
  std::vector<RouteLeg> legs;
  for (RouteLeg& leg : in) {
    if (leg.length_m < 1e-9) continue;
    if (!legs.empty() && leg.kind == RouteLeg::Kind::line && legs.back().kind == RouteLeg::Kind::line) {
      RouteLeg& prev = legs.back();
      const Vec2 d0 = prev.to - prev.from, d1 = leg.to - leg.from;
      if (std::abs(d0.x() * d1.y() - d0.y() * d1.x()) <= 1e-9 * d0.norm() * d1.norm() && d0.dot(d1) > 0.0) {
        prev.to = leg.to;
        prev.length_m = (prev.to - prev.from).norm();
        continue;
      }
    }
    if (!legs.empty() && leg.kind == RouteLeg::Kind::arc && legs.back().kind == RouteLeg::Kind::arc) {
      RouteLeg& prev = legs.back();
      const Ellipse &c0 = prev.core, &c1 = leg.core;
      if (prev.turn == leg.turn && c0.centre == c1.centre && c0.a == c1.a && c0.b == c1.b && c0.theta == c1.theta &&
          prev.offset_m == leg.offset_m && std::abs(prev.phi_to - leg.phi_from) < 1e-9) {
        prev.to = leg.to;
        prev.phi_to = prev.phi_from + (leg.phi_to - leg.phi_from) + (prev.phi_to - prev.phi_from);
        prev.length_m += leg.length_m;
        continue;
      }
    }
    legs.push_back(std::move(leg));
  }
  return legs;
}

}  // namespace

PlanResult TangentGraph::solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel*,
                               const SearchBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  Impl::Query query(m, problem);
  query.add_end_circles();  // after the query exists: its end takes them out again if this throws
  const Vec2 s = query.s, g = query.g;

  // Start and goal get tangents only to the pieces that can meet the informed
  // bound's ellipse (informed_bound.hpp; a piece lies in the disc of radius
  // `radius` around its inner point).
  std::vector<double> low(m.pieces.size());
  double farthest = (g - s).norm();
  for (std::size_t i = 0; i < m.pieces.size(); ++i) {
    const ZonePiece& z = m.pieces[i];
    const Vec2 c = z.inner_point();
    const double radius = z.bounding_radius();
    low[i] = informed_reach(c, s, g) - 2.0 * radius;
    farthest = std::max(farthest, low[i] + 4.0 * radius);
  }
  const bool direct = m.segment_free(s, g);
  const double first = m.focus.active() ? m.focus.bound_m : kFirstBoundStretch * (g - s).norm();
  const SearchResult found = search_in_growing_bound(first, farthest, 1.0, [&](double bound) {
    query.clean();
    std::vector<std::vector<std::size_t>> added(m.pieces.size());
    query.join_ends(low, bound, added);
    if (direct && query.end_nodes.empty()) boost::add_edge(0, 1, (g - s).norm(), m.base);
    query.join_end_circles(low, bound, added);
    query.split_arcs(added);
    const std::function<double(GraphVertex)> h = [&](GraphVertex v) { return (m.nodes[v].p - g).norm(); };
    return shortest_path(m.base, 0, 1, algorithm, h, {}, budget);
  });

  PlanResult result = search_outcome(found, "the goal cannot be reached from the start without entering a safety zone");
  result.stats.graph_vertices = m.nodes.size();  // the spare vertices the query did not take do not count
  result.stats.graph_edges = boost::num_edges(m.base) / 2;
  result.stats.build_ms = m.build_ms;
  if (found.found) {
    query.trace(found.path, result);
    result.legs = merged_legs(std::move(result.legs));
  }
  result.stats.query_ms = elapsed_ms(t0);
  return result;
}

}  // namespace deepguide
