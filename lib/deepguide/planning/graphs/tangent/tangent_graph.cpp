// The tangent graph of an environment: its zone pieces, the collision-free
// common tangents between them and the arcs along them, built once and
// searched by every query (tangent_query.cpp).

#include "deepguide/planning/graphs/tangent/tangent_graph.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <iterator>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/periodic_roots.hpp"
#include "deepguide/planning/graphs/tangent/tangent_graph_impl.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using tangent_detail::elapsed_ms;
using tangent_detail::kTouchEps;
using tangent_detail::orientation;
using tangent_detail::unit;

namespace {

// About 10 s of build on the reference machine (docs/PERFORMANCE.md).
constexpr std::size_t kMaxPieces = 3000;

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
