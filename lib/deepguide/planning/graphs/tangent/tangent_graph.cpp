#include "deepguide/planning/graphs/tangent/tangent_graph.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/math/tools/minima.hpp>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <numbers>
#include <unordered_map>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/periodic_roots.hpp"
#include "deepguide/planning/graphs/tangent/zone_pieces.hpp"
#include "deepguide/planning/informed_bound.hpp"
#include "deepguide/planning/polygon_visibility.hpp"
#include "deepguide/planning/turn_rounding.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

constexpr std::size_t kNoPiece = static_cast<std::size_t>(-1);
// Tangent segments touch zones exactly; the field judging them allows this
// much (m) so rounding does not reject them. The route checker allows 1e-6.
constexpr double kTouchEps = 1e-7;
// The first informed bound (informed_bound.hpp): a little more than the straight line.
constexpr double kFirstBoundStretch = 1.05;
// About 10 s of build on the reference machine (docs/PERFORMANCE.md).
constexpr std::size_t kMaxPieces = 3000;

Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

struct Node {
  std::size_t piece;  // kNoPiece for start and goal
  double phi;         // outward normal angle on the piece, in [0, 2 pi)
  Vec2 p;
  int orient = 0;  // the way round the piece a route passes here: +1 anticlockwise, -1 clockwise, 0 either (one_way)
};

// The way round a piece of a route moving along `d` where the piece's outward
// normal is `u`: anticlockwise when d is u turned left.
int orientation(const Vec2& u, const Vec2& d) { return u.x() * d.y() - u.y() * d.x() > 0.0 ? +1 : -1; }

struct Segment {
  Node a, b;
};

ObstacleSet shifted(ObstacleSet set, const Vec2& origin) {
  for (auto& c : set.ellipses) c.footprint.centre -= origin;
  for (auto& poly : set.polygons) {
    auto shift = [&](auto& ring) {
      for (auto& pt : ring) pt = to_bg(to_eigen(pt) - origin);
    };
    shift(poly.footprint.outer());
    for (auto& inner : poly.footprint.inners()) shift(inner);
  }
  return set;
}

Vec2 centre_of(const ObstacleSet& set) {
  BgBox box;
  bool any = false;
  auto grow = [&](const Vec2& p) {
    if (!any) {
      box = BgBox(to_bg(p), to_bg(p));
      any = true;
    } else {
      bg::expand(box, to_bg(p));
    }
  };
  for (const auto& c : set.ellipses) grow(c.footprint.centre);
  for (const auto& poly : set.polygons) {
    for (const auto& pt : poly.footprint.outer()) grow(to_eigen(pt));
  }
  if (!any) return Vec2::Zero();
  return 0.5 * (to_eigen(box.min_corner()) + to_eigen(box.max_corner()));
}

// Bounding box of a piece (support function along the axes).
BgBox piece_box(const ZonePiece& z) {
  return BgBox(BgPoint(-z.support(-Vec2::UnitX()), -z.support(-Vec2::UnitY())),
               BgPoint(z.support(Vec2::UnitX()), z.support(Vec2::UnitY())));
}

}  // namespace

struct TangentGraph::Impl {
  Vec2 origin;
  double margin;
  double tolerance;
  QueryFocus focus;  // in the shifted frame
  std::vector<ZonePiece> pieces;
  std::vector<std::string> piece_names;
  std::vector<bool> needs_arc_check;  // another zone reaches into the piece's box
  double turn_radius = 0.0;           // routes turn on no boundary tighter than this (m)
  // Dubins ends: a query with a start (goal) heading leaves (reaches) that
  // end only along one of the two circles of this radius through it, the
  // way round that has the heading there. The circles are appended to
  // `pieces` while the query runs; end_way is +1 (anticlockwise) or -1 on
  // them, 0 on the environment's pieces, which may be passed either way.
  double heading_radius = 0.0;
  std::vector<int> end_way;
  std::vector<bool> end_is_start;
  // Whether a route may turn at the piece's point with normal phi, and along
  // its arc from phi0 to phi1 (phi0 < phi1): only where the radius is >= turn_radius.
  bool turns_at(std::size_t piece, double phi) const { return turns_along(piece, phi, phi); }
  bool turns_along(std::size_t piece, double phi0, double phi1) const {
    const ZonePiece& z = pieces[piece];
    if (turn_radius <= 0.0) return true;
    const double least =
        z.kind == ZonePiece::Kind::ellipse ? least_offset_ellipse_radius(z.ellipse, z.margin, phi0, phi1) : z.margin;
    return least >= turn_radius * (1.0 - 1e-12);
  }
  std::unique_ptr<ObstacleField> field;  // shifted frame, accepts margin - kTouchEps
  std::vector<Segment> tangents;         // collision-free common tangents
  double build_ms = 0.0;

  // The environment's graph, built once: vertex 0 and 1 are reserved for
  // start and goal, then one vertex per tangent point and way round its piece
  // (anticlockwise, clockwise). A tangent leaves its first point and reaches
  // its second going one way round each; it is an edge between those
  // vertices and, backwards, between the other two. Arcs join vertices of one
  // way round: a route never reverses along a piece (with pieces that are not
  // obstacles, the turning circles, a reversal could otherwise look short).
  // Without a turning radius there are no such pieces, and a shortest route
  // never reverses (a cusp is never shortest): one vertex per tangent point
  // (orient 0), tangents and arcs both ways, half the vertices to build,
  // join and search (`one_way`).
  // Arcs are stored in the direction of travel (from u to v), with the way
  // round they run (+1 anticlockwise).
  struct Arc {
    std::size_t u, v;
    double w;
    int turn;
  };
  bool one_way = false;
  std::vector<Node> nodes;  // the environment's, then a query's own while it runs
  std::size_t env_nodes = 0;
  std::vector<std::vector<std::size_t>> on_piece;  // vertex ids per piece, by phi
  PlanningGraph base;
  std::vector<Arc> arcs;
  std::unordered_map<std::uint64_t, std::size_t> arc_of;  // (u, v) -> cheapest arc
  std::size_t base_edges = 0;

  static std::uint64_t key(std::size_t u, std::size_t v) { return (static_cast<std::uint64_t>(u) << 32) | v; }
  // Adds the arcs between cyclically consecutive vertices of `ids` (sorted by
  // phi) of one way round for which `want(a, b)` holds.
  template <class Want>
  void add_arcs(std::size_t piece, const std::vector<std::size_t>& ids, const std::vector<Node>& all, Want want,
                PlanningGraph& graph, std::vector<Arc>& out,
                std::unordered_map<std::uint64_t, std::size_t>& index) const;

  // The obstacle polygons: a segment crossing one is blocked for certain,
  // found far faster than the exact polygon test, which then only judges the
  // rest. (Ellipses have their own quick verdicts in ObstacleField.)
  std::unique_ptr<PolygonVisibility> inner;
  // A convex zone (an ellipse's) does not meet a line tangent to it beyond
  // the touch, nor a point on its boundary: the tests skip the ellipse a
  // segment or point was built on (`skip_*` are piece indices or kNoPiece).
  std::size_t own_ellipse(std::size_t piece) const {
    return piece != kNoPiece && pieces[piece].kind == ZonePiece::Kind::ellipse ? pieces[piece].obstacle
                                                                               : ObstacleField::kNone;
  }
  bool segment_free(const Vec2& a, const Vec2& b, std::size_t piece_a = kNoPiece,
                    std::size_t piece_b = kNoPiece) const {
    return !inner->properly_crosses(a, b) && field->segment_free(a, b, own_ellipse(piece_a), own_ellipse(piece_b));
  }
  bool point_free(const Vec2& p, std::size_t piece) const { return field->is_free(p, own_ellipse(piece)); }
  bool arc_free(std::size_t piece, double phi0, double phi1) const;
  // Tangents from p to the pieces whose lower bound of |x - s| + |x - g| is
  // within `bound` (all pieces for an infinite bound).
  void add_point_tangents(const Vec2& p, std::vector<Segment>& out, const std::vector<double>& low, double bound) const;
  // The collision-free common tangents of pieces i and j, from i to j.
  void common_tangents(std::size_t i, std::size_t j, std::vector<Segment>& out) const;
  std::vector<Vec2> arc_polyline(std::size_t piece, double phi0, double phi1, int turn) const;
  // The route's legs along a piece from normal angle phi0 to phi1 (turn: the
  // sign of phi1 - phi0), in the unshifted frame: one arc on an ellipse's
  // zone; on a capsule, arcs round its ends and lines along its flat sides.
  // from_p and to_p are the route's points there (at a flat side's normal
  // they tell which end the route is at).
  std::vector<RouteLeg> arc_legs(std::size_t piece, double phi0, double phi1, int turn, const Vec2& from_p,
                                 const Vec2& to_p) const;
};

TangentGraph::TangentGraph(const ObstacleSet& obstacles, double margin, double tolerance, const QueryFocus& focus,
                           double turn_radius)
    : impl_(std::make_unique<Impl>()) {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  m.origin = centre_of(obstacles);
  m.margin = margin;
  m.tolerance = tolerance;
  m.focus = focus.shifted(m.origin);
  const ObstacleSet local = shifted(obstacles, m.origin);
  m.pieces = zone_pieces(local, m.margin);
  std::size_t first_circle = m.pieces.size();
  if (turn_radius > m.margin) {
    // Polygon corners turn at d: routes turn round them on their circles only,
    // and the polygons' zones stay in the field for every segment and arc.
    m.turn_radius = turn_radius;
    std::erase_if(m.pieces, [](const ZonePiece& p) { return p.kind == ZonePiece::Kind::capsule; });
    first_circle = m.pieces.size();
    for (const TurningCircle& c : turning_circles(local, m.margin, turn_radius)) {
      ZonePiece p;
      p.kind = ZonePiece::Kind::capsule;
      p.a = p.b = c.centre;
      p.margin = turn_radius;
      p.obstacle = c.obstacle;
      m.pieces.push_back(p);
    }
  }
  if (m.focus.active()) {
    // A piece no route within the bound can come near adds nothing (single_query.hpp): on a chart's
    // coast this keeps the few hundred edges near the ellipse of thousands.
    std::erase_if(m.pieces, [&](const ZonePiece& p) {
      const Vec2 c = p.inner_point();
      const double r = p.bounding_radius();
      return (c - m.focus.start).norm() + (c - m.focus.goal).norm() - 2.0 * r > m.focus.bound_m;
    });
  }
  // The build pairs every two pieces: quadratic, so refuse what cannot finish.
  if (m.pieces.size() > kMaxPieces) {
    throw InputError("the tangent graph would pair " + std::to_string(m.pieces.size()) +
                     " zone pieces (obstacles plus polygon edges), more than it handles (" +
                     std::to_string(kMaxPieces) + "); use `graph` visibility or plan a smaller area");
  }
  m.field = std::make_unique<ObstacleField>(local, m.margin, kTouchEps);
  BgMultiPolygon inner;
  for (const PolygonObstacle& poly : local.polygons) inner.push_back(poly.footprint);
  m.inner = std::make_unique<PolygonVisibility>(std::move(inner), 1e-9);
  for (const ZonePiece& z : m.pieces) m.piece_names.push_back(m.field->obstacle_name(z.obstacle));
  m.heading_radius = turn_radius;
  m.one_way = !(turn_radius > 0.0);
  m.end_way.assign(m.pieces.size(), 0);
  m.end_is_start.assign(m.pieces.size(), false);

  // Pieces whose box meets another obstacle's piece need their arcs checked.
  using Item = std::pair<BgBox, std::size_t>;
  std::vector<Item> boxes;
  for (std::size_t i = 0; i < m.pieces.size(); ++i) boxes.emplace_back(piece_box(m.pieces[i]), i);
  const bgi::rtree<Item, bgi::rstar<16>> tree(boxes);
  m.needs_arc_check.assign(m.pieces.size(), false);
  // A turning circle's arcs leave the circle's own obstacle's zone only near its corner.
  for (std::size_t i = first_circle; i < m.pieces.size(); ++i) m.needs_arc_check[i] = true;
  for (const Item& it : boxes) {
    std::vector<Item> hits;
    tree.query(bgi::intersects(it.first), std::back_inserter(hits));
    for (const Item& h : hits) {
      if (h.second != it.second) m.needs_arc_check[it.second] = true;
    }
  }

  std::vector<double> radius;
  for (const ZonePiece& z : m.pieces) radius.push_back(z.bounding_radius());
  for (std::size_t i = 0; i < m.pieces.size(); ++i) {
    for (std::size_t j = i + 1; j < m.pieces.size(); ++j) {
      const ZonePiece& zi = m.pieces[i];
      const ZonePiece& zj = m.pieces[j];
      if (!m.focus.keeps_disc_pair(zi.inner_point(), radius[i], zj.inner_point(), radius[j])) continue;
      m.common_tangents(i, j, m.tangents);
    }
  }
  m.nodes = {Node{kNoPiece, 0.0, Vec2::Zero()}, Node{kNoPiece, 0.0, Vec2::Zero()}};
  m.on_piece.assign(m.pieces.size(), {});
  std::vector<std::pair<std::size_t, std::size_t>> segment_ends;
  for (const Segment& seg : m.tangents) {
    const Vec2 d = seg.b.p - seg.a.p;
    const int oa = orientation(unit(seg.a.phi), d), ob = orientation(unit(seg.b.phi), d);
    auto vertex = [&](Node n, int orient) {
      n.orient = orient;
      m.nodes.push_back(n);
      m.on_piece[n.piece].push_back(m.nodes.size() - 1);
      return m.nodes.size() - 1;
    };
    if (m.one_way) {
      const std::size_t a = vertex(seg.a, 0), b = vertex(seg.b, 0);
      segment_ends.emplace_back(a, b);
      segment_ends.emplace_back(b, a);
      continue;
    }
    const std::size_t a_out = vertex(seg.a, oa), b_in = vertex(seg.b, ob);
    const std::size_t b_out = vertex(seg.b, -ob), a_in = vertex(seg.a, -oa);
    segment_ends.emplace_back(a_out, b_in);
    segment_ends.emplace_back(b_out, a_in);
  }
  // Spare vertices for the queries' tangent points (at most two per piece
  // from each of start and goal, or a boundary point's two ways round): a
  // query adds edges, never vertices, so the graph is searched in place
  // instead of copied.
  m.env_nodes = m.nodes.size();
  m.base = PlanningGraph(m.env_nodes + 4 * m.pieces.size());
  for (const auto& [a, b] : segment_ends) boost::add_edge(a, b, (m.nodes[a].p - m.nodes[b].p).norm(), m.base);
  for (std::size_t i = 0; i < m.pieces.size(); ++i) {
    auto& ids = m.on_piece[i];
    std::sort(ids.begin(), ids.end(), [&](std::size_t x, std::size_t y) { return m.nodes[x].phi < m.nodes[y].phi; });
    // An arc is no shorter than its chord: the focus judges arcs by chords.
    m.add_arcs(
        i, ids, m.nodes,
        [&](std::size_t a, std::size_t b) { return m.focus.keeps_segment(m.nodes[a].p, m.nodes[b].p); }, m.base, m.arcs,
        m.arc_of);
  }
  m.base_edges = segment_ends.size() + m.arcs.size();
  m.build_ms = elapsed_ms(t0);
}

void TangentGraph::Impl::common_tangents(std::size_t i, std::size_t j, std::vector<Segment>& out) const {
  const ZonePiece& zi = pieces[i];
  const ZonePiece& zj = pieces[j];
  // Outer tangents: h_i(u) = h_j(u); inner: h_i(u) = -h_j(-u). The
  // slopes follow from the support points (see ZonePiece::support_at).
  auto g_outer = [&](double phi) {
    const Vec2 u = unit(phi);
    const ZonePiece::Support si = zi.support_at(u), sj = zj.support_at(u);
    return ValueSlope{si.h - sj.h, (si.p - sj.p).dot(Vec2(-u.y(), u.x()))};
  };
  auto g_inner = [&](double phi) {
    const Vec2 u = unit(phi);
    const ZonePiece::Support si = zi.support_at(u), sj = zj.support_at(-u);
    return ValueSlope{si.h + sj.h, (si.p - sj.p).dot(Vec2(-u.y(), u.x()))};
  };
  double r[2];
  // Both functions are positive along inner_i - inner_j and, for
  // separated pieces, negative against it (periodic_two_roots' hint).
  const Vec2 dc = zi.inner_point() - zj.inner_point();
  const double along = std::atan2(dc.y(), dc.x());
  auto add = [&](double phi_i, double phi_j) {
    phi_i = wrap_two_pi(phi_i);
    phi_j = wrap_two_pi(phi_j);
    const Node a{i, phi_i, zi.point_at_normal(phi_i)};
    const Node b{j, phi_j, zj.point_at_normal(phi_j)};
    if ((a.p - b.p).norm() > 0.0 && turns_at(i, phi_i) && turns_at(j, phi_j) && focus.keeps_segment(a.p, b.p) &&
        segment_free(a.p, b.p, i, j)) {
      out.push_back({a, b});
    }
  };
  if (periodic_two_roots(g_outer, r[0], r[1], along)) {
    for (double phi : r) add(phi, phi);
  }
  if (!zones_overlap(zi, zj) && periodic_two_roots(g_inner, r[0], r[1], along)) {
    for (double phi : r) add(phi, phi + std::numbers::pi);
  }
}

template <class Want>
void TangentGraph::Impl::add_arcs(std::size_t piece, const std::vector<std::size_t>& ids, const std::vector<Node>& all,
                                  Want want, PlanningGraph& graph, std::vector<Arc>& out,
                                  std::unordered_map<std::uint64_t, std::size_t>& index) const {
  for (int orient : one_way ? std::vector<int>{0} : std::vector<int>{+1, -1}) {
    std::vector<std::size_t> way;
    for (std::size_t v : ids) {
      if (all[v].orient == orient) way.push_back(v);
    }
    if (way.size() < 2) continue;
    for (std::size_t k = 0; k < way.size(); ++k) {
      const std::size_t a = way[k], b = way[(k + 1) % way.size()];
      if (!want(a, b)) continue;
      const double phi0 = all[a].phi;
      const double phi1 = k + 1 < way.size() ? all[b].phi : all[b].phi + kTwoPi;
      if (!turns_along(piece, phi0, phi1)) continue;
      if (needs_arc_check[piece] && !arc_free(piece, phi0, phi1)) continue;
      const double w = pieces[piece].arc_length(phi0, phi1);
      // Anticlockwise is from a (smaller phi) to b; clockwise the other way.
      // Two vertices at one point (the sort's order between them is
      // arbitrary) are joined both ways.
      const bool same_point = k + 1 < way.size() && phi1 == phi0;
      const bool both_ways = same_point || orient == 0;
      for (const int dir : {+1, -1}) {
        if (!both_ways && dir != orient) continue;
        const std::size_t from = dir > 0 ? a : b, to = dir > 0 ? b : a;
        boost::add_edge(from, to, w, graph);
        out.push_back({from, to, w, orient != 0 ? orient : dir});
        auto it = index.find(key(from, to));
        if (it == index.end() || out[it->second].w > w) index[key(from, to)] = out.size() - 1;
      }
    }
  }
}

TangentGraph::~TangentGraph() = default;
TangentGraph::TangentGraph(TangentGraph&&) noexcept = default;
TangentGraph& TangentGraph::operator=(TangentGraph&&) noexcept = default;

std::size_t TangentGraph::piece_count() const { return impl_->pieces.size(); }
std::size_t TangentGraph::tangent_count() const { return impl_->tangents.size(); }
double TangentGraph::build_ms() const { return impl_->build_ms; }

std::vector<std::pair<Vec2, Vec2>> TangentGraph::tangent_segments() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  for (const Segment& s : impl_->tangents) out.emplace_back(s.a.p + impl_->origin, s.b.p + impl_->origin);
  return out;
}

bool TangentGraph::Impl::arc_free(std::size_t piece, double phi0, double phi1) const {
  const ZonePiece& z = pieces[piece];
  // Conservative advancement: where the arc's point has clearance c from
  // every other zone, the next c metres of arc are clear too (an arc is no
  // shorter than its chord), and the boundary runs at most `radius` metres
  // per radian of normal. Where c is below `step` the arc is sampled `step`
  // apart; an arc that enters another zone does so over a stretch, which the
  // samples find unless the overlap is thinner than the step (then the route
  // checker, which every route passes, has the last word). Far from other
  // zones an arc takes a few distances instead of one point test per `step`
  // (up to 200,000 on a turning circle). No arc takes more than 200,000
  // steps: a longer one is sampled that many times over its whole length.
  // The candidates are the obstacles whose box comes within the margin of
  // the piece's disc.
  const double radius = std::max(z.max_curvature_radius(), 1e-9);
  const double step = std::max({0.5 * tolerance, 1e-3, (phi1 - phi0) * radius / 200000.0});
  const std::size_t own = own_ellipse(piece);
  const Vec2 reach = Vec2::Constant(z.bounding_radius());
  std::vector<std::size_t> near = field->near(z.inner_point() - reach, z.inner_point() + reach, margin);
  std::erase(near, own);
  double phi = phi0;
  while (!near.empty()) {
    const Vec2 q = z.point_at_normal(phi);
    double c = std::numeric_limits<double>::infinity();
    for (std::size_t i : near) c = std::min(c, field->distance_to(i, q) - margin);
    if (c < -kTouchEps && phi > phi0) return false;
    phi += std::max(c, step) / radius;
    if (!(phi < phi1)) break;
  }
  // Capsules: the flat sides crossed are segments of their own.
  for (double f : z.flat_normals()) {
    for (double g = f + kTwoPi * std::ceil((phi0 - f) / kTwoPi); g < phi1; g += kTwoPi) {
      if (g > phi0 && !segment_free(z.a + z.margin * unit(g), z.b + z.margin * unit(g))) return false;
    }
  }
  return true;
}

void TangentGraph::Impl::add_point_tangents(const Vec2& p, std::vector<Segment>& out, const std::vector<double>& low,
                                            double bound) const {
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (low[i] > bound) continue;
    const ZonePiece& z = pieces[i];
    auto f = [&](double phi) {
      const Vec2 u = unit(phi);
      const ZonePiece::Support sz = z.support_at(u);
      return ValueSlope{u.dot(p) - sz.h, (p - sz.p).dot(Vec2(-u.y(), u.x()))};
    };
    double r[2];
    const Vec2 out_dir = p - z.inner_point();  // f > 0 this way when p lies outside
    if (periodic_two_roots(f, r[0], r[1], std::atan2(out_dir.y(), out_dir.x()))) {
      for (double phi : r) {
        const Node t{i, wrap_two_pi(phi), z.point_at_normal(wrap_two_pi(phi))};
        if (turns_at(i, t.phi) && segment_free(p, t.p, kNoPiece, i)) out.push_back({Node{kNoPiece, 0.0, p}, t});
      }
      continue;
    }
    // No tangent: p is inside the piece, or on its boundary. On the boundary,
    // p itself joins the piece's arcs at its normal angle.
    auto neg = [&](double phi) { return -f(phi).value; };
    const Vec2 d = p - z.inner_point();
    const double guess = std::atan2(d.y(), d.x());
    auto best = boost::math::tools::brent_find_minima(neg, guess - std::numbers::pi, guess + std::numbers::pi, 52);
    if (std::abs(best.second) <= kTouchEps && turns_at(i, wrap_two_pi(best.first))) {
      const double phi = wrap_two_pi(best.first);
      out.push_back({Node{kNoPiece, 0.0, p}, Node{i, phi, p}});
    }
  }
}

std::vector<Vec2> TangentGraph::Impl::arc_polyline(std::size_t piece, double phi0, double phi1, int turn) const {
  const ZonePiece& z = pieces[piece];
  // The arc's tangent lines at normals spaced so each corner where two meet
  // lies within `tolerance` of the arc, plus every flat side crossed. Between
  // tangent points T_k, T_k+1 the polyline runs T_k -> corner -> T_k+1, which
  // stays outside this zone; where a corner would poke into a neighbouring
  // zone the interval is split further (the arc itself is clear of it).
  const double lo = std::min(phi0, phi1), hi = std::max(phi0, phi1);
  const double rho = std::max(z.max_curvature_radius(), 1e-12);
  const double delta = 2.0 * std::acos(1.0 / (1.0 + tolerance / rho));
  std::vector<double> normals;
  const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / delta)));
  for (int k = 0; k <= n; ++k) normals.push_back(lo + (hi - lo) * k / n);
  for (double f : z.flat_normals()) {
    for (double g = f + kTwoPi * std::ceil((lo - f) / kTwoPi); g < hi; g += kTwoPi) {
      if (g > lo) normals.push_back(g);
    }
  }
  std::sort(normals.begin(), normals.end());
  normals.erase(std::unique(normals.begin(), normals.end()), normals.end());
  if (turn < 0) std::reverse(normals.begin(), normals.end());

  std::vector<Vec2> out;
  // Two tangent lines meet at a point whose rounding error grows as 1 / (b - a):
  // below 1e-7 rad it could land metres off, while the chord is within
  // R (b - a)^2 / 8 (< 1e-12 m) of the arc: no corner then.
  auto corner = [&](double a, double b, Vec2& v) {
    if (std::abs(b - a) < 1e-7) return false;
    const Vec2 u1 = unit(a), u2 = unit(b);
    const double h1 = z.support(u1), h2 = z.support(u2);
    const double det = u1.x() * u2.y() - u1.y() * u2.x();
    if (std::abs(det) < 1e-15) return false;
    v = Vec2((h1 * u2.y() - h2 * u1.y()) / det, (u1.x() * h2 - u2.x() * h1) / det);
    return true;
  };
  std::function<void(double, double, int)> emit = [&](double a, double b, int depth) {
    const Vec2 ta = z.point_at_normal(wrap_two_pi(a)), tb = z.point_at_normal(wrap_two_pi(b));
    Vec2 v;
    if (!corner(a, b, v)) return;
    if (depth < 40 && (!segment_free(ta, v, piece) || !segment_free(v, tb, piece))) {
      const double mid = 0.5 * (a + b);
      emit(a, mid, depth + 1);
      out.push_back(z.point_at_normal(wrap_two_pi(mid)));
      emit(mid, b, depth + 1);
      return;
    }
    out.push_back(v);
  };
  for (std::size_t k = 0; k + 1 < normals.size(); ++k) {
    if (k > 0) out.push_back(z.point_at_normal(wrap_two_pi(normals[k])));
    emit(normals[k], normals[k + 1], 0);
  }
  return out;
}

std::vector<RouteLeg> TangentGraph::Impl::arc_legs(std::size_t piece, double phi0, double phi1, int turn,
                                                   const Vec2& from_p, const Vec2& to_p) const {
  const ZonePiece& z = pieces[piece];
  std::vector<RouteLeg> out;
  auto arc = [&](const Ellipse& core, double from, double to, double length, double radius) {
    if (!(length > 1e-12)) return;
    RouteLeg leg;
    leg.kind = RouteLeg::Kind::arc;
    leg.turn = turn;
    leg.core = core;
    leg.core.centre += origin;
    leg.offset_m = z.margin;
    leg.phi_from = from;
    leg.phi_to = to;
    // From the core, not the piece: at a flat side's normal the piece's point is either end.
    leg.from = arc_point(leg, from);
    leg.to = arc_point(leg, to);
    leg.length_m = length;
    leg.radius_m = radius;
    leg.obstacle = piece_names[piece];
    out.push_back(std::move(leg));
  };
  if (z.kind == ZonePiece::Kind::ellipse) {
    arc(z.ellipse, phi0, phi1, z.arc_length(std::min(phi0, phi1), std::max(phi0, phi1)), z.max_curvature_radius());
    return out;
  }
  // A capsule: the flat sides crossed split the span into turns round one
  // end each, with a line along each side. A side's normal within rounding of
  // either end of the span is no cut: the points say which end the route is at.
  const double lo = std::min(phi0, phi1), hi = std::max(phi0, phi1);
  std::vector<double> cuts;
  for (double f : z.flat_normals()) {
    for (double g = f + kTwoPi * std::ceil((lo - f) / kTwoPi); g < hi; g += kTwoPi) {
      if (g > lo + 1e-12 && g < hi - 1e-12) cuts.push_back(g);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  if (turn < 0) std::reverse(cuts.begin(), cuts.end());
  auto end_at = [&](const Vec2& p, double phi) {
    const Vec2 q = p - z.margin * unit(phi);
    return (q - z.a).norm() <= (q - z.b).norm() ? z.a : z.b;
  };
  auto side = [&](const Vec2& from_end, const Vec2& to_end, double normal) {
    RouteLeg line;
    line.from = from_end + z.margin * unit(normal) + origin;
    line.to = to_end + z.margin * unit(normal) + origin;
    line.length_m = (line.to - line.from).norm();
    out.push_back(std::move(line));
  };
  Vec2 end = end_at(from_p, phi0);
  double from = phi0;
  for (double g : cuts) {
    arc(Ellipse{end, 0.0, 0.0, 0.0}, from, g, z.margin * std::abs(g - from), z.margin);
    const Vec2 other = end == z.a ? z.b : z.a;
    side(end, other, g);
    end = other;
    from = g;
  }
  arc(Ellipse{end, 0.0, 0.0, 0.0}, from, phi1, z.margin * std::abs(phi1 - from), z.margin);
  if (const Vec2 last = end_at(to_p, phi1); last != end) side(end, last, phi1);
  return out;
}

PlanResult TangentGraph::solve(const PlanningProblem& problem, SearchAlgorithm algorithm, const CostModel*,
                               const SearchBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  const Vec2 s = problem.start - m.origin;
  const Vec2 g = problem.goal - m.origin;
  PlanningGraph& graph = m.base;
  std::vector<Node>& nodes = m.nodes;
  nodes[0].p = s;
  nodes[1].p = g;

  // The query's edges and vertices go into the environment's graph and come
  // out again when it ends, however it ends.
  std::vector<std::size_t> used;  // spare vertices taken
  auto clean = [&] {
    boost::clear_vertex(0, graph);
    boost::clear_vertex(1, graph);
    for (std::size_t v : used) boost::clear_vertex(v, graph);
    used.clear();
    nodes.resize(m.env_nodes);
  };
  struct Cleanup {
    std::function<void()> f;
    ~Cleanup() { f(); }
  } cleanup{clean};
  auto new_vertex = [&](const Node& n) {
    const std::size_t v = nodes.size();
    if (v >= boost::num_vertices(graph)) boost::add_vertex(graph);  // stays, isolated, for later queries
    nodes.push_back(n);
    used.push_back(v);
    return v;
  };

  // Dubins ends. On the circle through p turning `way` round (left of the
  // heading for anticlockwise), p's outward normal is heading - way pi/2.
  const std::size_t env_pieces = m.pieces.size();
  Cleanup drop_end_circles{[&m, env_pieces] {
    m.pieces.resize(env_pieces);
    m.piece_names.resize(env_pieces);
    m.needs_arc_check.resize(env_pieces);
    m.on_piece.resize(env_pieces);
    m.end_way.resize(env_pieces);
    m.end_is_start.resize(env_pieces);
  }};
  std::vector<Node> end_nodes;  // the ends' own points on their circles
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
  // A tangent point within rounding of its end's own point is that point, so
  // the route goes straight on instead of once round the circle.
  auto snapped = [&](Node n) {
    for (const Node& e : end_nodes) {
      if (e.piece == n.piece && std::abs(wrap_pi(n.phi - e.phi)) < 1e-9) {
        n.phi = e.phi;
        n.p = e.p;
      }
    }
    return n;
  };

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
  std::vector<Impl::Arc> arcs;
  std::unordered_map<std::uint64_t, std::size_t> arc_of;
  const SearchResult found = search_in_growing_bound(first, farthest, 1.0, [&](double bound) {
    clean();
    arcs.clear();
    arc_of.clear();
    std::vector<std::vector<std::size_t>> added(m.pieces.size());
    for (std::size_t end = 0; end < 2; ++end) {
      if (end == 0 ? problem.start_heading.has_value() : problem.goal_heading.has_value()) continue;
      std::vector<Segment> tangents;
      m.add_point_tangents(end == 0 ? s : g, tangents, low, bound);
      for (const Segment& seg : tangents) {
        // Away from the start, towards the goal; a point on the boundary
        // itself may go either way round.
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
            boost::add_edge(0, v, w, graph);
          } else {
            boost::add_edge(v, 1, w, graph);
          }
        }
      }
    }
    if (direct && end_nodes.empty()) boost::add_edge(0, 1, (g - s).norm(), graph);
    // An end with a heading is on its circles, and leaves (is reached) along
    // them; the circles' tangents to the pieces within the bound, and from
    // the start's to the goal's, each kept the way round its end circle goes.
    for (const Node& e : end_nodes) {
      const std::size_t v = new_vertex(e);
      added[e.piece].push_back(v);
      if (m.end_is_start[e.piece]) {
        boost::add_edge(0, v, 0.0, graph);
      } else {
        boost::add_edge(v, 1, 0.0, graph);
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
            boost::add_edge(va, vb, d.norm(), graph);
          } else {
            boost::add_edge(vb, va, d.norm(), graph);
          }
        }
      }
    }
    // New tangent points split the pieces' arcs: join them to their neighbours.
    for (std::size_t i = 0; i < m.pieces.size(); ++i) {
      if (added[i].empty()) continue;
      // The piece's own vertices are sorted once, at the build: only the
      // query's few are sorted here (a full sort per piece and query was an
      // eighth of the prebuilt solve).
      const auto by_phi = [&](std::size_t x, std::size_t y) { return nodes[x].phi < nodes[y].phi; };
      std::sort(added[i].begin(), added[i].end(), by_phi);
      std::vector<std::size_t> ids;
      ids.reserve(m.on_piece[i].size() + added[i].size());
      std::merge(m.on_piece[i].begin(), m.on_piece[i].end(), added[i].begin(), added[i].end(), std::back_inserter(ids),
                 by_phi);
      m.add_arcs(
          i, ids, nodes, [&](std::size_t a, std::size_t b) { return a >= m.env_nodes || b >= m.env_nodes; }, graph,
          arcs, arc_of);
    }
    const std::function<double(GraphVertex)> h = [&](GraphVertex v) { return (nodes[v].p - g).norm(); };
    return shortest_path(graph, 0, 1, algorithm, h, {}, budget);
  });

  PlanResult result = search_outcome(found, "the goal cannot be reached from the start without entering a safety zone");
  result.stats.graph_vertices = nodes.size();  // the spare vertices the query did not take do not count
  result.stats.graph_edges = boost::num_edges(graph) / 2;
  result.stats.build_ms = m.build_ms;
  if (!found.found) {
    result.stats.query_ms = elapsed_ms(t0);
    return result;
  }
  std::vector<Vec2>& pts = result.route.points;
  pts.push_back(s + m.origin);
  for (std::size_t k = 0; k + 1 < found.path.size(); ++k) {
    const std::size_t u = found.path[k], v = found.path[k + 1];
    const Node& a = nodes[u];
    const Node& b = nodes[v];
    RouteLeg leg;
    leg.from = a.p + m.origin;
    leg.to = b.p + m.origin;
    // Two tangent points of one piece are joined only by arcs; the index
    // holds the cheaper one, which is the one the search used.
    const Impl::Arc* arc = nullptr;
    if (a.piece != kNoPiece && a.piece == b.piece) {
      if (auto it = arc_of.find(Impl::key(u, v)); it != arc_of.end()) arc = &arcs[it->second];
      if (auto it = m.arc_of.find(Impl::key(u, v)); it != m.arc_of.end() && (!arc || m.arcs[it->second].w < arc->w)) {
        arc = &m.arcs[it->second];
      }
    }
    if (arc != nullptr) {
      const int turn = arc->turn;
      const double phi_from = a.phi;
      double phi_to = b.phi;
      if (turn > 0) {
        while (phi_to < phi_from) phi_to += kTwoPi;
      } else {
        while (phi_to > phi_from) phi_to -= kTwoPi;
      }
      for (RouteLeg& part : m.arc_legs(a.piece, phi_from, phi_to, turn, a.p, b.p)) {
        result.exact_length_m += part.length_m;
        result.legs.push_back(std::move(part));
      }
      for (const Vec2& q : m.arc_polyline(a.piece, phi_from, phi_to, turn)) pts.push_back(q + m.origin);
    } else {
      leg.length_m = (b.p - a.p).norm();
      result.exact_length_m += leg.length_m;
      result.legs.push_back(leg);
    }
    pts.push_back(b.p + m.origin);
  }
  // One arc per turn round one curve: the tangent points a route passes on a
  // piece split its turn into arcs that continue one another.
  // Arcs of no length (a tangent that only touches a piece) go, and the
  // lines on either side become one.
  std::vector<RouteLeg> legs;
  for (RouteLeg& leg : result.legs) {
    if (leg.length_m < 1e-9) continue;  // a tangent that only touches a piece, an end's step onto its circle
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
  result.legs = std::move(legs);
  // Drop repeated points (zero-length legs at touching pieces).
  pts.erase(std::unique(pts.begin(), pts.end(), [](const Vec2& x, const Vec2& y) { return (x - y).norm() < 1e-12; }),
            pts.end());
  result.stats.query_ms = elapsed_ms(t0);
  return result;
}

GraphEntry tangent_graph_entry() {
  GraphEntry e;
  e.name = GraphKind::tangent.name;
  e.help = "exact, curved";
  e.can = {.turn_radius = true, .dubins_ends = true};
  e.build = [](const GraphBuild& in) -> std::unique_ptr<RouteGraph> {
    return std::make_unique<TangentGraph>(in.obstacles, in.margin, in.options.tolerance, in.focus,
                                          in.options.turn_radius_m);
  };
  return e;
}

}  // namespace deepguide
