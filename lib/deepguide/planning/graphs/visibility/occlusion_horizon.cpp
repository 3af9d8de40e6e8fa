#include "deepguide/planning/graphs/visibility/occlusion_horizon.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>

#include "deepguide/core/angles.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

// Edges per piece: short enough that the nearest pieces close the view soon
// (a piece's far vertex sets the horizon), long enough to keep the R-tree small.
constexpr std::size_t kPieceEdges = 8;

// Removes the open interval (lo, hi) of the real line from `set`; true if it
// took anything (a point of the set strictly inside counts).
bool remove_open(BearingSet& set, double lo, double hi) {
  bool took = false;
  BearingSet kept;
  kept.reserve(set.size() + 1);
  for (const auto& [a, b] : set) {
    if (hi <= a || lo >= b) {  // disjoint (a point [a, a] strictly inside is not)
      kept.emplace_back(a, b);
      continue;
    }
    took = true;
    if (a <= lo) kept.emplace_back(a, lo);
    if (hi <= b) kept.emplace_back(hi, b);
  }
  set.swap(kept);
  return took;
}

// Removes the arc (lo, hi), hi - lo < 2 pi, taking bearings modulo 2 pi.
bool remove_arc(BearingSet& set, double lo, double hi) {
  const double shift = kFullTurn * std::floor(lo / kFullTurn);
  lo -= shift;
  hi -= shift;
  bool took = remove_open(set, lo, hi);
  if (hi > kFullTurn) took = remove_open(set, lo - kFullTurn, hi - kFullTurn) || took;
  return took;
}

}  // namespace

double pseudo_bearing(const Vec2& v) {
  const double s = std::abs(v.x()) + std::abs(v.y());
  if (s == 0.0) return 0.0;
  const double t = v.y() / s;  // sine-like, in [-1, 1]
  return v.x() >= 0.0 ? (t >= 0.0 ? t : kFullTurn + t) : 2.0 - t;
}

void add_arc(BearingSet& set, double from, double to) {
  if (to - from >= kFullTurn) {
    set.assign(1, {0.0, kFullTurn});
    return;
  }
  const double shift = kFullTurn * std::floor(from / kFullTurn);
  from -= shift;
  to -= shift;
  if (to <= kFullTurn) {
    set.emplace_back(from, to);
  } else {
    set.emplace_back(from, kFullTurn);
    set.emplace_back(0.0, to - kFullTurn);
  }
}

OcclusionHorizon::OcclusionHorizon(const BgMultiPolygon& polygons, double eps) : margin_m_(1e3 * eps) {
  std::vector<BoxItem> boxes;
  auto add_ring = [&](const auto& ring) {
    // A closed ring repeats its first point, so pieces of kPieceEdges edges
    // sharing their end vertices cover every edge once.
    for (std::size_t first = 0; first + 1 < ring.size(); first += kPieceEdges) {
      const std::size_t last = std::min(first + kPieceEdges, ring.size() - 1);
      BgBox box(ring[first], ring[first]);
      piece_begin_.push_back(points_.size());
      for (std::size_t i = first; i <= last; ++i) {
        points_.push_back(to_eigen(ring[i]));
        bg::expand(box, ring[i]);
      }
      boxes.emplace_back(box, piece_begin_.size() - 1);
    }
  };
  for (const BgPolygon& poly : polygons) {
    add_ring(poly.outer());
    for (const auto& inner : poly.inners()) add_ring(inner);
  }
  piece_begin_.push_back(points_.size());
  boxes_ = decltype(boxes_)(boxes);
  extent_ = BgBox(BgPoint(0.0, 0.0), BgPoint(0.0, 0.0));
  if (!boxes.empty()) extent_ = boxes.front().first;
  for (const BoxItem& b : boxes) bg::expand(extent_, b.first);
  // Pieces are about ellipse-sized; four of them across makes the first
  // square hold the neighbours that usually close a corner's view.
  double size = 0.0;
  for (const BoxItem& b : boxes) size += bg::distance(b.first.min_corner(), b.first.max_corner());
  if (!boxes.empty()) first_radius_m_ = std::max(1.0, 4.0 * size / static_cast<double>(boxes.size()));
}

OcclusionHorizon::~OcclusionHorizon() = default;

std::vector<BgPolygon> bearing_wedges(const Vec2& p, double lo, double hi, double far) {
  // The point of the square |x| + |y| = 1 at a bearing: its norm is at least
  // 1 / sqrt 2, so scaling by 2 far puts it beyond far * sqrt 2.
  const auto on_square = [](double b) {
    b -= kFullTurn * std::floor(b / kFullTurn);
    if (b <= 1.0) return Vec2(1.0 - b, b);
    if (b <= 2.0) return Vec2(1.0 - b, 2.0 - b);
    if (b <= 3.0) return Vec2(b - 3.0, 2.0 - b);
    return Vec2(b - 3.0, b - 4.0);
  };
  std::vector<BgPolygon> out;
  const double slack = 1e-9;  // the wedge's own rounding must not drop a point on its side
  lo -= slack;
  hi += slack;
  const int pieces = std::max(1, static_cast<int>(std::ceil((hi - lo) / 0.5)));
  for (int k = 0; k < pieces; ++k) {
    const double a = lo + (hi - lo) * k / pieces, b = lo + (hi - lo) * (k + 1) / pieces;
    BgPolygon wedge;
    for (const double bearing : {a, 0.5 * (a + b), b})
      wedge.outer().push_back(to_bg(p + 2.0 * far * on_square(bearing)));
    wedge.outer().push_back(to_bg(p));
    bg::correct(wedge);
    out.push_back(std::move(wedge));
  }
  return out;
}

bool Horizon::sees(const Vec2& offset) const {
  if (offset.squaredNorm() <= reach_m * reach_m) return true;
  if (open.empty()) return false;
  const double b = pseudo_bearing(offset);
  for (const auto& [lo, hi] : open) {
    if (lo <= b && b <= hi) return true;
  }
  return false;
}

Horizon OcclusionHorizon::horizon(const Vec2& p, BearingSet wanted, std::size_t max_pieces) const {
  Horizon out;
  if (wanted.empty()) return out;
  // One run of a piece that keeps clear of p: its unwrapped bearings and its
  // farthest and nearest vertex (squared distances).
  double lo = 0.0, hi = 0.0, phi = 0.0, far2 = 0.0, near2 = 0.0;
  bool in_run = false;
  const auto close_run = [&] {
    if (!in_run) return;
    in_run = false;
    // Shrunk so that a ray grazing an end vertex by less than margin_m_ is
    // not counted as blocked. A pseudo-angle moves at most as fast as the
    // angle, so a shrink of x in it is at least x rad.
    const double shrink = kMarginRad + std::min(margin_m_ / std::sqrt(near2), kPi);
    if (hi - lo <= 2.0 * shrink) return;
    if (hi - lo - 2.0 * shrink >= kFullTurn) {
      wanted.clear();
    } else if (!remove_arc(wanted, lo + shrink, hi - shrink)) {
      return;
    }
    out.reach_m = std::max(out.reach_m, std::sqrt(far2));
  };
  // near_p: the piece's box is within the margin of p, so an edge may pass
  // through p; such an edge ends the run (its side decides nothing the exact
  // test would agree with).
  const auto take_piece = [&](std::size_t k, bool near_p) {
    const std::size_t begin = piece_begin_[k], end = piece_begin_[k + 1];
    Vec2 va = points_[begin] - p;
    double ba = pseudo_bearing(va), da2 = va.squaredNorm();
    for (std::size_t i = begin + 1; i < end; ++i) {
      const Vec2 vb = points_[i] - p;
      const double bb = pseudo_bearing(vb), db2 = vb.squaredNorm();
      if (near_p && point_segment_distance(p, points_[i - 1], points_[i]) < margin_m_) {
        close_run();
      } else {
        if (!in_run) {
          in_run = true;
          phi = lo = hi = ba;
          far2 = near2 = da2;
        }
        // The turn has the sign of the cross product and is below a half turn.
        const double c = cross(va, vb);
        double turn = c == 0.0 ? 0.0 : bb - ba;
        if (c > 0.0 && turn < 0.0) turn += kFullTurn;
        if (c < 0.0 && turn > 0.0) turn -= kFullTurn;
        phi += turn;
        lo = std::min(lo, phi);
        hi = std::max(hi, phi);
        far2 = std::max(far2, db2);
        near2 = std::min(near2, db2);
      }
      va = vb;
      ba = bb;
      da2 = db2;
    }
    close_run();
    return wanted.empty();
  };
  // Pieces by growing squares around p, nearest first within each: the
  // horizon is set by the pieces that close the view, so near ones first.
  std::vector<std::pair<double, std::size_t>> ring;
  std::size_t taken = 0;
  for (double r = first_radius_m_, inner = -1.0;; inner = r, r *= 2.0) {
    ring.clear();
    const BgBox square(to_bg(p - Vec2(r, r)), to_bg(p + Vec2(r, r)));
    for (auto it = boxes_.qbegin(bgi::intersects(square)); it != boxes_.qend(); ++it) {
      const Vec2 lo_corner = to_eigen(it->first.min_corner()), hi_corner = to_eigen(it->first.max_corner());
      const Vec2 gap = (lo_corner - p).cwiseMax(p - hi_corner).cwiseMax(0.0);
      if (gap.maxCoeff() <= inner) continue;  // met by the last square: taken
      ring.emplace_back(gap.squaredNorm(), it->second);
    }
    std::sort(ring.begin(), ring.end());
    for (const auto& [gap2, piece] : ring) {
      if (take_piece(piece, gap2 <= margin_m_ * margin_m_)) return out;
      if (++taken >= max_pieces) break;
    }
    if (taken >= max_pieces || bg::within(extent_, square)) break;
  }
  out.open = std::move(wanted);
  return out;
}

}  // namespace deepguide
