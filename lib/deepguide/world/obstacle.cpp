#include "deepguide/world/obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "deepguide/core/error.hpp"

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

}  // namespace deepguide
