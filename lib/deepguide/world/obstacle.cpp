#include "deepguide/world/obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <unordered_map>

#include "deepguide/core/error.hpp"
#include "deepguide/core/fnv1a.hpp"

namespace deepguide {

std::size_t remove_passable(ObstacleSet& obstacles, double depth_m, double vertical_clearance_m) {
  if (!std::isfinite(depth_m) || depth_m < 0.0) {
    throw InputError("`depth_m`: expected an operating depth >= 0 m, got " + std::to_string(depth_m));
  }
  if (!std::isfinite(vertical_clearance_m) || vertical_clearance_m < 0.0) {
    throw InputError("`vertical_clearance_m`: expected a clearance >= 0 m, got " +
                     std::to_string(vertical_clearance_m));
  }
  auto passable = [&](const auto& o) { return o.top_depth_m && *o.top_depth_m > depth_m + vertical_clearance_m; };
  const std::size_t before = obstacles.size();
  std::erase_if(obstacles.ellipses, passable);
  std::erase_if(obstacles.polygons, passable);
  return before - obstacles.size();
}

std::pair<Vec2, Vec2> footprint_box(const ObstacleSet& obstacles) {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const EllipticCylinder& c : obstacles.ellipses) {
    lo = lo.cwiseMin(c.footprint.centre - Vec2::Constant(c.footprint.a));
    hi = hi.cwiseMax(c.footprint.centre + Vec2::Constant(c.footprint.a));
  }
  for (const PolygonObstacle& p : obstacles.polygons) {
    for (const BgPoint& pt : p.footprint.outer()) lo = lo.cwiseMin(to_eigen(pt)), hi = hi.cwiseMax(to_eigen(pt));
  }
  return {lo, hi};
}

std::string footprint_fingerprint(const ObstacleSet& obstacles) {
  Fnv1a h;
  h.number(static_cast<std::uint64_t>(obstacles.ellipses.size()));
  for (const EllipticCylinder& e : obstacles.ellipses) {
    for (const double x :
         {e.footprint.centre.x(), e.footprint.centre.y(), e.footprint.a, e.footprint.b, e.footprint.theta})
      h.number(x);
  }
  const auto ring = [&h](const BgPolygon::ring_type& r) {
    h.number(static_cast<std::uint64_t>(r.size()));
    for (const BgPoint& p : r) h.number(p.x()), h.number(p.y());
  };
  h.number(static_cast<std::uint64_t>(obstacles.polygons.size()));
  for (const PolygonObstacle& p : obstacles.polygons) {
    ring(p.footprint.outer());
    h.number(static_cast<std::uint64_t>(p.footprint.inners().size()));
    for (const BgPolygon::ring_type& inner : p.footprint.inners()) ring(inner);
  }
  return h.text();
}

std::optional<ObstacleSet> obstacles_beyond(const ObstacleSet& all, const ObstacleSet& part) {
  // One obstacle's fingerprint: the set's of it alone.
  const auto print = [](const auto& obstacle) {
    ObstacleSet one;
    if constexpr (std::is_same_v<std::decay_t<decltype(obstacle)>, EllipticCylinder>) {
      one.ellipses.push_back(obstacle);
    } else {
      one.polygons.push_back(obstacle);
    }
    return footprint_fingerprint(one);
  };
  std::unordered_map<std::string, std::size_t> left;
  for (const EllipticCylinder& e : part.ellipses) ++left[print(e)];
  for (const PolygonObstacle& p : part.polygons) ++left[print(p)];
  ObstacleSet out;
  std::size_t matched = 0;
  const auto take = [&](const auto& obstacle, auto& into) {
    auto it = left.find(print(obstacle));
    if (it != left.end() && it->second > 0) {
      --it->second;
      ++matched;
    } else {
      into.push_back(obstacle);
    }
  };
  for (const EllipticCylinder& e : all.ellipses) take(e, out.ellipses);
  for (const PolygonObstacle& p : all.polygons) take(p, out.polygons);
  if (matched != part.size()) return std::nullopt;
  return out;
}

}  // namespace deepguide
