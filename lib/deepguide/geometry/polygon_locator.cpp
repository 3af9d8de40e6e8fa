#include "deepguide/geometry/polygon_locator.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <iterator>

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

PolygonLocator::PolygonLocator(const std::vector<const BgPolygon*>& polygons) : count_(polygons.size()) {
  std::vector<Item> items;
  auto add_ring = [&](const auto& ring, std::size_t k) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
      items.emplace_back(Segment(ring[i], ring[i + 1]), k);
      max_x_ = std::max({max_x_, ring[i].x(), ring[i + 1].x()});
    }
  };
  std::vector<BoxItem> boxes;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    add_ring(polygons[k]->outer(), k);
    for (const auto& r : polygons[k]->inners()) add_ring(r, k);
    if (!polygons[k]->outer().empty()) boxes.emplace_back(bg::return_envelope<BgBox>(polygons[k]->outer()), k);
  }
  edges_ = decltype(edges_)(items.begin(), items.end());
  boxes_ = decltype(boxes_)(boxes.begin(), boxes.end());
}

std::vector<std::size_t> PolygonLocator::covering(const Vec2& p) const {
  std::vector<std::size_t> out;
  if (count_ == 0 || !(p.x() <= max_x_)) return out;
  // Only a polygon whose box holds p can cover it, and the ray meets all of
  // that polygon's edges it can meet before leaving the box: the ray stops
  // there instead of crossing every edge east of p.
  std::vector<BoxItem> holders;
  boxes_.query(bgi::intersects(to_bg(p)), std::back_inserter(holders));
  for (const auto& [box, k] : holders) {
    bool odd = false, on_edge = false;
    const BgBox ray(BgPoint(p.x(), p.y()), BgPoint(box.max_corner().x(), p.y()));
    for (auto it = edges_.qbegin(bgi::intersects(ray)); it != edges_.qend() && !on_edge; ++it) {
      if (it->second != k) continue;
      const BgPoint& a = it->first.first;
      const BgPoint& b = it->first.second;
      const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
      const bool within_box = std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
                              std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
      if (cross == 0.0 && within_box) {
        on_edge = true;
        continue;
      }
      if ((a.y() > p.y()) == (b.y() > p.y())) continue;
      // The crossing's x on the ray's line, compared exactly through the sign of `cross`:
      // it lies east of p when p is on the side of a-b that makes the edge point upward-left.
      const bool upward = b.y() > a.y();
      if ((upward && cross > 0.0) || (!upward && cross < 0.0)) odd = !odd;
    }
    if (odd || on_edge) out.push_back(k);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double PolygonLocator::distance_to_edges(const Vec2& p) const {
  std::vector<Item> nearest;
  edges_.query(bgi::nearest(to_bg(p), 1), std::back_inserter(nearest));
  if (nearest.empty()) return std::numeric_limits<double>::infinity();
  return bg::distance(to_bg(p), nearest.front().first);
}

PolygonLocator::NearestEdge PolygonLocator::nearest_edge(const Vec2& a, const Vec2& b) const {
  std::vector<Item> nearest;
  if (a == b) {
    edges_.query(bgi::nearest(to_bg(a), 1), std::back_inserter(nearest));
  } else {
    edges_.query(bgi::nearest(Segment(to_bg(a), to_bg(b)), 1), std::back_inserter(nearest));
  }
  if (nearest.empty()) return {std::numeric_limits<double>::infinity(), a, a};
  const Segment& e = nearest.front().first;
  const double d = a == b ? bg::distance(to_bg(a), e) : bg::distance(Segment(to_bg(a), to_bg(b)), e);
  return {d, to_eigen(e.first), to_eigen(e.second)};
}

}  // namespace deepguide
