#include "deepguide/planning/polygon_visibility.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <limits>

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

// Signed distance of x from the line through a and b (positive to the left).
double side(const Vec2& a, const Vec2& b, const Vec2& x) {
  const Vec2 d = b - a;
  const double len = d.norm();
  return len > 0.0 ? cross(d, x - a) / len : (x - a).norm();
}

template <class Ring, class F>
void for_each_edge(const Ring& ring, F f) {
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) f(to_eigen(ring[i]), to_eigen(ring[i + 1]));
}

}  // namespace

PolygonVisibility::PolygonVisibility(BgMultiPolygon polygons, double eps) : polygons_(std::move(polygons)), eps_(eps) {
  std::vector<EdgeItem> edges;
  std::vector<BoxItem> boxes;
  for (std::size_t i = 0; i < polygons_.size(); ++i) {
    bg::correct(polygons_[i]);
    boxes.emplace_back(bg::return_envelope<BgBox>(polygons_[i]), i);
    auto add = [&](const Vec2& a, const Vec2& b) { edges.emplace_back(Segment(to_bg(a), to_bg(b)), i); };
    for_each_edge(polygons_[i].outer(), add);
    for (const auto& inner : polygons_[i].inners()) for_each_edge(inner, add);
  }
  edges_ = decltype(edges_)(edges);
  std::vector<EdgeBox> edge_boxes;
  edge_boxes.reserve(edges.size());
  edge_ends_.reserve(edges.size());
  for (const EdgeItem& e : edges) {
    edge_boxes.emplace_back(bg::return_envelope<BgBox>(e.first), edge_ends_.size());
    edge_ends_.emplace_back(to_eigen(e.first.first), to_eigen(e.first.second));
  }
  edge_boxes_ = decltype(edge_boxes_)(edge_boxes);
  boxes_ = decltype(boxes_)(boxes);
  std::vector<const BgPolygon*> ptrs;
  for (const BgPolygon& poly : polygons_) ptrs.push_back(&poly);
  locator_ = std::make_unique<PolygonLocator>(ptrs);
}

PolygonVisibility::~PolygonVisibility() = default;

std::size_t PolygonVisibility::containing_polygon(const Vec2& p) const {
  // The locator answers in O(log n) where a walk round a chart's coast takes thousands of steps.
  for (const std::size_t k : locator_->covering(p)) {
    // Rounding may put a boundary point just inside: count it as boundary.
    std::vector<EdgeItem> nearest;
    edges_.query(bgi::nearest(to_bg(p), 1), std::back_inserter(nearest));
    if (!nearest.empty() &&
        point_segment_distance(p, to_eigen(nearest[0].first.first), to_eigen(nearest[0].first.second)) <= eps_) {
      return npos;
    }
    return k;
  }
  return npos;
}

bool PolygonVisibility::strictly_inside(const Vec2& p) const { return containing_polygon(p) != npos; }

Vec2 PolygonVisibility::closest_boundary_point(const Vec2& p) const {
  std::vector<EdgeItem> nearest;
  edges_.query(bgi::nearest(to_bg(p), 4), std::back_inserter(nearest));
  Vec2 best = p;
  double best_d = std::numeric_limits<double>::infinity();
  for (const EdgeItem& e : nearest) {
    const Vec2 a = to_eigen(e.first.first), b = to_eigen(e.first.second);
    const Vec2 d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    const Vec2 c = a + t * d;
    if ((c - p).norm() < best_d) best_d = (c - p).norm(), best = c;
  }
  return best;
}

bool PolygonVisibility::properly_crosses(const Vec2& p, const Vec2& q) const {
  if (p == q) return false;
  const Segment seg(to_bg(p), to_bg(q));
  for (auto it = edge_boxes_.qbegin(bgi::intersects(seg)); it != edge_boxes_.qend(); ++it) {
    const auto& [a, b] = edge_ends_[it->second];
    const double sa = side(p, q, a), sb = side(p, q, b);
    const double sp = side(a, b, p), sq = side(a, b, q);
    if (((sa > eps_ && sb < -eps_) || (sa < -eps_ && sb > eps_)) &&
        ((sp > eps_ && sq < -eps_) || (sp < -eps_ && sq > eps_))) {
      return true;
    }
  }
  return false;
}

bool PolygonVisibility::segment_visible(const Vec2& p, const Vec2& q) const {
  const double len = (q - p).norm();
  if (len == 0.0) return !strictly_inside(p);
  // Only edges whose boxes the segment meets can cross it or put a corner on
  // it (a corner within eps but off to the side is not on it; one clipped by
  // the segment lies in its edges' boxes). Iterated lazily: most segments
  // between far corners are blocked, and the first proper crossing ends it.
  std::vector<double> breaks{0.0, 1.0};
  const Segment seg(to_bg(p), to_bg(q));
  for (auto it = edge_boxes_.qbegin(bgi::intersects(seg)); it != edge_boxes_.qend(); ++it) {
    const auto& [a, b] = edge_ends_[it->second];
    const double sa = side(p, q, a), sb = side(p, q, b);
    const double sp = side(a, b, p), sq = side(a, b, q);
    const bool straddle_pq = (sa > eps_ && sb < -eps_) || (sa < -eps_ && sb > eps_);
    const bool straddle_ab = (sp > eps_ && sq < -eps_) || (sp < -eps_ && sq > eps_);
    if (straddle_pq && straddle_ab) return false;
    // Every end of a candidate edge splits PQ where it projects, not only
    // those on it: a piece then has no corner beside it, its depth inside a
    // polygon is concave along it, and a midpoint within eps of a ring bounds
    // the whole piece's depth by 2 eps. Split only at corners on PQ, a piece
    // that entered a zone through a corner it starts at and ran on just
    // inside an edge to its end passed on its shallow midpoint however deep
    // its first part went (0.6 m, NavMeshGraph.DenseFields... with seed
    // shift 4242).
    for (const Vec2& x : {a, b}) {
      const double t = (x - p).dot(q - p) / (len * len);
      if (t * len > eps_ && (1.0 - t) * len > eps_) breaks.push_back(t);
    }
  }
  std::sort(breaks.begin(), breaks.end());
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    if ((breaks[i + 1] - breaks[i]) * len <= eps_) continue;
    const Vec2 mid = p + 0.5 * (breaks[i] + breaks[i + 1]) * (q - p);
    if (strictly_inside(mid)) return false;
  }
  return true;
}

CentredPolygons centred_polygons(const BgMultiPolygon& polygons) {
  CentredPolygons out;
  if (!polygons.empty()) {
    BgBox box;
    bg::envelope(polygons, box);
    out.origin =
        Vec2(0.5 * (box.min_corner().x() + box.max_corner().x()), 0.5 * (box.min_corner().y() + box.max_corner().y()));
  }
  out.polygons = polygons;
  double extent = 1.0;
  for (BgPolygon& poly : out.polygons) {
    bg::correct(poly);
    auto shift = [&](auto& ring) {
      for (BgPoint& pt : ring) {
        pt = to_bg(to_eigen(pt) - out.origin);
        extent = std::max({extent, std::abs(pt.x()), std::abs(pt.y())});
      }
    };
    shift(poly.outer());
    for (auto& inner : poly.inners()) shift(inner);
  }
  out.eps = 1e-9 * extent;
  return out;
}

CentredVisibility centred_visibility(const BgMultiPolygon& polygons) {
  CentredPolygons local = centred_polygons(polygons);
  return {local.origin, std::make_unique<PolygonVisibility>(std::move(local.polygons), local.eps)};
}

}  // namespace deepguide
