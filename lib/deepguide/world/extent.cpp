#include "deepguide/world/extent.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {

Eigen::Vector2d LonLatExtent::centre() const {
  const double lon = 0.5 * (west + east);
  return {lon - 360.0 * std::floor((lon + 180.0) / 360.0), 0.5 * (south + north)};
}

LonLatExtent extent_of(const std::vector<Eigen::Vector2d>& lonlat) {
  LonLatExtent e;
  if (lonlat.empty()) return e;
  std::vector<double> lons;
  lons.reserve(lonlat.size());
  e.south = e.north = lonlat.front().y();
  for (const Eigen::Vector2d& p : lonlat) {
    lons.push_back(p.x() - 360.0 * std::floor((p.x() + 180.0) / 360.0));  // [-180, 180)
    e.south = std::min(e.south, p.y());
    e.north = std::max(e.north, p.y());
  }
  std::sort(lons.begin(), lons.end());
  // The extent is the circle of longitudes less its widest gap; the gap
  // across the antimeridian gives the plain bounds.
  double gap = lons.front() + 360.0 - lons.back();
  e.west = lons.front(), e.east = lons.back();
  for (std::size_t i = 1; i < lons.size(); ++i) {
    if (lons[i] - lons[i - 1] > gap) {
      gap = lons[i] - lons[i - 1];
      e.west = lons[i], e.east = lons[i - 1] + 360.0;
    }
  }
  return e;
}

}  // namespace deepguide
