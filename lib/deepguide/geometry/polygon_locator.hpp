#pragma once
// Which of many large polygons hold a point, and how far the point is from
// their edges, in O(log n) per query instead of a walk round every ring.
//
// An R-tree holds every edge of every ring. A point lies inside polygon k
// when a ray from it to the east crosses k's edges an odd number of times
// (holes included: their edges count too); an edge crosses when its ends lie
// on either side of the ray's line, the lower end counting as above on a tie
// (the half-open rule, so a ray through a vertex counts once). Points on an
// edge count as inside (covered). Only polygons whose box holds the point are
// tested, each with the ray cut at its box; the edges the ray can cross are
// those whose box meets the ray's box, found by the R-tree. The nearest edge
// to a point or a segment is the R-tree's nearest query, which measures the
// exact distance to its segments (Boost.Geometry's segment distances).

#include <boost/geometry/geometries/segment.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cstddef>
#include <limits>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

class PolygonLocator {
 public:
  explicit PolygonLocator(const std::vector<const BgPolygon*>& polygons);

  /// Indices (into the constructor's list) of the polygons covering p, ascending.
  std::vector<std::size_t> covering(const Vec2& p) const;
  /// Distance from p to the nearest edge of any polygon (infinite without polygons).
  double distance_to_edges(const Vec2& p) const;

  /// The edge nearest to the segment [a, b] (a point when a == b), and its
  /// distance: 0 when the segment meets it. Infinite without polygons.
  struct NearestEdge {
    double distance;
    Vec2 from, to;
  };
  NearestEdge nearest_edge(const Vec2& a, const Vec2& b) const;

 private:
  using Segment = boost::geometry::model::segment<BgPoint>;
  using Item = std::pair<Segment, std::size_t>;
  boost::geometry::index::rtree<Item, boost::geometry::index::rstar<16>> edges_;
  using BoxItem = std::pair<BgBox, std::size_t>;  // a polygon's box, its index
  boost::geometry::index::rtree<BoxItem, boost::geometry::index::rstar<16>> boxes_;
  std::size_t count_ = 0;
  double max_x_ = -std::numeric_limits<double>::infinity();
};

}  // namespace deepguide
