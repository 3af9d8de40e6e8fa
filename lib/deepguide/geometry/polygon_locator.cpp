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
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    add_ring(polygons[k]->outer(), k);
    for (const auto& r : polygons[k]->inners()) add_ring(r, k);
  }
  edges_ = decltype(edges_)(items.begin(), items.end());
}

std::vector<std::size_t> PolygonLocator::covering(const Vec2& p) const {
  std::vector<std::size_t> out;
  if (count_ == 0 || !(p.x() <= max_x_)) return out;
  std::vector<bool> odd(count_, false), on_edge(count_, false);
  std::vector<Item> hits;
  const BgBox ray(BgPoint(p.x(), p.y()), BgPoint(max_x_, p.y()));
  edges_.query(bgi::intersects(ray), std::back_inserter(hits));
  for (const auto& [seg, k] : hits) {
    const BgPoint& a = seg.first;
    const BgPoint& b = seg.second;
    const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
    const bool within_box = std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
                            std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
    if (cross == 0.0 && within_box) {
      on_edge[k] = true;
      continue;
    }
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    // The crossing's x on the ray's line, compared exactly through the sign of `cross`:
    // it lies east of p when p is on the side of a-b that makes the edge point upward-left.
    const bool upward = b.y() > a.y();
    if ((upward && cross > 0.0) || (!upward && cross < 0.0)) odd[k] = !odd[k];
  }
  for (std::size_t k = 0; k < count_; ++k) {
    if (odd[k] || on_edge[k]) out.push_back(k);
  }
  return out;
}

double PolygonLocator::distance_to_edges(const Vec2& p) const {
  std::vector<Item> nearest;
  edges_.query(bgi::nearest(to_bg(p), 1), std::back_inserter(nearest));
  if (nearest.empty()) return std::numeric_limits<double>::infinity();
  return bg::distance(to_bg(p), nearest.front().first);
}

}  // namespace deepguide
