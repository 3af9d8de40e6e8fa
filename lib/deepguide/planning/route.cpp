#include "deepguide/planning/route.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {

double Route::length() const {
  const bool in_depth = depth_m.size() == points.size();
  double sum = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double dz = in_depth ? depth_m[i] - depth_m[i - 1] : 0.0;
    sum += std::hypot((points[i] - points[i - 1]).norm(), dz);
  }
  return sum;
}

Vec2 Route::point_at(double s) const {
  if (points.empty()) return Vec2(0.0, 0.0);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double len = (points[i + 1] - points[i]).norm();
    if (s <= len) return len > 0.0 ? Vec2(points[i] + (std::max(s, 0.0) / len) * (points[i + 1] - points[i])) : points[i];
    s -= len;
  }
  return points.back();
}

}  // namespace deepguide
