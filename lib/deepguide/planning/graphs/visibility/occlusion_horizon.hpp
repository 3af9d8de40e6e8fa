#pragma once
// How far a point can see among polygons, in chosen directions: the horizon
// that turns the visibility graph's all-pairs loop into a neighbourhood query.
//
// Why it holds: walk a piece of a polygon boundary (a polyline that does not
// pass through p) and follow its bearing seen from p, unwrapped, phi(s). For
// any bearing theta strictly between min phi and max phi the boundary crosses
// the ray from p at theta (intermediate values), and a crossing of a boundary
// has the polygon's interior on one side of the crossing point along the ray,
// before it or after it. So every point of that ray farther from p than the
// piece's farthest vertex is hidden: the segment to it runs through interior.
// Pieces are taken nearest first until the wanted bearings are covered; the
// largest far-vertex distance among the pieces that covered something is the
// horizon. Nothing beyond it, in those bearings, can be seen from p.
//
// Each interval is shrunk at both ends (kMarginRad, and a margin in metres
// turned into an angle) so that rays that only graze a piece, which the exact
// test with its eps tolerance may still call visible, are never counted as
// hidden. The horizon only prunes candidates; every candidate is still decided
// by the exact segment test (polygon_visibility.hpp).

#include <boost/geometry/index/rtree.hpp>
#include <cstddef>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

/// Bearings here are pseudo-angles: where the ray from the origin meets the
/// square |x| + |y| = 1, measured along it anticlockwise from +x, in [0, 4).
/// They order directions as angles do without a trigonometric call; a half
/// turn is exactly 2, and a pseudo-angle changes at most as fast as the angle
/// (a difference of x in it is at least x rad).
inline constexpr double kFullTurn = 4.0;
double pseudo_bearing(const Vec2& v);

/// Polygons that together hold every point at bearings lo..hi from p up to
/// `far` (pieces of at most half a quarter turn, each a quadrilateral whose
/// outer edges stay beyond far): a cone query for an R-tree.
std::vector<BgPolygon> bearing_wedges(const Vec2& p, double lo, double hi, double far);

/// Bearings as closed intervals [lo, hi] with 0 <= lo <= hi <= kFullTurn; an
/// arc across bearing 0 is two intervals.
using BearingSet = std::vector<std::pair<double, double>>;

/// Adds the arc from `from` anticlockwise to `to` (any real values; an arc of
/// a full turn or more is the whole circle).
void add_arc(BearingSet& set, double from, double to);

/// What p can see: points within reach_m, and beyond it only at the bearings
/// in `open` (those of the wanted ones that no piece taken closes).
struct Horizon {
  double reach_m = 0.0;
  BearingSet open;
  bool bounded() const { return open.empty(); }
  /// Whether the point at `offset` from p may be visible.
  bool sees(const Vec2& offset) const;
};

class OcclusionHorizon {
 public:
  /// `eps`: the distance under which the exact test treats points as on a
  /// line (PolygonVisibility::eps()); it sets how far intervals are shrunk.
  OcclusionHorizon(const BgMultiPolygon& polygons, double eps);
  ~OcclusionHorizon();
  OcclusionHorizon(const OcclusionHorizon&) = delete;
  OcclusionHorizon& operator=(const OcclusionHorizon&) = delete;

  /// What p may see at the bearings in `wanted`, from the boundary pieces
  /// nearest p, at most `max_pieces` of them: the work per point is bounded,
  /// and where that many leave bearings open the caller tests those.
  Horizon horizon(const Vec2& p, BearingSet wanted, std::size_t max_pieces) const;

  static constexpr double kMarginRad = 1e-6;

 private:
  using BoxItem = std::pair<BgBox, std::size_t>;  // box, piece index
  std::vector<Vec2> points_;                      // the pieces' vertices, piece after piece
  std::vector<std::size_t> piece_begin_;          // piece k is points_[piece_begin_[k], piece_begin_[k + 1])
  boost::geometry::index::rtree<BoxItem, boost::geometry::index::rstar<16>> boxes_;
  BgBox extent_;                 // of every piece: a square holding it has seen them all
  double first_radius_m_ = 1.0;  // the first square's half side: a few pieces across
  double margin_m_;
};

}  // namespace deepguide
