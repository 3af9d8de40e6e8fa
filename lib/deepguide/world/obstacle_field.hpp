#pragma once
// The obstacle field: clearance queries over an obstacle set with a safety
// margin, the planners' state-validity checker (in the sense of OMPL's
// StateValidityChecker) and the ground truth routes are checked against.
//
// Math on top. For footprints F_i with signed distances sd_i (negative inside),
//   clearance(p)           = min_i sd_i(p)
//   segment clearance      = min_i min_{t in [0,1]} sd_i(a + t (b - a))
//   free                   <=> clearance >= margin  (the zone boundary is free)
// Ellipse, point: exact (project_to_ellipse). Ellipse, segment: the signed
// distance to a convex set is convex, so t -> sd(a + t (b - a)) is convex on
// [0, 1] and Brent's method finds its minimum; t is located to about 3e-8 and
// where the minimum is smooth (always outside the ellipse) the distance error is
// quadratic in that, far below a micrometre. Inside, the distance has a ridge
// (the medial axis between the evolute cusps), so a crossing's depth is only
// good to about 1e-8 of the segment length; its sign is always right.
// Polygon: Boost.Geometry distances; inside, minus the distance to the rings;
// a segment entering a polygon gets the depth Brent finds on its inside pieces.
// Pruning: an obstacle lies inside its bounding box, so the distance to the box
// is a lower bound of the distance to the obstacle (and a box that meets the
// query bounds nothing: the query may be inside). The R-tree hands out boxes by
// increasing distance; the search stops once the next box is no closer than the
// best exact distance found.
//
// 2-D only: footprints, no heights or top depths. An obstacle under the
// vehicle's depth still counts here; the vertical extent is handled by the
// depth-aware planners later.

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <boost/geometry/index/rtree.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/geometry/polygon_locator.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

/// Smallest signed distance between a closed segment and one footprint, and
/// where on the segment it is attained.
struct SegmentDistance {
  double distance;        ///< m; negative when the segment enters the footprint
  Vec2 point_on_segment;  ///< a point of the segment at that distance
};

/// Signed distance from p to the polygon's area: positive outside (and in a
/// hole), 0 on a ring, minus the distance to the nearest ring inside.
double signed_distance(const BgPolygon& polygon, const Vec2& p);

/// Minimum over the segment [a, b] of the signed distance to the ellipse
/// (negative when the segment crosses it: the depth of its deepest point).
SegmentDistance segment_signed_distance(const Ellipse& ellipse, const Vec2& a, const Vec2& b);

/// Signed distance between the segment [a, b] and the polygon's area. Disjoint:
/// the exact distance and the segment's closest point. Entering the interior: a
/// negative value, minus the depth of the deepest point Brent finds on the
/// pieces inside (the deepest point for a convex polygon, a deep one otherwise).
/// Only touching a ring: 0 at the first contact going from a to b.
SegmentDistance segment_signed_distance(const BgPolygon& polygon, const Vec2& a, const Vec2& b);

class ObstacleField {
 public:
  /// Obstacle indices: ellipses first (0 .. E-1), then polygons (E .. E+P-1).
  struct Nearest {
    double distance;        ///< signed, m; +inf when there are no obstacles
    std::size_t obstacle;   ///< index of the nearest obstacle (0 when there are none)
    Vec2 point_on_segment;  ///< point of the segment closest to it
  };

  /// Builds the R-tree of obstacle bounding boxes. Throws InputError for a
  /// margin that is not finite and >= 0, or an obstacle with non-finite
  /// coordinates, an ellipse without 0 < b <= a, or an empty polygon.
  /// `slack` (>= 0) lets is_free / segment_free accept clearance down to
  /// margin - slack: planners whose segments touch the zones exactly (the
  /// tangent graph) pass a few nanometres so rounding does not reject them.
  ObstacleField(ObstacleSet obstacles, double margin, double slack = 0.0);

  double margin() const { return margin_; }
  const ObstacleSet& obstacles() const { return obstacles_; }
  std::size_t size() const { return obstacles_.size(); }

  /// Signed distance from p to the nearest obstacle footprint (negative inside
  /// one); +inf when there are no obstacles.
  double clearance(const Vec2& p) const;
  /// No obstacle: the default of the `skip` arguments below.
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  /// clearance(p) >= margin: p is outside every safety zone; the boundary counts as free.
  /// Obstacle `skip` is not looked at (a point known to lie on its zone's boundary).
  bool is_free(const Vec2& p, std::size_t skip = kNone) const;

  /// Smallest signed distance between the closed segment [a, b] and any
  /// obstacle footprint, which obstacle and where. Ties go to the obstacle found
  /// first; a degenerate segment (a == b) is the point a. Obstacle `skip` is
  /// not looked at (one whose distance the caller knows exactly).
  Nearest segment_clearance(const Vec2& a, const Vec2& b, std::size_t skip = kNone) const;
  /// The ellipse obstacle whose footprint is `footprint`: the same axes and
  /// heading bit for bit, its centre at most `within` from footprint's (a
  /// planner that worked in a shifted frame gives it back rounded); kNone
  /// when there is none.
  std::size_t ellipse_index(const Ellipse& footprint, double within = 0.0) const;
  /// segment_clearance(a, b).distance >= margin, stopping at the first obstacle
  /// closer than the margin and never looking at boxes farther than it.
  /// Obstacles skip_a and skip_b are not looked at: a planner passes the
  /// convex zones a tangent segment touches by construction, whose exact
  /// distance would only confirm the touch (and cost most of the test).
  bool segment_free(const Vec2& a, const Vec2& b, std::size_t skip_a = kNone, std::size_t skip_b = kNone) const;

  /// The obstacles whose bounding box comes within `within` of the box
  /// [lo, hi]: every obstacle closer than that to a point of the box is among
  /// them (the 3-D volume asks which cylinders a cell or a leg could meet).
  std::vector<std::size_t> near(const Vec2& lo, const Vec2& hi, double within) const;

  /// Exact signed distance to one obstacle (no R-tree): for brute-force checks.
  double distance_to(std::size_t obstacle, const Vec2& p) const;
  SegmentDistance segment_distance_to(std::size_t obstacle, const Vec2& a, const Vec2& b) const;

  /// The obstacle's id if non-empty, else "ellipse #i" / "polygon #j", with i
  /// and j counted from 0 within their own list.
  std::string obstacle_name(std::size_t obstacle) const;

 private:
  using Entry = std::pair<BgBox, std::size_t>;
  using Tree = boost::geometry::index::rtree<Entry, boost::geometry::index::rstar<16>>;

  ObstacleSet obstacles_;
  double margin_;
  double threshold_;  // margin - slack
  Tree tree_;
  std::vector<Vec2> axes_;  // major-axis directions of the ellipses, cached

  // Edge R-trees of the polygons with at least kIndexedPoints ring points,
  // each built on its first query (a chart's field has hundreds of polygons,
  // and a query meets few), once even when threads share the field; copies
  // of the field share them.
  static constexpr std::size_t kIndexedPoints = 32;
  struct EdgeIndexes {
    explicit EdgeIndexes(std::size_t polygons);
    std::vector<std::once_flag> built;
    std::vector<std::unique_ptr<PolygonLocator>> locators;
  };
  std::shared_ptr<EdgeIndexes> edge_indexes_;
  const PolygonLocator* edge_index(std::size_t polygon) const;  // null for a small polygon
};

}  // namespace deepguide
