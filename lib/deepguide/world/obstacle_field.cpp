#include "deepguide/world/obstacle_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include <boost/geometry/algorithms/distance.hpp>
#include <boost/geometry/algorithms/envelope.hpp>
#include <boost/geometry/algorithms/for_each.hpp>
#include <boost/geometry/algorithms/intersection.hpp>
#include <boost/geometry/algorithms/intersects.hpp>
#include <boost/geometry/algorithms/within.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_linestring.hpp>
#include <boost/geometry/geometries/segment.hpp>
#include <boost/math/tools/minima.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"

namespace deepguide {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgSegment = bg::model::segment<BgPoint>;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Brent cannot locate a minimum closer than sqrt(eps) (function values are flat
// there), so asking for more bits only costs iterations.
constexpr int kBrentBits = std::numeric_limits<double>::digits / 2;
// A convex function on [0, 1] converges in a few dozen steps; this only bounds
// the cost if something pathological slips through.
constexpr std::uintmax_t kBrentMaxIter = 200;

// The point of [a, b] closest to q. Boost 1.74 has no closest_points, so the
// segment's closest point to a ring edge is found from its candidates below.
Vec2 foot_on_segment(const Vec2& a, const Vec2& b, const Vec2& q) {
  const Vec2 d = b - a;
  const double t = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return a + t * d;
}

// Bounding box of an ellipse from its support in +-x and +-y, grown by a few
// ulps of the coordinates: the box must contain the ellipse for the box
// distance to be a lower bound, and rounding could shave the last bit.
BgBox ellipse_box(const Ellipse& e) {
  const double c = std::cos(e.theta);
  const double s = std::sin(e.theta);
  const double hx = std::hypot(e.a * c, e.b * s);
  const double hy = std::hypot(e.a * s, e.b * c);
  const double pad =
      16.0 * std::numeric_limits<double>::epsilon() * (e.a + std::abs(e.centre.x()) + std::abs(e.centre.y()));
  return {BgPoint(e.centre.x() - hx - pad, e.centre.y() - hy - pad),
          BgPoint(e.centre.x() + hx + pad, e.centre.y() + hy + pad)};
}

// The point of segment [a, b] closest to the disjoint edge [e0, e1]: for two
// disjoint segments the closest pair includes an endpoint of one of them.
Vec2 closest_to_edge(const Vec2& a, const Vec2& b, const Vec2& e0, const Vec2& e1) {
  const BgSegment edge(to_bg(e0), to_bg(e1));
  Vec2 point = a;
  double point_distance = kInf;
  for (const Vec2& c : {a, b, foot_on_segment(a, b, e0), foot_on_segment(a, b, e1)}) {
    const double dist = bg::distance(to_bg(c), edge);
    if (dist < point_distance) {
      point_distance = dist;
      point = c;
    }
  }
  return point;
}

bool finite(const Vec2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// Hands out obstacle indices by increasing distance of their boxes to `query`,
// with a lower bound of the obstacle's signed distance, until visit returns false.
//
// Boost 1.74's incremental nearest iterator walks depth-first: with k = size()
// it has nothing to prune with and can sweep whole subtrees far from the query
// before it returns the next value (seconds per query at 10^5 boxes). So ask
// for the k nearest, which prunes properly, and grow k while visit wants more.
// Entries tied with the k-th distance may have peers outside the batch, so a
// round only hands out entries strictly closer than that; `done` keeps a later,
// larger batch from handing out an entry twice.
template <class Tree, class Query, class Visit>
void by_box_distance(const Tree& tree, const Query& query, Visit visit) {
  using Entry = typename Tree::value_type;
  std::vector<Entry> found;
  std::vector<std::pair<double, std::size_t>> batch;
  std::vector<std::size_t> done;
  for (std::size_t k = 16;; k *= 4) {
    const auto k_query = static_cast<unsigned>(std::min<std::size_t>(k, std::numeric_limits<unsigned>::max()));
    found.clear();
    tree.query(bgi::nearest(query, k_query), std::back_inserter(found));
    const bool all = found.size() < k_query;
    batch.clear();
    for (const Entry& e : found) batch.emplace_back(bg::distance(query, e.first), e.second);
    std::sort(batch.begin(), batch.end());
    const double cutoff = all ? kInf : batch.back().first;
    for (const auto& [box_distance, index] : batch) {
      if (!all && box_distance >= cutoff) break;
      if (std::find(done.begin(), done.end(), index) != done.end()) continue;
      done.push_back(index);
      // A box that meets the query bounds nothing: the query may be inside the obstacle.
      const double lower_bound = box_distance > 0.0 ? box_distance : -kInf;
      if (!visit(index, lower_bound)) return;
    }
    if (all) return;
  }
}

// Quick verdicts for an ellipse footprint before the exact distance (which
// costs a Brent search). In the ellipse's frame, with k = 1 + t / b:
//  - every point closer than t to the ellipse lies strictly inside the
//    ellipse (k a, k b): write it y + t w with |y|_E <= 1 and |w| < 1, then
//    |y + t w|_E <= 1 + t |w| / b < k  (|.|_E the unit-circle-frame norm);
//  - every point of the ellipse (a + t, b + t) lies within t of the ellipse:
//    its boundary point at parameter s is (a cos s, b sin s) + t (cos s, sin s),
//    and the distance to a convex set is convex, so the inside is no farther.
// Both are widened by a relative 1e-9 towards "unknown", so rounding never
// turns an uncertain case into a verdict; the exact distance decides those.
enum class Verdict { clear, blocked, unknown };

// Smallest value over the segment p0 + s (p1 - p0), s in [0, 1], of
// (x / A)^2 + (y / B)^2 (coordinates in the ellipse's frame).
double min_implicit(const Vec2& p0, const Vec2& p1, double A, double B) {
  const Vec2 q0(p0.x() / A, p0.y() / B);
  const Vec2 d(p1.x() / A - q0.x(), p1.y() / B - q0.y());
  const double dd = d.squaredNorm();
  const double s = dd > 0.0 ? std::clamp(-q0.dot(d) / dd, 0.0, 1.0) : 0.0;
  return (q0 + s * d).squaredNorm();
}

// `axis` = e.major_dir(), passed in: computing it costs two sincos per call.
Verdict quick_verdict(const Ellipse& e, const Vec2& axis, double t, const Vec2& a, const Vec2& b) {
  if (!(t > 0.0)) return Verdict::unknown;
  const auto local = [&](const Vec2& p) {
    const Vec2 d = p - e.centre;
    return Vec2(d.dot(axis), axis.x() * d.y() - axis.y() * d.x());
  };
  const Vec2 p0 = local(a), p1 = local(b);
  const double k = (1.0 + t / e.b) * (1.0 + 1e-9);
  if (min_implicit(p0, p1, k * e.a, k * e.b) >= 1.0) return Verdict::clear;
  const double shrink = 1.0 - 1e-9;
  if (min_implicit(p0, p1, (e.a + t) * shrink, (e.b + t) * shrink) < 1.0) return Verdict::blocked;
  return Verdict::unknown;
}

}  // namespace

double signed_distance(const BgPolygon& polygon, const Vec2& p) {
  const BgPoint q = to_bg(p);
  const double d = bg::distance(q, polygon);
  if (d > 0.0 || !bg::within(q, polygon)) return d;
  double to_rings = kInf;
  bg::for_each_segment(polygon, [&](const auto& edge) { to_rings = std::min(to_rings, bg::distance(q, edge)); });
  return -to_rings;
}

SegmentDistance segment_signed_distance(const Ellipse& ellipse, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const auto f = [&](double t) { return signed_distance(ellipse, a + t * d); };
  if (d.x() == 0.0 && d.y() == 0.0) return {f(0.0), a};
  // A segment that stays outside: in closed form. With n the line's unit
  // normal pointing away from the centre, the line keeps
  //   gap = n.(a - c) - sqrt(n^T A n)
  // from the ellipse, attained at its support point in direction -n... seen
  // from the line, i.e. the boundary point with outward normal n. The distance
  // along the line is convex, smallest at that point's foot t*, so on [0, 1]
  // it is smallest at clamp(t*, 0, 1): the gap itself, or an end point's distance.
  const double len2 = d.squaredNorm();
  Vec2 n = Vec2(-d.y(), d.x()) / std::sqrt(len2);
  double side = n.dot(a - ellipse.centre);
  if (side < 0.0) n = -n, side = -side;
  const double gap = side - (ellipse.support(n) - n.dot(ellipse.centre));
  if (gap > 0.0) {
    const double t_foot = (ellipse.support_point(n) - a).dot(d) / len2;
    if (t_foot >= 0.0 && t_foot <= 1.0) return {gap, a + t_foot * d};
    return t_foot < 0.0 ? SegmentDistance{f(0.0), a} : SegmentDistance{f(1.0), b};
  }
  // The line meets the ellipse; a segment that does not (strictly) is
  // closest at an end, the one nearer the chord.
  if (!segment_intersects(ellipse, a, b)) {
    const double fa = f(0.0), fb = f(1.0);
    return fa <= fb ? SegmentDistance{fa, a} : SegmentDistance{fb, b};
  }
  // Crossing: the depth, by Brent (the convex distance has a ridge inside).
  SegmentDistance best{f(0.0), a};
  const auto consider = [&](double t, double value) {
    if (value < best.distance) best = {value, a + t * d};
  };
  consider(1.0, f(1.0));
  std::uintmax_t iterations = kBrentMaxIter;
  const auto [t_min, f_min] = boost::math::tools::brent_find_minima(f, 0.0, 1.0, kBrentBits, iterations);
  consider(t_min, f_min);
  // Also the point nearest the centre in the unit-circle frame: it is inside
  // whenever the segment dips into the ellipse, however shallowly, so a
  // crossing never comes out positive.
  const Vec2 q0 = ellipse.to_unit(a);
  const Vec2 dq = ellipse.to_unit(b) - q0;
  const double t_centre = std::clamp(-q0.dot(dq) / dq.squaredNorm(), 0.0, 1.0);
  consider(t_centre, f(t_centre));
  return best;
}

SegmentDistance segment_signed_distance(const BgPolygon& polygon, const Vec2& a, const Vec2& b) {
  if (a == b) return {signed_distance(polygon, a), a};
  const BgSegment seg(to_bg(a), to_bg(b));
  if (!bg::intersects(seg, polygon)) {
    // Disjoint: the closest pair lies on a ring edge.
    double best = kInf;
    Vec2 e0 = a;
    Vec2 e1 = a;
    bg::for_each_segment(polygon, [&](const auto& edge) {
      const double dist = bg::distance(seg, edge);
      if (dist < best) {
        best = dist;
        e0 = to_eigen(edge.first);
        e1 = to_eigen(edge.second);
      }
    });
    return {best, closest_to_edge(a, b, e0, e1)};
  }
  // Meeting: minimise the signed distance over each piece of the segment inside
  // the polygon. For a convex polygon the function is convex along the segment
  // and Brent finds the deepest point; otherwise it finds a deep one.
  const Vec2 d = b - a;
  const auto f = [&](double t) { return signed_distance(polygon, a + t * d); };
  SegmentDistance best{f(0.0), a};
  const auto consider = [&](double t, double value) {
    if (value < best.distance) best = {value, a + t * d};
  };
  consider(1.0, f(1.0));
  const auto param = [&](const BgPoint& p) { return std::clamp((to_eigen(p) - a).dot(d) / d.squaredNorm(), 0.0, 1.0); };
  bg::model::multi_linestring<bg::model::linestring<BgPoint>> inside;
  bg::intersection(bg::model::linestring<BgPoint>{seg.first, seg.second}, polygon, inside);
  for (const auto& piece : inside) {
    if (piece.empty()) continue;
    double t0 = param(piece.front());
    double t1 = param(piece.back());
    if (t0 > t1) std::swap(t0, t1);
    if (!(t1 > t0)) continue;
    consider(0.5 * (t0 + t1), f(0.5 * (t0 + t1)));
    std::uintmax_t iterations = kBrentMaxIter;
    const auto [t_min, f_min] = boost::math::tools::brent_find_minima(f, t0, t1, kBrentBits, iterations);
    consider(t_min, f_min);
  }
  if (best.distance < 0.0) return best;
  // Only touches the rings: 0 at the first contact from a.
  double t_first = kInf;
  Vec2 first = a;
  bg::for_each_segment(polygon, [&](const auto& edge) {
    std::vector<BgPoint> contacts;
    bg::intersection(seg, BgSegment(edge.first, edge.second), contacts);
    for (const BgPoint& c : contacts) {
      const double t = (to_eigen(c) - a).dot(d) / d.squaredNorm();
      if (t < t_first) {
        t_first = t;
        first = to_eigen(c);
      }
    }
  });
  return {0.0, first};
}

ObstacleField::ObstacleField(ObstacleSet obstacles, double margin, double slack)
    : obstacles_(std::move(obstacles)), margin_(margin), threshold_(margin - slack) {
  if (!std::isfinite(margin) || margin < 0.0) {
    throw input_error({"obstacle field", "", "margin"}, "a finite safety margin >= 0 m", general(margin));
  }
  if (!std::isfinite(slack) || slack < 0.0) {
    throw input_error({"obstacle field", "", "slack"}, "a finite slack >= 0 m", general(slack));
  }
  const std::size_t n_ellipses = obstacles_.ellipses.size();
  std::vector<Entry> entries;
  entries.reserve(obstacles_.size());
  for (std::size_t i = 0; i < n_ellipses; ++i) {
    const Ellipse& e = obstacles_.ellipses[i].footprint;
    const InputLocation where{"obstacle field", obstacle_name(i), "footprint"};
    if (!finite(e.centre) || !std::isfinite(e.theta)) {
      throw input_error(where, "a finite centre and orientation");
    }
    if (!std::isfinite(e.a) || !(e.b > 0.0) || e.b > e.a) {
      throw input_error(where, "semi-axes 0 < b <= a", "a = " + general(e.a) + ", b = " + general(e.b));
    }
    entries.emplace_back(ellipse_box(e), i);
    axes_.push_back(e.major_dir());
  }
  for (std::size_t j = 0; j < obstacles_.polygons.size(); ++j) {
    const BgPolygon& poly = obstacles_.polygons[j].footprint;
    const InputLocation where{"obstacle field", obstacle_name(n_ellipses + j), "footprint"};
    if (poly.outer().empty()) throw input_error(where, "a polygon with an outer ring");
    bool all_finite = true;
    bg::for_each_point(poly, [&](const BgPoint& p) { all_finite = all_finite && finite(to_eigen(p)); });
    if (!all_finite) throw input_error(where, "finite coordinates");
    entries.emplace_back(bg::return_envelope<BgBox>(poly), n_ellipses + j);
  }
  tree_ = Tree(entries.begin(), entries.end());  // packing (bulk) construction
  edge_indexes_ = std::make_shared<EdgeIndexes>(obstacles_.polygons.size());
}

ObstacleField::EdgeIndexes::EdgeIndexes(std::size_t polygons) : built(polygons), locators(polygons) {}

const PolygonLocator* ObstacleField::edge_index(std::size_t polygon) const {
  const BgPolygon& poly = obstacles_.polygons[polygon].footprint;
  std::size_t points = poly.outer().size();
  for (const auto& inner : poly.inners()) points += inner.size();
  if (points < kIndexedPoints) return nullptr;
  std::call_once(edge_indexes_->built[polygon], [&] {
    edge_indexes_->locators[polygon] = std::make_unique<PolygonLocator>(std::vector<const BgPolygon*>{&poly});
  });
  return edge_indexes_->locators[polygon].get();
}

double ObstacleField::distance_to(std::size_t obstacle, const Vec2& p) const {
  return segment_distance_to(obstacle, p, p).distance;
}

SegmentDistance ObstacleField::segment_distance_to(std::size_t obstacle, const Vec2& a, const Vec2& b) const {
  const std::size_t n_ellipses = obstacles_.ellipses.size();
  if (obstacle < n_ellipses) {
    const Ellipse& e = obstacles_.ellipses[obstacle].footprint;
    return a == b ? SegmentDistance{signed_distance(e, a), a} : segment_signed_distance(e, a, b);
  }
  const std::size_t j = obstacle - n_ellipses;
  const BgPolygon& poly = obstacles_.polygons.at(j).footprint;
  // A polygon of many vertices (a chart's coastline): its nearest edge from
  // the R-tree, and the side from the crossing number. Only a segment clear
  // of every ring by more than a billionth of the coordinates is answered so:
  // there the side tests cannot be misjudged (PolygonLocator), and the
  // distance is the exact distance to the nearest edge, as below. Touching,
  // crossing and lying inside are left to the full computation.
  if (const PolygonLocator* index = edge_index(j)) {
    const PolygonLocator::NearestEdge near = index->nearest_edge(a, b);
    const double scale = 1.0 + a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
    if (near.distance > 1e-9 * scale) {
      const bool inside = !index->covering(a).empty();
      const Vec2 point = a == b ? a : closest_to_edge(a, b, near.from, near.to);
      if (!inside) return {near.distance, point};
      if (a == b) return {-near.distance, a};
    }
  }
  return a == b ? SegmentDistance{signed_distance(poly, a), a} : segment_signed_distance(poly, a, b);
}

double ObstacleField::clearance(const Vec2& p) const {
  double best = kInf;
  by_box_distance(tree_, to_bg(p), [&](std::size_t i, double lower_bound) {
    if (lower_bound > best) return false;
    best = std::min(best, distance_to(i, p));
    return true;
  });
  return best;
}

bool ObstacleField::is_free(const Vec2& p, std::size_t skip) const { return segment_free(p, p, skip); }

ObstacleField::Nearest ObstacleField::segment_clearance(const Vec2& a, const Vec2& b, std::size_t skip) const {
  Nearest best{kInf, 0, a};
  const auto visit = [&](std::size_t i, double lower_bound) {
    if (lower_bound > best.distance) return false;
    if (i == skip) return true;
    const SegmentDistance d = segment_distance_to(i, a, b);
    if (d.distance < best.distance) best = {d.distance, i, d.point_on_segment};
    return true;
  };
  // A point query keeps degenerate segments away from the segment-box distance.
  if (a == b) {
    by_box_distance(tree_, to_bg(a), visit);
  } else {
    by_box_distance(tree_, BgSegment(to_bg(a), to_bg(b)), visit);
  }
  return best;
}

std::size_t ObstacleField::ellipse_index(const Ellipse& footprint, double within) const {
  const std::size_t n_ellipses = obstacles_.ellipses.size();
  for (auto it = tree_.qbegin(bgi::intersects(to_bg(footprint.centre))); it != tree_.qend(); ++it) {
    const std::size_t i = it->second;
    if (i >= n_ellipses) continue;
    const Ellipse& e = obstacles_.ellipses[i].footprint;
    if ((e.centre - footprint.centre).norm() <= within && e.a == footprint.a && e.b == footprint.b &&
        e.theta == footprint.theta)
      return i;
  }
  return kNone;
}

bool ObstacleField::segment_free(const Vec2& a, const Vec2& b, std::size_t skip_a, std::size_t skip_b) const {
  // A yes/no question needs no nearest-first order: every obstacle closer
  // than the threshold has its box within the threshold of the segment, so
  // the boxes meeting the segment's box grown by it are all candidates, and
  // the first blocking one ends the search.
  const double grow = std::max(threshold_, 0.0);
  const BgBox query(BgPoint(std::min(a.x(), b.x()) - grow, std::min(a.y(), b.y()) - grow),
                    BgPoint(std::max(a.x(), b.x()) + grow, std::max(a.y(), b.y()) + grow));
  const std::size_t n_ellipses = obstacles_.ellipses.size();
  for (auto it = tree_.qbegin(bgi::intersects(query)); it != tree_.qend(); ++it) {
    const std::size_t i = it->second;
    if (i == skip_a || i == skip_b) continue;
    if (i < n_ellipses) {
      const Verdict v = quick_verdict(obstacles_.ellipses[i].footprint, axes_[i], threshold_, a, b);
      if (v == Verdict::clear) continue;
      if (v == Verdict::blocked) return false;
    } else {
      const double box_distance =
          a == b ? bg::distance(to_bg(a), it->first) : bg::distance(BgSegment(to_bg(a), to_bg(b)), it->first);
      if (box_distance > 0.0 && box_distance >= threshold_) continue;  // a meeting box bounds nothing
    }
    const double exact = a == b ? distance_to(i, a) : segment_distance_to(i, a, b).distance;
    if (exact < threshold_) return false;
  }
  return true;
}

std::vector<std::size_t> ObstacleField::near(const Vec2& lo, const Vec2& hi, double within) const {
  const BgBox query(to_bg(lo - Vec2::Constant(within)), to_bg(hi + Vec2::Constant(within)));
  std::vector<std::size_t> out;
  for (auto it = tree_.qbegin(bgi::intersects(query)); it != tree_.qend(); ++it) out.push_back(it->second);
  return out;
}

std::string ObstacleField::obstacle_name(std::size_t obstacle) const {
  const std::size_t n_ellipses = obstacles_.ellipses.size();
  if (obstacle < n_ellipses) {
    const std::string& id = obstacles_.ellipses[obstacle].id;
    return id.empty() ? "ellipse #" + std::to_string(obstacle) : id;
  }
  const std::size_t j = obstacle - n_ellipses;
  const std::string& id = obstacles_.polygons.at(j).id;
  return id.empty() ? "polygon #" + std::to_string(j) : id;
}

}  // namespace deepguide
