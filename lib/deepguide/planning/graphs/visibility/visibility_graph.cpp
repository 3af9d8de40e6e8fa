#include "deepguide/planning/graphs/visibility/visibility_graph.hpp"

#include <boost/geometry.hpp>
#include <chrono>
#include <cmath>
#include <string>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/parallel_blocks.hpp"
#include "deepguide/planning/graphs/visibility/occlusion_horizon.hpp"
#include "deepguide/planning/informed_bound.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

// The first informed bound (informed_bound.hpp): a little more than the straight line.
constexpr double kFirstBoundStretch = 1.05;

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

// Whether the line along d through a corner has both polygon neighbours (at
// to_prev, to_next from the corner) on one closed side, up to eps in
// distance: s_i / |d| compared with eps, squared to spare the root (this runs
// for every pair of corners).
inline bool supports_line(const Vec2& to_prev, const Vec2& to_next, const Vec2& d, double eps) {
  const double len2 = d.squaredNorm();
  if (len2 == 0.0) return false;
  const double s1 = cross(d, to_prev);
  const double s2 = cross(d, to_next);
  if ((s1 > 0.0) == (s2 > 0.0) || s1 == 0.0 || s2 == 0.0) return true;
  const double eps2 = eps * eps * len2;
  return !(s1 * s1 > eps2 && s2 * s2 > eps2);
}

// The bearings (pseudo-angles, occlusion_horizon.hpp) of the lines through a
// corner that support it, widened by the angle supports_line's eps admits and
// a little more: outside the cone between the corner's two edges and outside
// its opposite.
BearingSet supporting_bearings(const Vec2& to_prev, const Vec2& to_next, double eps) {
  BearingSet set;
  const double shortest = std::min(to_prev.norm(), to_next.norm());
  const double margin = OcclusionHorizon::kMarginRad + (shortest > 0.0 ? 2.0 * eps / shortest : kFullTurn);
  const double half = 0.5 * kFullTurn;
  if (margin >= 0.5 * half) {
    add_arc(set, 0.0, kFullTurn);
    return set;
  }
  // The cone runs anticlockwise from lo to hi, less than a half turn.
  const bool from_prev = cross(to_prev, to_next) >= 0.0;
  const double lo = pseudo_bearing(from_prev ? to_prev : to_next);
  double hi = pseudo_bearing(from_prev ? to_next : to_prev);
  if (hi < lo) hi += kFullTurn;
  add_arc(set, hi - margin, lo + half + margin);
  add_arc(set, hi + half - margin, lo + kFullTurn + margin);
  return set;
}

// Boundary pieces a corner's horizon takes at most: a dense field closes a
// corner's supporting bearings within a few hundred metres, a few hundred
// pieces; past that the bearings still open are tested pair by pair.
constexpr std::size_t kHorizonPieces = 256;
// Usable corners from which the reduced graph looks for pairs within the
// occlusion horizons. Below it the all-pairs loop, whose supporting test
// rejects most pairs in a few cross products, is quicker than setting the
// horizons up; both find the same edges (bench_planning, docs/PERFORMANCE.md).
constexpr std::size_t kHorizonCorners = 6000;
// Corner pairs the bearing test may take where corners look out at open
// water (each is tried with every later corner): about the old all-pairs
// limit, 10 s on the 2-core reference machine.
constexpr double kMaxOpenPairs = 8e8;
// Corners a square round a corner would hold, at the field's mean density,
// past which the supporting cones are queried instead of the square.
constexpr double kCornersForCones = 256.0;

// An edge found between two usable corners (their indices in `usable`).
struct Link {
  std::size_t u, v;
  double w;
};

// Graphs with fewer corners are built on one thread: threads cost more than
// they save there, and evaluate already runs one plan per core.
constexpr std::size_t kParallelCorners = 4000;
std::size_t build_workers(std::size_t corners) { return corners >= kParallelCorners ? hardware_workers() : 1; }

// Runs test(u, v, horizon of v), u < v, for every pair of corners (points,
// with their edges to_prev and to_next) where u may see v along a line
// supporting u: within u's occlusion horizon over its supporting bearings
// (occlusion_horizon.hpp). A pair left out is hidden or not supporting at u,
// so the edges are those of the all-pairs loop; test() checks v's horizon
// the other way once it knows the line supports v, and returns the edge's
// weight or a negative number. Returns the edges found, in no order.
template <class TestPair>
std::vector<Link> pairs_within_horizons(const std::vector<Vec2>& points, const std::vector<Vec2>& to_prev,
                                        const std::vector<Vec2>& to_next, const PolygonVisibility& visibility,
                                        TestPair test) {
  const std::size_t m = points.size();
  const std::size_t workers = build_workers(m);
  const OcclusionHorizon occlusion(visibility.polygons(), visibility.eps());
  std::vector<BearingSet> supporting(m);
  std::vector<Horizon> seen(m);
  parallel_blocks(m, 256, workers, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t u = begin; u < end; ++u) {
      supporting[u] = supporting_bearings(to_prev[u], to_next[u], visibility.eps());
      seen[u] = occlusion.horizon(points[u], supporting[u], kHorizonPieces);
    }
  });
  double open_pairs = 0.0;
  for (std::size_t u = 0; u < m; ++u) {
    if (!seen[u].bounded()) open_pairs += static_cast<double>(m - u - 1);
  }
  if (open_pairs > kMaxOpenPairs) {
    throw InputError("the safety zones have " + std::to_string(m) +
                     " polygon corners in the focus, too many in open view of each other for the reduced "
                     "visibility graph; raise `tolerance` or plan a smaller area");
  }
  using Item = std::pair<BgPoint, std::size_t>;
  std::vector<Item> items;
  items.reserve(m);
  for (std::size_t u = 0; u < m; ++u) items.emplace_back(to_bg(points[u]), u);
  const bgi::rtree<Item, bgi::rstar<16>> index(items);
  BgBox extent(to_bg(points.empty() ? Vec2::Zero() : points[0]), to_bg(points.empty() ? Vec2::Zero() : points[0]));
  for (const Vec2& q : points) bg::expand(extent, to_bg(q));
  // Corners per square metre of their box: how many a square round a corner holds, roughly.
  const double density = static_cast<double>(m) / std::max(bg::area(extent), 1.0);

  struct Scratch {
    std::vector<std::size_t> near;
    std::vector<std::size_t> taken;  // taken[v] == u: v is in u's list already
    std::vector<Link> links;
  };
  std::vector<Scratch> scratch(workers);
  for (Scratch& s : scratch) s.taken.assign(m, m);
  parallel_blocks(m, 64, workers, [&](std::size_t begin, std::size_t end, std::size_t worker) {
    Scratch& s = scratch[worker];
    for (std::size_t u = begin; u < end; ++u) {
      const Vec2& p = points[u];
      s.near.clear();
      const auto collect = [&](const auto& region, double max_d2) {
        for (auto it = index.qbegin(bgi::intersects(region)); it != index.qend(); ++it) {
          const std::size_t v = it->second;
          if (v > u && s.taken[v] != u && (points[v] - p).squaredNorm() <= max_d2) {
            s.taken[v] = u;
            s.near.push_back(v);
          }
        }
      };
      // Within the reach: a square round the corner, or, where that square
      // would hold many corners, only the supporting bearings. A coast's
      // corners are nearly flat, their supporting lines two narrow cones
      // along the coast, where a square round them holds the whole bay; in a
      // field of small obstacles the square holds a few corners, and the
      // cones' polygon queries cost more than they save (bench_planning,
      // N = 1000: 213 ms against 158 ms with squares only).
      const double r = seen[u].reach_m + visibility.eps();
      if (4.0 * r * r * density > kCornersForCones) {
        for (const auto& [lo, hi] : supporting[u]) {
          for (const BgPolygon& wedge : bearing_wedges(p, lo, hi, r)) collect(wedge, r * r);
        }
      } else {
        collect(BgBox(to_bg(p - Vec2(r, r)), to_bg(p + Vec2(r, r))), r * r);
      }
      // Beyond the reach, only the open bearings: wedges from p past every corner.
      const Vec2 span =
          (to_eigen(extent.max_corner()) - p).cwiseAbs().cwiseMax((to_eigen(extent.min_corner()) - p).cwiseAbs());
      const double far = 2.0 * span.norm() + 1.0;
      for (const auto& [lo, hi] : seen[u].open) {
        for (const BgPolygon& wedge : bearing_wedges(p, lo, hi, far)) collect(wedge, far * far);
      }
      for (const std::size_t v : s.near) {
        const double w = test(u, v, &seen[v]);
        if (w >= 0.0) s.links.push_back({u, v, w});
      }
    }
  });
  std::vector<Link> links;
  for (Scratch& s : scratch) links.insert(links.end(), s.links.begin(), s.links.end());
  return links;
}

// Runs test(u, v, nullptr) for every pair u < v: the full graph's loop.
template <class TestPair>
std::vector<Link> all_pairs(std::size_t m, TestPair test) {
  const std::size_t workers = build_workers(m);
  std::vector<std::vector<Link>> found(workers);
  parallel_blocks(m, 16, workers, [&](std::size_t begin, std::size_t end, std::size_t worker) {
    for (std::size_t u = begin; u < end; ++u) {
      for (std::size_t v = u + 1; v < m; ++v) {
        const double w = test(u, v, nullptr);
        if (w >= 0.0) found[worker].push_back({u, v, w});
      }
    }
  });
  std::vector<Link> links;
  for (const auto& f : found) links.insert(links.end(), f.begin(), f.end());
  return links;
}

}  // namespace

VisibilityGraph::VisibilityGraph(const BgMultiPolygon& zones, VisibilityVariant variant, const QueryFocus& focus,
                                 const WaypointGrid& grid, CornerPairs pairs)
    : variant_(variant) {
  const auto t0 = std::chrono::steady_clock::now();
  CentredVisibility centred = centred_visibility(zones);
  origin_ = centred.origin;
  focus_ = focus.shifted(origin_);
  visibility_ = std::move(centred.visibility);

  // Corners of every ring. Boost rings run clockwise around the polygon's
  // interior (holes anticlockwise), so the obstacle is always on the right.
  for (const BgPolygon& poly : visibility_->polygons()) {
    auto add_ring = [&](const auto& ring) {
      const std::size_t n = ring.size() - 1;  // closed ring repeats its first point
      for (std::size_t i = 0; i < n; ++i) {
        Corner c;
        c.p = to_eigen(ring[i]);
        c.prev = to_eigen(ring[(i + n - 1) % n]);
        c.next = to_eigen(ring[(i + 1) % n]);
        // Clockwise travel turns right (negative cross) at a convex corner.
        c.convex = cross(c.p - c.prev, c.next - c.p) < 0.0;
        corners_.push_back(c);
      }
    };
    add_ring(poly.outer());
    for (const auto& inner : poly.inners()) add_ring(inner);
  }

  const std::size_t n = corners_.size();
  if (n > max_corners(variant_)) {
    const bool full = variant_ == VisibilityVariant::full;
    throw InputError("the safety zones have " + std::to_string(n) + " polygon corners, more than the " +
                     (full ? std::string("full") : std::string("reduced")) + " visibility graph handles (" +
                     std::to_string(max_corners(variant_)) + "); raise `tolerance` or plan a smaller area" +
                     (full ? ", or use the reduced graph (`graph` visibility)" : ""));
  }
  // Lattice points follow the polygon corners in corners_; start and goal take the two slots after all.
  std::vector<std::size_t> lattice_cells;
  if (grid.active()) lattice_cells = add_lattice_points(grid);
  graph_ = PlanningGraph(corners_.size() + 2);
  // The corners a pair may use: an edge the focus keeps has both ends in its
  // ellipse (triangle inequality), and the reduced graph bends at convex
  // corners only. Filtering once keeps the pair loop to these.
  std::vector<std::size_t> usable;
  for (std::size_t i = 0; i < n; ++i) {
    if (variant_ == VisibilityVariant::reduced && !corners_[i].convex) continue;
    if (focus_.keeps_point(corners_[i].p)) usable.push_back(i);
  }
  // Each pair tried runs the cheapest test that rejects most pairs first. In
  // the reduced graph that is the supporting test (four
  // cross products; a corner of a 32-gon supports 1 line direction in 16),
  // then the focus, with each corner's distances to start and goal computed
  // once instead of per pair.
  const std::size_t m = usable.size();
  std::vector<double> to_start(m), to_goal(m);
  std::vector<Vec2> to_prev(m), to_next(m);
  for (std::size_t u = 0; u < m; ++u) {
    const Corner& c = corners_[usable[u]];
    to_start[u] = (c.p - focus_.start).norm();
    to_goal[u] = (c.p - focus_.goal).norm();
    to_prev[u] = c.prev - c.p;
    to_next[u] = c.next - c.p;
  }
  const bool reduced = variant_ == VisibilityVariant::reduced;
  const double eps = visibility_->eps();
  // The edge's weight if corners ui and uj see each other along a line the
  // graph keeps, else -1; seen_j: what uj's occlusion horizon lets it see
  // (nullptr: anything). Runs on several threads: reads only.
  const auto test_pair = [&](std::size_t ui, std::size_t uj, const Horizon* seen_j) {
    const std::size_t i = usable[ui], j = usable[uj];
    const Vec2 d = corners_[j].p - corners_[i].p;
    if (reduced &&
        (!supports_line(to_prev[ui], to_next[ui], d, eps) || !supports_line(to_prev[uj], to_next[uj], -d, eps))) {
      return -1.0;
    }
    if (seen_j != nullptr && !seen_j->sees(-d)) return -1.0;
    const double w = d.norm();
    if (std::min(to_start[ui] + w + to_goal[uj], to_start[uj] + w + to_goal[ui]) > focus_.bound_m) return -1.0;
    return visibility_->segment_visible(corners_[i].p, corners_[j].p) ? w : -1.0;
  };
  std::vector<Link> links;
  const bool horizons =
      reduced && (pairs == CornerPairs::horizons || (pairs == CornerPairs::automatic && m >= kHorizonCorners));
  if (horizons) {
    std::vector<Vec2> points(m);
    for (std::size_t u = 0; u < m; ++u) points[u] = corners_[usable[u]].p;
    links = pairs_within_horizons(points, to_prev, to_next, *visibility_, test_pair);
  } else {
    links = all_pairs(m, test_pair);
  }
  // In corner order, as a single all-pairs loop adds them: the search breaks
  // ties by the order of out-edges, so the same graph gives the same route.
  std::sort(links.begin(), links.end(),
            [](const Link& a, const Link& b) { return a.u != b.u ? a.u < b.u : a.v < b.v; });
  for (const Link& l : links) {
    boost::add_edge(usable[l.u], usable[l.v], l.w, graph_);
    boost::add_edge(usable[l.v], usable[l.u], l.w, graph_);
  }
  base_edges_ += links.size();
  if (grid.active()) link_lattice(grid, lattice_cells, n);
  build_ms_ = elapsed_ms(t0);
}

// The lattice points outside the zone polygons and within the focus, appended
// to corners_; returns the vertex of each lattice cell (kNoVertex: none).
std::vector<std::size_t> VisibilityGraph::add_lattice_points(const WaypointGrid& grid) {
  validate(grid);
  const std::size_t cols = grid.columns(), rows = grid.rows();
  link_radius_ = grid.link_radius();
  std::vector<std::size_t> vertex(cols * rows, kNoVertex);
  for (std::size_t j = 0; j < rows; ++j) {
    for (std::size_t i = 0; i < cols; ++i) {
      const Vec2 p = grid.point(i, j) - origin_;
      if (!focus_.keeps_point(p) || visibility_->strictly_inside(p)) continue;
      vertex[j * cols + i] = corners_.size();
      corners_.push_back(Corner{p, p, p, true, true});
      ++lattice_points_;
    }
  }
  return vertex;
}

// Joins each lattice point to the lattice points and polygon corners (the
// first n of corners_) it sees within the link radius.
void VisibilityGraph::link_lattice(const WaypointGrid& grid, const std::vector<std::size_t>& vertex, std::size_t n) {
  const std::size_t cols = grid.columns(), rows = grid.rows();
  const Vec2 min = grid.min - origin_;
  const auto link = [&](std::size_t a, std::size_t b) {
    const Vec2 pa = corners_[a].p, pb = corners_[b].p;
    if (!focus_.keeps_segment(pa, pb) || !visibility_->segment_visible(pa, pb)) return;
    const double w = (pb - pa).norm();
    boost::add_edge(a, b, w, graph_);
    boost::add_edge(b, a, w, graph_);
    ++base_edges_;
  };
  // Lattice to lattice: each unordered pair once, by offsets in one half plane.
  const auto reach = static_cast<long>(std::floor(link_radius_ / grid.spacing_m));
  for (std::size_t j = 0; j < rows; ++j) {
    for (std::size_t i = 0; i < cols; ++i) {
      const std::size_t a = vertex[j * cols + i];
      if (a == kNoVertex) continue;
      for (long dj = 0; dj <= reach; ++dj) {
        for (long di = -reach; di <= reach; ++di) {
          if (dj == 0 && di <= 0) continue;
          if (std::hypot(static_cast<double>(di), static_cast<double>(dj)) * grid.spacing_m > link_radius_) continue;
          const long ii = static_cast<long>(i) + di, jj = static_cast<long>(j) + dj;
          if (ii < 0 || jj < 0 || ii >= static_cast<long>(cols) || jj >= static_cast<long>(rows)) continue;
          const std::size_t b = vertex[static_cast<std::size_t>(jj) * cols + static_cast<std::size_t>(ii)];
          if (b != kNoVertex) link(a, b);
        }
      }
    }
  }
  // Corners to the lattice points around them.
  for (std::size_t c = 0; c < n; ++c) {
    if (variant_ == VisibilityVariant::reduced && !corners_[c].convex) continue;
    const Vec2 q = (corners_[c].p - min) / grid.spacing_m;
    const long i0 = static_cast<long>(std::ceil(q.x() - link_radius_ / grid.spacing_m));
    const long i1 = static_cast<long>(std::floor(q.x() + link_radius_ / grid.spacing_m));
    const long j0 = static_cast<long>(std::ceil(q.y() - link_radius_ / grid.spacing_m));
    const long j1 = static_cast<long>(std::floor(q.y() + link_radius_ / grid.spacing_m));
    for (long jj = std::max(j0, 0L); jj <= std::min(j1, static_cast<long>(rows) - 1); ++jj) {
      for (long ii = std::max(i0, 0L); ii <= std::min(i1, static_cast<long>(cols) - 1); ++ii) {
        const std::size_t b = vertex[static_cast<std::size_t>(jj) * cols + static_cast<std::size_t>(ii)];
        if (b == kNoVertex || (corners_[b].p - corners_[c].p).norm() > link_radius_) continue;
        link(c, b);
      }
    }
  }
}

std::size_t VisibilityGraph::max_corners(VisibilityVariant variant) {
  // The full graph tries all pairs: about 10 s of build at 4000 corners on the
  // 2-core reference machine (docs/PERFORMANCE.md). The reduced graph tries
  // the pairs within each corner's occlusion horizon, and refuses where too
  // many corners see open water without end (kMaxOpenPairs); its corner
  // limit bounds memory.
  return variant == VisibilityVariant::full ? 4000 : 250000;
}

bool VisibilityGraph::supporting_at(const Corner& c, const Vec2& other) const {
  if (c.open_water) return true;
  return supports_line(c.prev - c.p, c.next - c.p, other - c.p, visibility_->eps());
}

PlanResult VisibilityGraph::solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel* cost,
                                  const SearchBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  const Vec2 s = problem.start - origin_;
  const Vec2 g = problem.goal - origin_;
  const std::size_t n = corners_.size();
  const GraphVertex sv = n, gv = n + 1;
  auto link = [&](GraphVertex from, GraphVertex to, double w) { boost::add_edge(from, to, w, graph_); };
  auto position = [&](GraphVertex v) { return v == sv ? s : v == gv ? g : corners_[v].p; };
  if (cost != nullptr && cost->kind == CostKind::length) cost = nullptr;  // the graph's weights are lengths
  // Cost per metre of progress, at least: the heuristic's factor, and what
  // turns a cost back into the longest route that can have it.
  const double per_metre = cost != nullptr ? cost_per_metre_lower_bound(*cost) : 1.0;
  const std::function<double(GraphVertex)> h = [&](GraphVertex v) { return per_metre * (position(v) - g).norm(); };
  EdgeCostFn priced;
  if (cost != nullptr) {
    priced = [&](GraphVertex from, GraphVertex to, double label) {
      const LegCost leg =
          price_leg(*cost, position(from) + origin_, position(to) + origin_, departure_after(*cost, label));
      return edge_weight(*cost, leg);
    };
  }

  // Start and goal join only the corners within the informed bound
  // (informed_bound.hpp): a path of length L passes only corners with
  // |c - s| + |c - g| <= L; the rest of the graph is complete.
  std::vector<double> reach(n);
  double farthest = (g - s).norm();
  for (std::size_t i = 0; i < n; ++i) {
    reach[i] = informed_reach(corners_[i].p, s, g);
    farthest = std::max(farthest, reach[i]);
  }
  const bool direct = visibility_->segment_visible(s, g);
  const double first = focus_.active() ? focus_.bound_m : kFirstBoundStretch * (g - s).norm();
  std::size_t attached = 0;
  const SearchResult found = search_in_growing_bound(first, farthest, per_metre, [&](double bound) {
    boost::clear_vertex(sv, graph_);
    boost::clear_vertex(gv, graph_);
    // Start and goal join every corner they see (full), or the corners where
    // the line to them is supporting (reduced), and each other directly.
    for (std::size_t i = 0; i < n; ++i) {
      const Corner& c = corners_[i];
      if (reach[i] > bound) continue;
      if (variant_ == VisibilityVariant::reduced && !c.convex) continue;
      for (const auto& [point, vertex] : {std::pair{s, sv}, std::pair{g, gv}}) {
        if (c.open_water && (c.p - point).norm() > link_radius_) continue;  // lattice edges stay short
        if (variant_ == VisibilityVariant::reduced && !supporting_at(c, point)) continue;
        if (!visibility_->segment_visible(point, c.p)) continue;
        const double w = (c.p - point).norm();
        if (vertex == sv)
          link(sv, i, w);
        else
          link(i, gv, w);
      }
    }
    if (direct) link(sv, gv, (g - s).norm());
    attached = boost::out_degree(sv, graph_) + boost::in_degree(gv, graph_);
    return shortest_path(graph_, sv, gv, algorithm, h, priced, budget);
  });
  // No way at all, or none the current allows? The length search tells.
  bool current_blocks = false;
  if (!found.found && found.stopped == SearchStop::none && cost != nullptr) {
    current_blocks = shortest_path(
                         graph_, sv, gv, algorithm, [&](GraphVertex v) { return (position(v) - g).norm(); }, {}, budget)
                         .found;
  }

  PlanResult result = search_outcome(
      found, current_blocks ? "on every way to the goal the current is stronger than the vehicle: no feasible route"
                            : "the goal cannot be reached from the start without entering a safety zone");
  result.stats.graph_vertices = n + 2;
  result.stats.open_water_vertices = lattice_points_;
  result.stats.graph_edges = base_edges_ + attached;
  result.stats.build_ms = build_ms_;
  boost::clear_vertex(sv, graph_);
  boost::clear_vertex(gv, graph_);
  if (found.found) {
    for (GraphVertex v : found.path) result.route.points.push_back(position(v) + origin_);
  }
  result.stats.query_ms = elapsed_ms(t0);
  return result;
}

std::vector<Vec2> VisibilityGraph::corner_positions() const {
  std::vector<Vec2> out;
  for (const Corner& c : corners_) out.push_back(c.p + origin_);
  return out;
}

std::vector<std::pair<Vec2, Vec2>> VisibilityGraph::edges() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  const std::size_t n = corners_.size();
  for (auto [it, end] = boost::edges(graph_); it != end; ++it) {
    const GraphVertex a = boost::source(*it, graph_), b = boost::target(*it, graph_);
    if (a < b && b < n) out.emplace_back(corners_[a].p + origin_, corners_[b].p + origin_);
  }
  return out;
}

bool VisibilityGraph::segment_visible(const Vec2& p, const Vec2& q) const {
  return visibility_->segment_visible(p - origin_, q - origin_);
}

bool VisibilityGraph::strictly_inside(const Vec2& p) const { return visibility_->strictly_inside(p - origin_); }

Vec2 VisibilityGraph::closest_boundary_point(const Vec2& p) const {
  return visibility_->closest_boundary_point(p - origin_) + origin_;
}

}  // namespace deepguide
