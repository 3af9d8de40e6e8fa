#pragma once
// Exact visibility among closed polygons (holes allowed): a segment is visible
// when it meets no polygon's interior. Touching a vertex, running along an
// edge, or starting on a boundary is fine. The one place the polygon graphs
// decide "is this segment free", with spatial indexes (Boost.Geometry R-trees)
// over the edges and the polygons.
//
// Test for segment PQ: (1) no candidate edge crosses it properly (both pairs
// of endpoints strictly on opposite sides, beyond eps); (2) split PQ where
// every vertex of the edges it meets projects onto it; no piece's midpoint is
// strictly inside a polygon (more than eps from every edge). Together these reject a segment entering an
// interior through a vertex or leaving its start into the interior, and accept
// grazing and collinear runs: the cases that break naive visibility graphs.

#include <boost/geometry/index/rtree.hpp>
#include <cstddef>
#include <memory>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/geometry/polygon_locator.hpp"

namespace DEEPGUIDE_API deepguide {

class PolygonVisibility {
 public:
  /// `eps` is the distance (m) under which points count as on a line or a boundary.
  PolygonVisibility(BgMultiPolygon polygons, double eps);
  ~PolygonVisibility();
  PolygonVisibility(const PolygonVisibility&) = delete;
  PolygonVisibility& operator=(const PolygonVisibility&) = delete;

  bool segment_visible(const Vec2& p, const Vec2& q) const;
  /// True if the segment properly crosses some polygon edge (enters an
  /// interior for sure); the cheap first half of segment_visible.
  bool properly_crosses(const Vec2& p, const Vec2& q) const;
  /// Strictly inside some polygon (farther than eps from its boundary).
  bool strictly_inside(const Vec2& p) const;
  /// Index of the polygon strictly containing p, or npos.
  std::size_t containing_polygon(const Vec2& p) const;
  /// Closest point on any polygon boundary to p.
  Vec2 closest_boundary_point(const Vec2& p) const;

  const BgMultiPolygon& polygons() const { return polygons_; }
  double eps() const { return eps_; }
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  using Segment = boost::geometry::model::segment<BgPoint>;
  using EdgeItem = std::pair<Segment, std::size_t>;  // edge, polygon index
  using BoxItem = std::pair<BgBox, std::size_t>;
  BgMultiPolygon polygons_;
  double eps_;
  boost::geometry::index::rtree<EdgeItem, boost::geometry::index::rstar<16>> edges_;  // nearest queries
  // The same edges by their boxes, for the segment queries: a leaf's box test
  // is a few comparisons where Boost's segment-segment test computes the
  // whole intersection, and the side tests that follow decide exactly anyway.
  using EdgeBox = std::pair<BgBox, std::size_t>;  // box, index into edge_ends_
  boost::geometry::index::rtree<EdgeBox, boost::geometry::index::rstar<16>> edge_boxes_;
  std::vector<std::pair<Vec2, Vec2>> edge_ends_;
  boost::geometry::index::rtree<BoxItem, boost::geometry::index::rstar<16>> boxes_;
  std::unique_ptr<PolygonLocator> locator_;  // which polygon holds a point (strictly_inside)
};

/// The polygon graphs' frame: `polygons` (corrected) about the centre of
/// their box, for UTM's millions of metres cost orientation tests six
/// digits, and their visibility with eps a billionth of their extent from it
/// (at least 1 m). The origin is zero for no polygons.
struct CentredPolygons {
  Vec2 origin{0.0, 0.0};
  BgMultiPolygon polygons;  ///< corrected, about `origin`
  double eps = 1e-9;        ///< a billionth of their extent, at least 1 m's
};
CentredPolygons centred_polygons(const BgMultiPolygon& polygons);

struct CentredVisibility {
  Vec2 origin{0.0, 0.0};
  std::unique_ptr<PolygonVisibility> visibility;
};
CentredVisibility centred_visibility(const BgMultiPolygon& polygons);

}  // namespace deepguide
